// Helper: the robot with the camera (thesis §6.4, Appendix A Listing A.2), on a robot of
// its own with its own rason_mas. The plans are the thesis's; changes are marked
//   FIX       needed on real Jason or with a real camera,
//   IMPROVED  asked for by thesis §8.1, or an explicit answer when it cannot see.

/* Initial beliefs and rules */
turnRate(10).          // IMPROVED: 10 degrees a step (the thesis used 5), still well
                       // inside the camera's 57 degrees
centerThreshold(7).
settleTime(400).       // FIX: ms for the robots to stop and fresh frames to arrive

// FIX: on a busy CPU the camera -> synthesizer -> belief pipeline can lag the robots by
// several frames, so a position read right after a motion may show it half done. A
// position counts once two reads settleTime apart agree within these tolerances
// (degrees, metres, degrees), at most maxSteadyReads reads.
steadyTolerance(1.0, 0.02, 3.0).
steady(D0, P0, Y0, D1, P1, Y1)
    :- steadyTolerance(TA, TD, TY)
     & math.abs(D1 - D0) < TA & math.abs(P1 - P0) < TD & math.abs(Y1 - Y0) < TY.
maxSteadyReads(15).

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

// IMPROVED: the robot asking for help left (its agents stopped, or it is gone): stop
// searching for it or tracking it; a turn under way stops at once (the bridge cancels it).
-present(R) : helping(R)
<- .print(R, " left; I stop helping it");
  .drop_desire(helpme);
  .drop_desire(trackMe);
  .drop_desire(giveFeedback);
  -helping(R);
  -foundRobot(R,_,_,_).

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

// IMPROVED: the initial position is the one seen (steadily) when tracking starts.
+!trackMe[source(R)]
: helping(R)
<- !steadyView(R,Deg,Depth,Yaw);
  -+foundRobot(R,Deg,Depth,Yaw);
  .print("I'm ready.");
  .send(R,achieve,tryMove).

-!trackMe[source(R)]
<- .send(R,achieve,noFeedback("the helper lost sight of the robot before it moved")).

+!giveFeedback[source(R)]
: helping(R)
<- !reportFeedback(R).

+!reportFeedback(R)
: foundRobot(R,Deg,Depth,Yaw)
<- !steadyView(R,Deg1,Depth1,Yaw1);
  .print("reporting to ",R," -> ",Deg," ",Depth," ",Yaw," / ",Deg1," ",Depth1," ",Yaw1);
  .send(R,achieve,feedback(initPos(Deg,Depth,Yaw),currPos(Deg1,Depth1,Yaw1))).

-!reportFeedback(R)
<- .print("I cannot see ", R, " (steadily) any more");
  .send(R,achieve,noFeedback("the helper lost sight of the robot after it moved")).

// Binds Deg, Depth, Yaw to where R is seen once two reads agree (see steady/6); a frame
// without R costs one read; fails when the view does not settle within maxSteadyReads.
+!steadyView(R,Deg,Depth,Yaw) <- !steadyView(R,Deg,Depth,Yaw,1).
+!steadyView(R,Deg,Depth,Yaw,N) : maxSteadyReads(M) & N > M
<- .print("My view of ", R, " did not settle");
  .fail.
+!steadyView(R,Deg,Depth,Yaw,N)
: robot(R,D0,P0,Y0)
& settleTime(T)
<- .wait(T);
  if (robot(R,D1,P1,Y1) & steady(D0,P0,Y0,D1,P1,Y1)) {
    Deg = D1; Depth = P1; Yaw = Y1;
  } else {
    !steadyView(R,Deg,Depth,Yaw,N+1);
  }.
+!steadyView(R,Deg,Depth,Yaw,N)
: settleTime(T)
<- .wait(T);
  !steadyView(R,Deg,Depth,Yaw,N+1).

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

{ include("helper_recovery.asl") }
