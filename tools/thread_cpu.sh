#!/bin/bash
# CPU per thread of rason_mas under a perception burst, without a profiler: Python's threads
# by their threading names (recorded by the node as they start), the JVM's by their own.
# Writes OUT_DIR/threads.txt: CPU ms per thread over the measured window and per message.
#   tools/thread_cpu.sh OUT_DIR MAS2J [SECONDS] [COUNT] [RATE]
# with the ROS environment of the worktree sourced; starts its own master on a free port.
set -euo pipefail
out=$(realpath -m "$1"); mas2j=$(realpath "$2"); seconds=${3:-10}; count=${4:-10}; rate=${5:-50}
mkdir -p "$out"
port=$(/usr/bin/python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
export ROS_MASTER_URI=http://127.0.0.1:$port
pids=()
cleanup() { for p in "${pids[@]}"; do kill -TERM "$p" 2>/dev/null || true; done; wait || true; }
trap cleanup EXIT
rosmaster --core -p "$port" >"$out/master.log" 2>&1 & pids+=($!)
for _ in $(seq 100); do rosparam list >/dev/null 2>&1 && break; sleep 0.1; done
rosrun rosout rosout >"$out/rosout.log" 2>&1 & pids+=($!)
/usr/bin/python3 - "$mas2j" "$out/names.txt" >"$out/rason_mas.log" 2>&1 <<'EOF' & mas=$!; pids+=($mas)
import sys, threading
from rason_bridge import mas_node
names, run = open(sys.argv[2], 'w', buffering=1), threading.Thread.run
def named_run(self):
    names.write('%d %s\n' % (threading.get_native_id(), self.name))
    run(self)
threading.Thread.run = named_run
names.write('%d main\n' % threading.get_native_id())
mas_node.main(['rason_mas', sys.argv[1]])
EOF
for _ in $(seq 600); do rosparam get /rason_mas/agents >/dev/null 2>&1 && break; sleep 0.1; done
rosrun rason_bench bench_synth _count:="$count" _rate:="$rate" >"$out/synth.log" 2>&1 & synth=$!; pids+=($synth)
sleep "${WARM:-5}"  # the JIT compiles the perception path
snap() { for t in /proc/$mas/task/*; do echo "${t##*/} $(cut -d' ' -f14,15 $t/stat) $(cat $t/comm)"; done; }
snap >"$out/t0.txt"; t0=$(date +%s.%N)
timeout $((seconds + 5)) rostopic echo -n $((seconds * ${rate%.*})) jason/perception/source >/dev/null 2>&1 || true
sleep 0; snap >"$out/t1.txt"; t1=$(date +%s.%N)
/usr/bin/python3 - "$out" "$t0" "$t1" "$rate" <<'EOF' | tee "$out/threads.txt"
import os, sys
out, t0, t1, rate = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
hz = os.sysconf('SC_CLK_TCK')
names = dict(l.split(' ', 1) for l in open(out + '/names.txt').read().splitlines())
def read(f):
    d = {}
    for l in open(f):
        tid, u, s, comm = l.split(' ', 3)
        d[tid] = (int(u) + int(s), names.get(tid, comm.strip()).strip())
    return d
a, b = read(out + '/t0.txt'), read(out + '/t1.txt')
rows = sorted(((b[t][0] - a.get(t, (0,))[0]) * 1000.0 / hz, b[t][1], t) for t in b)
wall = t1 - t0
msgs = wall * rate
total = sum(r[0] for r in rows)
print('window %.1f s, ~%d messages; process CPU %.0f ms = %.0f%% of a core, %.0f us per message'
      % (wall, msgs, total, 100 * total / 1000 / wall, 1000 * total / msgs))
for ms, name, tid in sorted(rows, reverse=True)[:25]:
    if ms > 0:
        print('%8.0f ms %7.0f us/msg  %s (%s)' % (ms, 1000 * ms / msgs, name, tid))
EOF
