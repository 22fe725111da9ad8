/* Preemption latency (rason_bench, part "preemption"): the harness starts a motion with a
   percept and, once the robot moves, asks for it back with another. The take-back's
   timestamp is rason.time_ms read right before .drop_intention; the bridge then cancels
   the move and motion_decomp publishes the zero twist, which the harness times. */

// round I of run Run: a motion long enough never to end by itself (3 m at 0.2 m/s)
+go_move(Me, Run, I)[source(percept)] : .my_name(Me) <- !drive(Run, I).
+!drive(Run, I) <- move(3).

// the take-back, and its timestamp reported to the harness
+take_back(Me, Run, I)[source(percept)] : .my_name(Me)
<- rason.time_ms(T); .drop_intention(drive(Run, I)); took_back(Run, I, T).

// the harness's handshake (as in bench.asl): act -> decomposer -> OK -> intention resumed
+go_ping(Me, Run, N)[source(percept)] : .my_name(Me) <- !ping(Run, 0, N).
+!ping(Run, I, N) : I < N
<- rason.time_ms(T0); ping(I); rason.time_ms(T1); rtt(Run, I, T1 - T0); !ping(Run, I + 1, N).
+!ping(_, _, _).
