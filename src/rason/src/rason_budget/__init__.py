"""A CPU budget per robot: each robot's processes in a CPU cgroup of their own with a quota
(cgroups.py), and their CPU and memory measured while they run (procstat.py, meter.py).
No rospy here."""
