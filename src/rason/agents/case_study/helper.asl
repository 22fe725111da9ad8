// Helper: the robot with the camera (thesis §6.4, Appendix A Listing A.2), on a robot of
// its own with its own rason_mas. The plans are the thesis's; changes are marked
//   FIX       needed on real Jason or with a real camera,
//   IMPROVED  asked for by thesis §8.1, or an explicit answer when it cannot see.

/* Initial beliefs and rules */
turnRate(10).          // IMPROVED: 10 degrees a step (the thesis used 5), still well
                       // inside the camera's 57 degrees
centerThreshold(7).
settleTime(400).       // FIX: ms for the robots to stop and fresh frames to arrive

/* Initial goals */
!start.

/* Plans */

+!start : true <- .print("ZZzzz...").

// IMPROVED: one robot at a time.
+!helpme[source(R)] : helping(Other)
<- .print("Already helping ", Other, "; ", R, " has to wait").

+!helpme[source(R)]
  <- +helping(R);
  !findRobot(R,0);
  .print("helper ready.");
  .send(R,tell,found(R)).

// IMPROVED: say so when the robot was not found, instead of searching for ever.
-!helpme[source(R)]
  <- .print("I could not find ", R);
  -helping(R);
  .send(R,tell,notFound(R)).

+!findRobot(Robot,Turned)
: math.abs(Turned) >= 360
<- .print("Turned a full circle without seeing ", Robot);
  .fail.

+!findRobot(Robot,Turned)
: robot(Robot,Deg,Depth,Yaw)
& centerThreshold(DT)
& (math.abs(Deg) >= DT)
<- .print("Found ",Robot,", but I need to reposition myself...");
  turn(Deg);
  !settle;
  !findRobot(Robot,Turned+Deg).

+!findRobot(Robot,Turned)
: robot(Robot,Deg,Depth,Yaw)
& centerThreshold(DT)
& math.abs(Deg) < DT
<- .print("Found ",Robot);
  -+foundRobot(Robot,Deg,Depth,Yaw).

+!findRobot(Robot,Turned)
: turnRate(Rate)
& centerThreshold(DT)
<- .print("Finding ",Robot," turning ",Rate," degrees, turned ",Turned," so far. Threshold is ",DT);
  turn(Rate);
  !settle;
  !findRobot(Robot,Turned+Rate).

+!settle : settleTime(T) <- .wait(T).

// IMPROVED: the initial position is the one seen when tracking starts.
+!trackMe[source(R)]
: helping(R)
& robot(R,Deg,Depth,Yaw)
<- -+foundRobot(R,Deg,Depth,Yaw);
  .print("I'm ready.");
  .send(R,achieve,tryMove).

+!trackMe[source(R)]
: helping(R)
<- .send(R,achieve,noFeedback("the helper lost sight of the robot before it moved")).

+!giveFeedback[source(R)]
: helping(R)
<- !settle;
  !reportFeedback(R).

+!reportFeedback(R)
: foundRobot(R,Deg,Depth,Yaw)
& robot(R,Deg1,Depth1,Yaw1)
<- .print("reporting to ",R," -> ",Deg," ",Depth," ",Yaw," / ",Deg1," ",Depth1," ",Yaw1);
  .send(R,achieve,feedback(initPos(Deg,Depth,Yaw),currPos(Deg1,Depth1,Yaw1))).

+!reportFeedback(R)
<- .print("I cannot see ", R, " any more");
  .send(R,achieve,noFeedback("the helper lost sight of the robot after it moved")).

// IMPROVED: nothing about R is kept after thanks (no stale beliefs, thesis §8.1).
+!thanks[source(R)]
: helping(R)
<- .print(R," said 'thanks'...");
  .print("You're welcome, ",R);
  -helping(R);
  -foundRobot(R,_,_,_).

// FIX: the thesis copied each robot/4 percept into a mental note
// (+robot(...) <- +robot(...)); those copies outlive the perception and made the plans
// above act on positions no longer seen. Perceptions alone are used.
