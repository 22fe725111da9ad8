/* Start-up: the initial goal's plan reads the clock in the agent's first reasoning cycle (its
   context is checked there); the agent reports that time when the harness asks. The action
   round trip the harness's handshake needs, as quiet.asl has it. */

!note_first_cycle.
+!note_first_cycle : rason.time_ms(T) <- +first_cycle_at(T).

+go_started(Me, Run)[source(percept)] : .my_name(Me) & first_cycle_at(T) <- started(Run, T).

+go_ping(Me, Run, N)[source(percept)] : .my_name(Me) <- !ping(Run, 0, N).
+!ping(Run, I, N) : I < N
<- rason.time_ms(T0); ping(I); rason.time_ms(T1); rtt(Run, I, T1 - T0); !ping(Run, I + 1, N).
+!ping(_, _, _).
