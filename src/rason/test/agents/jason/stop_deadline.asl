// .stopMAS(3000): the agents run on for 3 s of their clock, then the MAS stops.
!stop.
!early.
!late.

+!stop <- .stopMAS(3000).
+!early <- .wait(2000); .print("printed after 2 s").
+!late <- .wait(4000); .print("printed after 4 s").
+jag_shutting_down(T) <- .print("shutting down in ", T, " ms").
