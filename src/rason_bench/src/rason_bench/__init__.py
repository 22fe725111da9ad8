"""Benchmarks of the Rason bridge: ``make bench`` (see the README, "Benchmarks").

Pure modules (no rospy): :mod:`stats`, :mod:`thesis`, :mod:`protocol`, :mod:`report`,
:mod:`plots`, :mod:`preempt`. ROS adapters: :mod:`harness` (the controlling node), :mod:`procs`
(starting the master and the nodes), :mod:`experiments`, and the ``bench_synth`` and
``bench_base`` (:mod:`base`) nodes.
"""
