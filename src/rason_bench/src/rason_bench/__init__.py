"""Benchmarks of the Rason bridge: ``make bench`` (see the README, "Benchmarks").

Pure modules (no rospy): :mod:`stats`, :mod:`thesis`, :mod:`protocol`, :mod:`report`,
:mod:`plots`, :mod:`preempt`. ROS adapters: :mod:`harness` (the controlling node), :mod:`procs`
(starting the nodes, on the campaign's private master), :mod:`experiments` (the agents'
node: cycle time, latencies, CPU per message, reaction, scale, preemption), :mod:`behaviour`
(wake-up, rate limit, the simulator's rates), and the ``bench_synth`` and ``bench_base``
(:mod:`base`) nodes.
"""
