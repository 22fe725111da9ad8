"""Benchmarks of the Rason bridge: ``make bench`` (see the README, "Benchmarks").

Pure modules (no rospy): :mod:`stats`, :mod:`thesis`, :mod:`protocol`, :mod:`report`,
:mod:`plots`. ROS adapters: :mod:`harness` (the controlling node), :mod:`procs`
(starting the nodes, on the campaign's private master), :mod:`experiments` (the agents'
node: cycle time, latencies, CPU per message, reaction, scale), :mod:`behaviour` (wake-up,
rate limit, the simulator's rates), and the ``bench_synth`` node.
"""
