#!/bin/bash
# Profiles rason_mas under a perception burst: Python with cProfile (in every thread, each
# on its own CPU clock), Java with the JDK's Flight Recorder. Writes to OUT_DIR:
# python.txt (functions by own and total CPU time), jfr_hot_methods.txt (JFR's hot methods),
# rason_mas.jfr and the node's log.
#   tools/profile_mas.sh OUT_DIR MAS2J [SECONDS] [COUNT] [RATE]
# with the ROS environment of the worktree sourced; starts its own master on a free port.
set -euo pipefail
out=$(realpath -m "$1"); mas2j=$(realpath "$2"); seconds=${3:-20}; count=${4:-10}; rate=${5:-50}
mkdir -p "$out"
port=$(/usr/bin/python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
export ROS_MASTER_URI=http://127.0.0.1:$port
pids=()
cleanup() { for p in "${pids[@]}"; do kill -TERM "$p" 2>/dev/null || true; done; wait || true; }
trap cleanup EXIT
rosmaster --core -p "$port" >"$out/master.log" 2>&1 & pids+=($!)
rosout_ok=0
for _ in $(seq 100); do rosparam list >/dev/null 2>&1 && { rosout_ok=1; break; }; sleep 0.1; done
[ $rosout_ok = 1 ] || { echo "no master"; exit 1; }
rosrun rosout rosout >"$out/rosout.log" 2>&1 & pids+=($!)
# JFR's "profile" settings without jdk.ThreadCPULoad, which crashes the JVM on the Python
# threads JPype attached once they have ended
jfc=$(find /usr/lib/jvm -path '*/lib/jfr/profile.jfc' | head -1)
sed '/name="jdk.ThreadCPULoad"/,/<\/event>/s/<setting name="enabled">true/<setting name="enabled">false/' "$jfc" >"$out/profile.jfc"
JAVA_TOOL_OPTIONS="-XX:StartFlightRecording=filename=$out/rason_mas.jfr,settings=$out/profile.jfc" \
  /usr/bin/python3 - "$mas2j" "$out/python.txt" "$out/rason_mas.jfr" >"$out/rason_mas.log" 2>&1 <<'EOF' & mas=$!
import cProfile, io, pstats, sys, threading, time
from rason_bridge import mas_node
# cProfile in every Python thread, each on its own CPU clock; merged at the end
profiles, run = [], threading.Thread.run
def profiled_run(self):
    p = cProfile.Profile(time.thread_time)
    profiles.append(p)
    p.runcall(run, self)
threading.Thread.run = profiled_run
main = cProfile.Profile(time.thread_time)
profiles.append(main)
try:
    main.runcall(mas_node.main, ['rason_mas', sys.argv[1]])
finally:
    main.disable()
    for p in profiles:
        p.disable()
    stats = pstats.Stats(*[p for p in profiles if p.getstats()], stream=io.StringIO())
    with open(sys.argv[2], 'w') as f:
        stats.stream = f
        f.write('== Python functions by own CPU time (all threads) ==\n')
        stats.sort_stats('tottime').print_stats(40)
        f.write('== by cumulative CPU time ==\n')
        stats.sort_stats('cumulative').print_stats(60)
    import jpype
    if jpype.isJVMStarted():  # os._exit skips the JVM's exit, which would write the recording
        for rec in jpype.JClass('jdk.jfr.FlightRecorder').getFlightRecorder().getRecordings():
            rec.dump(jpype.JClass('java.nio.file.Path').of(sys.argv[3]))
    import os; os._exit(0)
EOF
for _ in $(seq 600); do rosparam get /rason_mas/agents >/dev/null 2>&1 && break; sleep 0.1; done
rosrun rason_bench bench_synth _count:="$count" _rate:="$rate" >"$out/synth.log" 2>&1 & synth=$!
sleep "$seconds"
kill -INT $synth; wait $synth || true
{ echo "process CPU over the run (start-up included):"; ps -o cputime= -p $mas
  echo "CPU by thread (Python's threads are named python3):"
  ps -L -o time=,tid=,comm= -p $mas | sort -r | head -12; } > "$out/cpu_time.txt" || true
kill -INT $mas; wait $mas || true
jfr print --events jdk.ExecutionSample "$out/rason_mas.jfr" \
  | awk '/stackTrace = \[/{getline; sub(/^[ \t]+/, ""); sub(/line:.*/, ""); top[$0]++; n++}
         END{for (m in top) printf "%6d %5.1f%%  %s\n", top[m], 100*top[m]/n, m}' \
  | sort -rn | head -40 > "$out/jfr_hot_methods.txt"
jfr summary "$out/rason_mas.jfr" | grep -E 'ExecutionSample|Duration' >> "$out/jfr_hot_methods.txt" || true
