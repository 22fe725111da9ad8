/* The teacher knows how to greet; once the pupil is there it teaches it to bow (tellHow). */
!start.
+!start : .all_names(L) & .member(pupil, L) <- .send(pupil, tellHow, "+!bow <- .print(\"result: bowing as taught\").").
+!start <- .wait(100); !start.

+!greet(Who) <- .my_name(Me); .print("result: ", Me, " greets ", Who).
