/* The benchmark agent without perception plans (node CPU per perception message): the
   burst's literals still become beliefs and events, but no plan runs for them. Only the
   action round trip the harness's handshake needs. */

+go_ping(Me, Run, N)[source(percept)] : .my_name(Me) <- !ping(Run, 0, N).
+!ping(Run, I, N) : I < N
<- rason.time_ms(T0); ping(I); rason.time_ms(T1); rtt(Run, I, T1 - T0); !ping(Run, I + 1, N).
+!ping(_, _, _).
