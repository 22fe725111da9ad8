/* The hostile-input benchmark's agent: answers the harness's handshake pings, reacts to
   trigger percepts at once (the harness times perception -> action after each hostile
   input) and reports each new flood mark (the harness times publish -> action). */

+go_ping(Me, Run, N)[source(percept)] : .my_name(Me) <- !ping(Run, 0, N).
+!ping(Run, I, N) : I < N
<- rason.time_ms(T0); ping(I); rason.time_ms(T1); rtt(Run, I, T1 - T0); !ping(Run, I + 1, N).
+!ping(_, _, _).

+trigger(Run, Seq, T)[source(percept)] <- react(Run, Seq, T).

+flood_mark(Run, K, T)[source(percept)] <- marked(Run, K, T).
