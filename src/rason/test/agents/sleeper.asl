/* Plans */

// the test publishes the percept go once it listens to rosout; it also drives /clock.
// Each line carries the ROS time the agent read (ms): rosout's own stamps come when the
// node logs a line, which a busy machine delays by a few clock steps.
+go <- !nap.

+!nap
<-  rason.ros_time_ms(T0); .print("asleep at ", T0);
    .wait(2000);
    rason.ros_time_ms(T1); .print("awake at ", T1);
    .wait(ready, 1000);
    .print("ready").
-!nap[error(wait_timeout)] <- rason.ros_time_ms(T); .print("gave up waiting at ", T).
