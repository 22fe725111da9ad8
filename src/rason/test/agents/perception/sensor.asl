/* A test agent that prints every change of the percepts the perception-manager
   test publishes; commands cmd(Id, Agent, C) are for the agent named Agent only. */

/* Plans */

// what the synthesizers of the test publish
+robot(N, _, _, _)[source(percept)] <- .print("+robot ", N).
-robot(N, _, _, _)[source(percept)] <- .print("-robot ", N).
+battery(L)[source(percept)] <- .print("+battery ", L).
-battery(L)[source(percept)] <- .print("-battery ", L).
+temp(T)[source(percept)] <- .print("+temp ", T).
-temp(T)[source(percept)] <- .print("-temp ", T).
+count(N)[source(percept)] <- .print("+count ", N).

// the bridge's own percept
+present(A) <- .print("present ", A).

// commands from the test
+cmd(Id, Me, C) : .my_name(Me) <- !run(Id, C).

+!run(Id, perceive_only(L)) <- rason.perceive_only(L); .print(Id, " perceiving only ", L).
+!run(Id, perceive_all) <- rason.perceive_all; .print(Id, " perceiving all").
+!run(Id, temps) <- .findall(T, temp(T), L); .sort(L, S); .print(Id, " temps ", S).

-!run(Id, _)[error(E), error_msg(M)] <- .print(Id, " failed ", E, ": ", M).
