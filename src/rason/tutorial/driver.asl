// The agent of "Your first robot" (docs/tutorial.md). move(Metres) is motion_decomp's
// action; pos(X, Y), moving and past_the_line come from the robot's odometry through
// perceptions.yaml.

!start.

+!start : pos(X, Y)
   <- .print("starting at ", X, " ", Y);
      move(0.5);
      ?pos(X1, Y1);                          // as the synthesizer last had it
      .print("moved 0.5 m: odometry says ", X1, " ", Y1);
      !!cruise.                              // a goal of its own, to be taken back
+!start                                      // no odometry perceived yet
   <- .wait("+pos(_, _)");
      !start.

// The robot's nodes may still be starting: nobody takes move yet.
-!start[no_decomposer]
   <- .wait(500);
      !start.

+!cruise
   <- .print("cruising 3 m ahead");
      move(3).

// Taking the goal back stops the robot: the bridge cancels move(3) on jason/action.
+past_the_line : .intend(cruise)
   <- .drop_intention(cruise);
      .print("past the line: cruise taken back");
      !halt.

+!halt : moving
   <- .wait("-moving");
      !halt.
+!halt : pos(X, Y)
   <- .print("stopped at ", X, " ", Y);
      .stopMAS.        // jason/mind's last message is the state the agent ends in
