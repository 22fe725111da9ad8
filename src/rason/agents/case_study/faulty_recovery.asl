// Faulty's recovery after the diagnosis (issue 15; thesis ch. 8 and §8.1's MAPE-K loop),
// included by faulty.asl and active with the belief recovery(on):
//   Monitor   the motion decomposer's failures (faulty.asl: no_progress, bad_move)
//   Analyse   the cooperative diagnosis (faulty.asl, with the helper)
//   Plan      the plans below: one recovery per diagnosis
//   Execute   reconfiguration actions of the motion decomposer (compensate/2,
//             pose_source/1) and the other robots (contract net, guide)
// A program that finds its guide or delegate otherwise (agents/fleet/fleet_robot.asl: by
// its own contract net) gives its own +!beGuided and +!delegateMission first, and reuses
// !guidedBy, !awaitDelegate and the hooks !guidedPoseFrom, !guidanceFailed, !delegated and
// !notDelegated.
//   Knowledge beliefs: missionStart/1, missionCmdStart/1, seenMove/6, helpedBy/1 and the
//             perceptions pos/3 (odometry), cmd_pos/3 (commanded odometry)
// The mission is the thesis's: reach the point missionLength ahead of the start, then come
// back to the start. Its outcome goes to /diagnostics as rason/mission (report_mission).

{ include("poses.asl") }

missionLength(1).          // metres ahead of the start (thesis §7: move(1), then move(-1))
guideWait(20000).          // ms to wait for the helper's first sighting when guided
guidedTries(60).           // goto tries while guided: the helper's view of me pauses while the
guidedPause(1000).         // link between us drops (I stand still, goto fails no_progress;
                           // at 30 % loss each way for up to 20 s); ms between two tries
proposalWait(5000).        // ms to wait for the proposals of a call for proposals
delegateTimeout(180000).   // ms for the winner of the contract net to report back

// An answer to a call for proposals, by agent A.
answer(Task, A) :- propose(Task, _)[source(A)].
answer(Task, A) :- refuse(Task)[source(A)].

missionGoal(G) :- missionStart(S) & missionLength(L) & compose(S, pose(L, 0, 0), G).

// Curvature (rad per metre) of the move the helper saw: its heading change over the
// distance between the two positions seen (Angle, Depth: degrees clockwise, metres).
curvatureSeen(K)
    :- seenMove(Deg, Depth, Yaw, Deg1, Depth1, Yaw1)
     & headingChange(Deg, Yaw, Deg1, Yaw1, C)
     & X0 = Depth * math.tan(Deg * math.pi / 180) & X1 = Depth1 * math.tan(Deg1 * math.pi / 180)
     & Dist = math.sqrt((X1 - X0) * (X1 - X0) + (Depth1 - Depth) * (Depth1 - Depth))
     & Dist > 0.03
     & K = math.abs(C) * math.pi / 180 / Dist.

/* Knowledge: where the mission starts */

+!noteMissionStart : recovery(on)
<- .wait(pos(_, _, _) & cmd_pos(_, _, _), 10000, _);
    if (pos(X, Y, T) & cmd_pos(CX, CY, CT)) {
        +missionStart(pose(X, Y, T));
        +missionCmdStart(pose(CX, CY, CT));
        .print("Mission: from (", X, ", ", Y, ") to 1 m ahead, and back");
    } else {
        .print("I do not perceive my pose: a fault will end the mission");
    }.

/* Plan: one recovery per diagnosis */

+!afterDiagnosis(Diagnosis) : recovery(on) & not missionStart(_)
<- !missionOver(false, [], none, Diagnosis).
+!afterDiagnosis(Diagnosis) : recovery(on)
<- !recover(Diagnosis).

// The mission ran to its end: nothing to recover.
+!recover(none) : destinationReached & .my_name(Me)
<- !missionOver(true, [Me], none, none).
// A false positive: go on with the mission, driving normally.
+!recover(none)
<- !completeMission(none, none).
+!recover(left_actuator) <- !compensate(left, left_actuator).
+!recover(right_actuator) <- !compensate(right, right_actuator).
+!recover(odometry) <- !beGuided.
+!recover(both_actuators) <- !delegateMission.
+!recover(Diagnosis) <- !missionOver(false, [], none, Diagnosis).

/* Execute: compensate a one-wheel fault */

+!compensate(Side, Diagnosis) : curvatureSeen(K)
<- .print("Compensating the ", Side, " actuator: I drive arcs of ", K, " rad/m");
    compensate(Side, K);
    !completeMission(compensate, Diagnosis).
+!compensate(Side, Diagnosis)
<- .print("The helper did not see me move far enough to measure the fault");
    !missionOver(false, [], compensate, Diagnosis).

// The rest of the mission, in the frame of the pose source: to the goal, back to the start.
+!completeMission(Recovery, Diagnosis)
: missionGoal(pose(GX, GY, _)) & missionStart(pose(SX, SY, _)) & .my_name(Me)
<- !driveMission(pose(GX, GY, 0), pose(SX, SY, 0));
    !missionOver(true, [Me], Recovery, Diagnosis).
-!completeMission(Recovery, Diagnosis)
<- !missionOver(false, [], Recovery, Diagnosis).

+!driveMission(pose(GX, GY, _), pose(SX, SY, _))
<- .print("Going on with the mission: to the goal (", GX, ", ", GY, ")");
    !reach(GX, GY);
    .print("Goal reached; back to the start (", SX, ", ", SY, ")");
    !reach(SX, SY);
    .print("Back at the start").

+!reach(X, Y) : beingGuided & guidedTries(N) <- !guidedGoto(X, Y, N).
+!reach(X, Y) <- goto(X, Y).

// A guided goto, tried again while the helper's view of me pauses. A try's failure is caught
// into a belief: a failure plan that itself fails (or one whose context does not hold) ends
// the whole intention in Jason, and the mission would never end.
+!guidedGoto(X, Y, N)
<- !tryGoto(X, Y);
    if (gotoFailed(Reason)) {
        -gotoFailed(Reason);
        if (N > 1 & Reason == no_progress & guidedPause(P)) {
            .print("The helper's view of me stopped coming; I try again (", N - 1, " tries left)");
            .wait(P);
            !guidedGoto(X, Y, N - 1);
        } else {
            .print("I give the guided drive up: ", Reason);
            .fail;
        }
    }.
+!tryGoto(X, Y) <- goto(X, Y).
-!tryGoto(X, Y)[R1 | Rest]
<- if (.member(no_progress, [R1 | Rest])) { +gotoFailed(no_progress) } else { +gotoFailed(R1) }.

/* Execute: guided by the helper's camera when the encoders fail */

// The helper streams my pose as it sees it (its odometry frame); the start and the goal in
// that frame come from where it sees me now and how far I commanded myself since the start.
+!beGuided : helpedBy(H)
<- .send(H, achieve, guideMe);
    !guidedBy(H).
+!beGuided <- !missionOver(false, [], guided, odometry).
-!beGuided : helpedBy(H)
<- -beingGuided;
    !sendSafely(H, achieve, stopGuiding);
    !missionOver(false, [], guided, odometry).

// The mission driven on H's view of me, once H is guiding me (agents/fleet/fleet_robot.asl
// calls it for the robot its contract net chose).
+!guidedBy(H) : .my_name(Me) & guideWait(W)
<- .wait(seenAt(_, _, _)[source(H)], W, _);
    ?seenAt(X, Y, T)[source(H)];
    ?cmd_pos(CX, CY, CT);
    ?missionCmdStart(CS);
    ?relative(CS, pose(CX, CY, CT), Travelled);
    ?inverse(Travelled, Back);
    ?compose(pose(X, Y, T), Back, Start);
    ?missionLength(L);
    ?compose(Start, pose(L, 0, 0), Goal);
    .print(H, " sees me at (", X, ", ", Y, "); I follow its view");
    !guidedPoseFrom(H);
    +beingGuided;
    !driveMission(Goal, Start);
    -beingGuided;
    pose_source(odom);
    .send(H, achieve, stopGuiding);
    !missionOver(true, [Me], guided, odometry).
-!guidedBy(H)
<- -beingGuided;
    !sendSafely(H, achieve, stopGuiding);
    !guidanceFailed(H).

// My decomposer's guided pose: the helper's view of me, wired by the launch file.
+!guidedPoseFrom(H) <- pose_source(guided).
+!guidanceFailed(H) <- !missionOver(false, [], guided, odometry).

/* Execute: delegate the mission with a contract net when I cannot move */

// The task: reach the point Forward metres ahead of me and Left metres to my left.
delegatedTask(reach(Me, F, L))
    :- missionGoal(Goal) & pos(X, Y, T) & relative(pose(X, Y, T), Goal, pose(F, L, _)) & .my_name(Me).

+!delegateMission
: delegatedTask(reach(Me, F, L))
  & .all_names(All) & .delete(Me, All, Others) & Others \== []
  & proposalWait(W)
<- .print("I cannot move: calling for proposals to reach the point ", F, " m ahead of me and ", L, " m to my left");
    .send(Others, tell, cfp(reach(Me, F, L)));
    .length(Others, N);
    .wait(.count(answer(reach(Me, F, L), _), N), W, _);
    .findall(offer(Cost, A), propose(reach(Me, F, L), Cost)[source(A)], Offers);
    !awardMission(reach(Me, F, L), Offers).
+!delegateMission <- !missionOver(false, [], delegate, both_actuators).

+!awardMission(Task, []) <- .print("Nobody can take my mission over"); !missionOver(false, [], delegate, both_actuators).
+!awardMission(Task, Offers)
<- .min(Offers, offer(Cost, Winner));
    .print("Out of service: ", Winner, " takes my mission over (", Cost, " m to go)");
    .send(Winner, tell, acceptProposal(Task));
    for (.member(offer(_, A), Offers) & A \== Winner) { .send(A, tell, rejectProposal(Task)) };
    !awaitDelegate(Task, Winner).

// The robot that took my mission over reports back (agents/fleet/fleet_robot.asl waits so
// for the robot its contract net chose).
+!awaitDelegate(Task, Winner) : delegateTimeout(W)
<- .wait(done(Task)[source(Winner)] | failure(Task)[source(Winner)], W, _);
    if (done(Task)[source(Winner)]) {
        !delegated(Task, Winner);
    } else {
        !notDelegated(Task, Winner);
    }.
+!delegated(Task, Winner) <- !missionOver(true, [Winner], delegate, both_actuators).
+!notDelegated(Task, Winner) <- !missionOver(false, [], delegate, both_actuators).

/* The outcome */

+!missionOver(Completed, By, Recovery, Diagnosis)
<- .print("Mission completed: ", Completed, " by ", By, " (recovery ", Recovery, ")");
    report_mission(Completed, By, Recovery, Diagnosis);
    !finish.
-!missionOver(Completed, By, Recovery, Diagnosis)
<- .print("could not report the mission");
    !finish.
