// Patrols waypoints of its odometry frame, then stops the MAS. Every action and perception
// is wired by wiring.yaml: goto/2 is a move_base goal, say/1 a topic, lamp/1 a service;
// pos/2 comes from odom and battery_low from a battery topic (generic_synthesizer).

waypoints([wp(1.0, 0.0), wp(1.0, 0.8), wp(0.0, 0.8), wp(0.0, 0.0)]).   // metres, odom frame

!patrol.

+!patrol : waypoints(W)
   <- lamp(true);
      say("patrol started");
      !visit(W);
      lamp(false);
      say("patrol complete");
      .print("patrol complete");
      .stopMAS.

+!visit([]).
+!visit([wp(X, Y) | Rest])
   <- .print("heading to ", X, " ", Y);
      goto(X, Y);
      ?pos(PX, PY);                   // as the synthesizer last had it
      .print("reached ", X, " ", Y, " at ", PX, " ", PY);
      !visit(Rest).

-!patrol[R | Rest]
   <- .print("patrol failed: ", [R | Rest]);
      .stopMAS.

// A low battery takes the patrol back: the goal on move_base is cancelled and the robot stops.
+battery_low : .intend(patrol)
   <- .drop_intention(patrol);
      .print("battery low: patrol stopped");
      say("battery low: patrol stopped");
      lamp(false);
      .stopMAS.
