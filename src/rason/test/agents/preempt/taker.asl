// Test agent of the preemption rostest: one long motion, taken back in the way the
// test names with the percept take(Construct); the next motion comes with next.

/* Plans */

// the motion the test takes back (3 m: far longer than any test lets it run)
+go <- !drive.
+!drive <- move(3); .print("drive arrived").
-!drive[R | Rest] : .member(Why, [suspended, timeout, decomposer_lost, shutdown]) & .member(Why, [R | Rest])
<- .print("drive failed ", Why).
-!drive <- .print("drive failed").

// every way Jason has to stop waiting for an action
+take(drop_intention) <- .drop_intention(drive).
+take(drop_desire) <- .drop_desire(drive).
+take(drop_all_intentions) <- .drop_all_intentions.
+take(drop_all_desires) <- .drop_all_desires.
+take(fail_goal) <- .fail_goal(drive).
+take(succeed_goal) <- .succeed_goal(drive).
+take(suspend) <- .suspend(drive).
+take(stop_mas) <- .stopMAS.
+resume <- .resume(drive).

// the next motion must start at once and end OK
+next <- turn(30); .print("next done").
-!next[R | Rest] <- .print("next failed ", R, Rest).
