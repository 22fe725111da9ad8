/* Plans */

// the test publishes the percept go once it listens to rosout
+go <- !!ticker; !!slow_job.

// keeps printing while slow_job's intention is suspended on its action
+!ticker : not slow_done <- .print("tick"); .wait(200); !ticker.
+!ticker.

+!slow_job <- .print("slow started"); slow(2); +slow_done; .print("slow done").
-!slow_job[R|Rest] <- .print("slow failed ", [R|Rest]).
