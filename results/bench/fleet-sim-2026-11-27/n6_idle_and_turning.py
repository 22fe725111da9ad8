import os, sys, rospy
from rason_bench.procs import Processes
from rason_bench import fleet_sim
procs = Processes('/tmp/fleetsim_exp_logs')
os.environ['ROS_MASTER_URI'] = procs.master_uri
procs.start_master()
try:
    rospy.init_node('exp', disable_signals=True)
    for n, turning in [(6, False), (6, True)]:
        r = fleet_sim.measure_one(procs, n, 10.0, print, turning=turning)
        print(turning, r['cpu_by_process_pct'])
finally:
    procs.stop_master()
