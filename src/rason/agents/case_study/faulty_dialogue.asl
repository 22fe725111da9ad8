// Faulty's part of the cooperative diagnosis (thesis §6.4, Appendix A Listing A.1): its
// mission, the failure it cannot diagnose alone, the dialogue with a robot that watches it
// move, and the diagnosis. Included by faulty.asl (the case study's robot with the fault) and
// by agents/fleet/fleet_robot.asl (any robot of a fleet whose move failed). Changes to the
// thesis's plans are marked FIX and IMPROVED (see faulty.asl).
//
// The dialogue answers whoever sends its messages (source(R)); who is asked for help, and
// what happens after the diagnosis, is the including program's:
//   +!askForHelp              ask another robot to watch me (it answers with found(Me))
//   +!afterDiagnosis(Component)  once the diagnosis is reported
//   +!finish                  once the diagnosis cannot be reported
// and it needs !sendSafely (send_safely.asl).

/* Initial beliefs and rules */

// FIX: perceived depth and angle are never exactly equal twice; "the same place" is
// within these tolerances (metres, degrees).
samePlaceTolerance(0.05, 2.0).
samePlace(Deg, Depth, Deg1, Depth1)
    :- samePlaceTolerance(DT, AT) & math.abs(Depth1 - Depth) < DT & math.abs(Deg1 - Deg) < AT.

// The thesis's threshold on the heading change (degrees).
headingThreshold(8).

// FIX: Yaw1 - (Yaw + (Deg1 - Deg)) is the heading change (clockwise positive, see
// vision_synth) only modulo 360; bring it into (-180, 180].
headingChange(Deg, Yaw, Deg1, Yaw1, C) :- D = Yaw1 - (Yaw + (Deg1 - Deg)) & wrapped(D, C).
wrapped(D, C) :- D > 180 & C = D - 360.
wrapped(D, C) :- D <= -180 & C = D + 360.
wrapped(D, D) :- D > -180 & D <= 180.

// IMPROVED: how long (ms) Faulty waits, after asking for help, for a diagnosis.
helpTimeout(120000).

/* Plans */

// IMPROVED: only the recovery plans need to know where the mission started.
+!noteMissionStart : not recovery(on) <- true.

+!goToDestination
<- .print("Moving to Destination");
    move(1);
    move(-1);
    .print("Arriving at destination");
    +destinationReached;      // IMPROVED: the recovery plans tell a finished mission apart
    !conclude(none, "destination reached").

// FIX: the thesis stored +reason(R1), but Jason sorts the failure annotations, so R1 is
// code(move(1)); the reason is the member no_progress or bad_move of [R1|Rest].
-!goToDestination[R1 | Rest]
: triedAlone & .member(Reason, [no_progress, bad_move]) & .member(Reason, [R1 | Rest])
<- .print("Cannot solve problem alone, asking for help.");
    +reason(Reason);
    !noteFailedMove([R1 | Rest]);
    !!helpWatchdog;
    !askForHelp.

-!goToDestination[R1 | Rest]
<- .print("something went wrong...",R1);
    !diagnoseAlone([R1| Rest]);
    !goToDestination.

+!diagnoseAlone(Reasons)
: .member(no_progress, Reasons)
| .member(bad_move, Reasons)
<- .print("Running local diagnosis");
    .print("diagnose alone has failed");
    +triedAlone;
    .print("Finished diagnosis").

// IMPROVED: a failure that is neither no_progress nor bad_move (timeout, no decomposer,
// ...) is not a case this diagnosis knows.
+!diagnoseAlone([R1 | Rest])
<- .print("This failure is not one I can diagnose: ", R1);
    !conclude(undiagnosed, "motion failed without no_progress or bad_move").

// IMPROVED: the help may never come (helper lost, perception lost, ...). A move still
// running for the helper stops with it (the bridge cancels it: no motion outlives its goal).
+!helpWatchdog : helpTimeout(T)
<- .wait(T);
    .drop_desire(tryMove);
    !conclude(undiagnosed, "no diagnosis within the help timeout").

// IMPROVED: for the helper to watch, the move that failed is made again as long (its
// length in the failure's code(move(D)) annotation), not the thesis's fixed move(0.3). A
// weaker actuator fault (issue 18: severity s below 1) drifts past bad_move's threshold
// only after about 0.28 (1 - s/2) / s m (0.8 m at 0.3); a shorter move passes and the
// fault is taken for a false positive. It is made backwards, over the way I came, which I
// know is free: ahead may be a wall. An actuator fault turns me the same way backwards.
+!noteFailedMove(Annotations) : .member(code(move(D)), Annotations) <- -+failedMove(D).
+!noteFailedMove(_) <- true.

+!repeatFailedMove : failedMove(D) <- move(-D).
+!repeatFailedMove <- move(0.3).

//Plans to help diagnose
+!tryMove[source(R)]
<- .print("Trying to move for ",R);
    !repeatFailedMove;
    .print("It was just a false positive.");
    -reason(_);
    -triedAlone;
    .send(R,achieve,thanks);
    !conclude(none, "moved as planned while observed (false positive)").

// FIX: the helper's plan is +!giveFeedback; the thesis sent givemeFeedback.
// IMPROVED: only a failure the diagnosis knows (no_progress, bad_move) is evidence; a move
// stopped by something else (e.g. timeout against an obstacle) says nothing of the fault.
-!tryMove[source(R) | Annotations]
: .member(Reason, [no_progress, bad_move]) & .member(Reason, Annotations)
<- .print(" requesting some feedback from ",R);
    !sendSafely(R,achieve,giveFeedback).

-!tryMove[source(R) | Annotations]
<- .print("The move for ", R, " failed otherwise: ", Annotations);
    !sendSafely(R,achieve,thanks);
    !conclude(undiagnosed, "the move watched by the helper failed without no_progress or bad_move").

+found(Me)[source(R)]
: .my_name(Me)
<- .print(R," found me, asking to track me");
    .send(R,achieve,trackMe).

// IMPROVED: the helper says when it cannot see us.
+notFound(Me)[source(R)]
: .my_name(Me)
<- .print(R," could not find me");
    !conclude(undiagnosed, "the helper could not find me").

+!noFeedback(Why)[source(R)]
<- .print(R," cannot give feedback: ", Why);
    .send(R,achieve,thanks);
    !conclude(undiagnosed, Why).

// FIX (all feedback plans): the thesis printed an unbound Helper; the sender is R.
// FIX: samePlace instead of Depth == Depth1 & Deg == Deg1.
+!feedback(initPos(Deg,Depth,Yaw),currPos(Deg1,Depth1,Yaw1))[source(R)]
: reason(no_progress)
  & not samePlace(Deg, Depth, Deg1, Depth1)
<- !reportFeedback(R, Deg, Depth, Yaw, Deg1, Depth1, Yaw1);
    .print("fault in odometry system, thanks ", R);
    .send(R,achieve,thanks);
    !conclude(odometry, "no progress measured, but seen moving").

+!feedback(initPos(Deg,Depth,Yaw),currPos(Deg1,Depth1,Yaw1))[source(R)]
: reason(no_progress)
  & samePlace(Deg, Depth, Deg1, Depth1)
<- !reportFeedback(R, Deg, Depth, Yaw, Deg1, Depth1, Yaw1);
    .print("fault in both actuators, thanks ",R);
    .send(R, achieve, thanks);
    !conclude(both_actuators, "no progress measured, and seen in the same place").

+!feedback(initPos(Deg,Depth,Yaw),currPos(Deg1,Depth1,Yaw1))[source(R)]
: reason(bad_move)
  & headingChange(Deg, Yaw, Deg1, Yaw1, C) & headingThreshold(T)
  & math.abs(C) < T
<- !reportFeedback(R, Deg, Depth, Yaw, Deg1, Depth1, Yaw1);
    .print("it was a false positive for bad_move, thanks ",R);
    .send(R, achieve, thanks);
    !conclude(none, "bad_move, but the heading change seen was below the threshold").

+!feedback(initPos(Deg,Depth,Yaw),currPos(Deg1,Depth1,Yaw1))[source(R)]
: reason(bad_move)
  & headingChange(Deg, Yaw, Deg1, Yaw1, C) & headingThreshold(T)
  & C > T
<- !reportFeedback(R, Deg, Depth, Yaw, Deg1, Depth1, Yaw1);
    .print("right actuator has problems, thanks ",R);
    .send(R, achieve, thanks);
    !conclude(right_actuator, "bad_move, seen turning clockwise").

+!feedback(initPos(Deg,Depth,Yaw),currPos(Deg1,Depth1,Yaw1))[source(R)]
: reason(bad_move)
  & headingChange(Deg, Yaw, Deg1, Yaw1, C) & headingThreshold(T)
  & C < -T
<- !reportFeedback(R, Deg, Depth, Yaw, Deg1, Depth1, Yaw1);
    .print("left actuator has problems, thanks ",R);
    .send(R, achieve, thanks);
    !conclude(left_actuator, "bad_move, seen turning counter-clockwise").

// IMPROVED: what the helper saw is kept (Knowledge, for the recovery plans).
+!reportFeedback(R, Deg, Depth, Yaw, Deg1, Depth1, Yaw1)
<- -+helpedBy(R);
    -+seenMove(Deg, Depth, Yaw, Deg1, Depth1, Yaw1);
    .print(R," has reported as initial info( pos ",Deg," degrees, depth ",Depth," meters and yaw ",Yaw," degrees )");
    .print("and current info( pos ",Deg1," degrees, depth ",Depth1," meters and yaw ",Yaw1," degrees )").

// IMPROVED: the diagnosis is reported once (report_diagnosis puts it on /diagnostics),
// then the program goes on (!afterDiagnosis): faulty.asl ends the scenario or recovers.
+!conclude(Component, Evidence) : diagnosed(_)
<- true.
+!conclude(Component, Evidence)
<- +diagnosed(Component);
    .print("Diagnosis: ", Component, " (", Evidence, ")");
    report_diagnosis(Component, Evidence);
    !afterDiagnosis(Component).
-!conclude(Component, Evidence)
<- .print("could not report the diagnosis");
    !finish.
