// The case study as one program for every robot of a fleet (issue 34; docs/guides/
// fleet-program.md, "The case study as one fleet program"). Each robot drives the case
// study's mission; a robot whose move fails and that cannot diagnose it alone asks for a
// robot to watch it by contract net (contract_net.asl) and runs Faulty's dialogue with the
// robot awarded; a robot with a camera offers to watch ("observe" in the directory) and,
// awarded, runs Helper's dialogue for that caller. Roles come from what happens and what a
// robot has, never from its name. Unlike the pair, no robot stops the MAS after its
// diagnosis: the others may still need it to watch them. With recovery(on) the mission goes
// on after the diagnosis with each of the pair's recoveries: compensation, a guide for an
// odometry fault and a robot that takes the mission over for both actuators, each chosen by
// contract net as the watcher is, each running the pair's own plans (faulty_recovery.asl,
// helper_recovery.asl).

// contract_net.asl first: its -present plans (a contractor that leaves, a caller that
// leaves) are the ones a fleet robot runs.
{ include("contract_net.asl") }
{ include("../case_study/poses.asl") }

callAgain(2000).       // ms before a caller that nobody could help calls again (within helpTimeout)
searchCost(360).       // the bid of a robot that must search for the caller: a full turn at worst
unseenReachCost(100).  // m: the bid to take over the mission of a robot I do not see (yet)
recoveryCalls(30).     // calls for a guide or a robot to take my mission over, callAgain
                       // apart, before the mission is given up

/* Which robot the camera sees */

// The camera may name a robot as the simulator's world does (vision_synth with fleet.yaml:
// r1), while its agent is r1_robot (the robot's ~agent_prefix r1_, and this program's agent,
// robot): a robot is looked for under its agent's name (helper_dialogue.asl's inView/4)
// and under that one.
inView(A, Deg, Depth, Yaw) :- cameraName(A, N) & robot(N, Deg, Depth, Yaw).
cameraName(A, N)
    :- .term2string(A, S) & .length(S, L) & L > 6
     & .substring("_robot", S, P) & P == L - 6
     & .substring(Prefix, S, 0, P) & .term2string(N, Prefix).

/* Bids: lower is better, in degrees I would turn before my camera faces the caller */

// I watch others only once my own mission ended without a fault (with recovery(on), once
// its outcome is reported: a false positive's mission goes on first).
canWatch :- diagnosed(none) & not recovery(on).
canWatch :- diagnosed(none) & missionEnded.

// Seen now: the camera's angle to it.
bid(help(C, _), C, B) :- canWatch & inView(C, Deg, _, _) & B = math.abs(Deg).
// Not seen, but both poses known in the room's frame (mapPose/3, localization.yaml), and I
// would not see it side-on from here: the clockwise turn that faces it.
bid(help(C, at(X, Y, T)), C, B)
    :- canWatch & not inView(C, _, _, _) & mapPose(MX, MY, MT)
     & not sideOn(pose(X, Y, T), pose(MX, MY, MT))
     & clockwiseFacing(pose(MX, MY, MT), X, Y, B).
// I would see it side-on from here: I first drive to the vantage point ahead of it or behind it
// (viewFrom below), so I bid after every robot that can look from where it stands, the nearer
// vantage point first. A robot that does not perceive its own odometry (pos/3) cannot drive there
// and does not bid.
bid(help(C, at(X, Y, T)), C, B)
    :- canWatch & not inView(C, _, _, _) & mapPose(MX, MY, MT) & pos(_, _, _)
     & sideOn(pose(X, Y, T), pose(MX, MY, MT))
     & vantagePoint(pose(X, Y, T), pose(MX, MY, MT), V) & distance(pose(MX, MY, MT), V, D)
     & searchCost(S) & B = S + math.round(D * 100) / 100.
// Neither: a search from where I face.
bid(help(C, Where), C, B)
    :- canWatch & not inView(C, _, _, _) & not (Where = at(_, _, _) & mapPose(_, _, _)) & searchCost(B).
// Guiding a robot starts as watching it does: by facing it.
bid(guide(C, Where), C, B) :- bid(help(C, Where), C, B).
// Taking a mission over: the metres I would drive to its goal, seen from where I see the
// caller (helper_recovery.asl's reachGoal); not seen, a search first, then an unknown way.
bid(reach(C, F, L), C, B) :- canWatch & reachGoal(C, F, L, _, _, B).
bid(reach(C, F, L), C, B) :- canWatch & not locatedAs(C, _, _, _) & unseenReachCost(B).

// A ratio that rounding may have put just outside [-1, 1], as a cosine.
cosine(R, 1) :- R > 1.
cosine(R, -1) :- R < -1.
cosine(R, R) :- R >= -1 & R <= 1.
// (Straight ahead is no turn, whatever side rounding put it on.)
clockwiseTo(Left, A, A) :- Left <= 0 | A < 0.01.
clockwiseTo(Left, A, B) :- Left > 0 & A >= 0.01 & B = 360 - A.
// From pose Me (the room's frame), the clockwise turn in degrees that faces the point (X, Y),
// and the shortest turn that does (negative: counter-clockwise, as turn/1 takes it).
clockwiseFacing(Me, X, Y, B)
    :- relative(Me, pose(X, Y, 0), pose(F, L, _))
     & D = math.sqrt(F * F + L * L) & D > 0 & Ratio = F / D & cosine(Ratio, Cos)
     & A = math.acos(Cos) * 180 / math.pi
     & clockwiseTo(L, A, T) & B = math.round(T * 100) / 100.
shortestTurn(B, B) :- B <= 180.
shortestTurn(B, A) :- B > 180 & A = B - 360.

/* Where a watcher sees its caller from */

// A robot seen side-on shows one cylinder behind the other, and the camera never takes one
// cylinder for a robot. Side-on: within 90 - sideOnFrom degrees of the caller's left or right
// (its cylinders 0.227 m apart look less than 0.08 m apart, their 0.04 m width and a gap).
sideOnFrom(70).
viewDistance(1.5).     // m ahead of or behind the caller: its two cylinders well apart
sideOn(Caller, Me)
    :- relative(Caller, Me, pose(F, L, _)) & sideOnFrom(A)
     & math.abs(L) * math.cos(A * math.pi / 180) >= math.abs(F) * math.sin(A * math.pi / 180).
// The vantage point on my side of the caller: viewDistance ahead of it, or behind it. (Not
// viewpoint/3: helper_dialogue.asl keeps a belief of that name, and removes it.)
vantagePoint(Caller, Me, V)
    :- relative(Caller, Me, pose(F, _, _)) & viewDistance(D) & signOf(F, Sign)
     & compose(Caller, pose(Sign * D, 0, 0), V).

// The robot watching me: the one I awarded the help, from the award on (its found(Me) may
// come before its acceptance is handled).
watchedBy(R) :- .my_name(Me) & awarded(_, help(Me, _), R).

// Where I am for a watcher that does not see me: in the shared frame, when I know it.
whereIAm(at(X, Y, Yaw)) :- mapPose(X, Y, Yaw).
whereIAm(unknown) :- not mapPose(_, _, _).

/* Initial goals */

!start.

/* Plans */

// A camera (its frames) makes me a robot that can watch others, and, with recovery(on)
// (my own pose perceived), guide them and take their missions over.
+cameraFrame(_, _) : not offering(observe)
<- +offering(observe);
    .df_register("observe");
    if (recovery(on)) { .df_register("reach") }.

// As Faulty: start once another robot is present (or after 20 s alone).
+!start
<- .my_name(Me);
    .wait(present(Other) & Other \== Me, 20000);
    !noteMissionStart;
    !goToDestination.
-!start <- .print("No other robot around; going alone."); !noteMissionStart; !goToDestination.

/* The caller: a robot whose move failed */

+!askForHelp : diagnosed(_) <- true.
+!askForHelp : .my_name(Me) & whereIAm(Where)
<- -+helpTask(help(Me, Where));
    !contract("observe", help(Me, Where)).

+!contracted(help(_, _), P) <- .print(P, " will watch me").

// Nobody could (or can any more) watch me: call again, until helpTimeout ends it.
+!uncontracted(help(_, _), _) : diagnosed(_) <- true.
+!uncontracted(help(_, _), Reason) : callAgain(W)
<- .print("Nobody can watch me now (", Reason, "); I call again in ", W / 1000, " s");
    .wait(W);
    !!askForHelp.

// The robot watching me is lost (it failed, left, or was revoked): what I was doing for it
// stops (a move under way is taken back); the contract net awards the next bidder.
-awarded(_, help(Me, _), P) : .my_name(Me) & not diagnosed(_)
<- .drop_desire(tryMove).
// A guide lost or released: its sightings go with it (a later award to the same robot must
// wait for a new one).
-awarded(_, guide(Me, _), P) : .my_name(Me) <- .abolish(seenAt(_, _, _)[source(P)]).
-awarded(_, _, _) <- true.

// Only the robot watching me now takes part in my dialogue: a robot lost meanwhile may
// still have something on its way.
+found(Me)[source(R)] : .my_name(Me) & not watchedBy(R)
<- -found(Me)[source(R)].
+notFound(Me)[source(R)] : .my_name(Me) & not watchedBy(R)
<- -notFound(Me)[source(R)].
+!tryMove[source(R)] : not watchedBy(R) <- .print("Ignored: ", R, " does not watch me").
+!noFeedback(_)[source(R)] : not watchedBy(R) <- .print("Ignored: ", R, " does not watch me").
+!feedback(_, _)[source(R)] : not watchedBy(R) <- .print("Ignored: ", R, " does not watch me").

// The diagnosis releases the robot that watched me; I stay for the others. With
// recovery(on) (fleet_robot_mission.mas2j) the mission then goes on as the pair's Faulty's
// does (faulty_recovery.asl, included below).
+!afterDiagnosis(D) : helpTask(Task) <- !contractDone(Task); -helpTask(Task); !afterDiagnosis(D).
// My part ends (the mission's outcome reported): whoever still works for me is released.
+!finish
<- +missionEnded;
    .findall(Task, awarded(_, Task, _), Tasks);
    for (.member(Task, Tasks)) { !contractDone(Task) }.

{ include("../case_study/faulty_dialogue.asl") }

/* The watcher: the robot awarded the help */

+!carryOut(help(C, Where), C)
<- .print("Watching ", C, " for its diagnosis");
    +helping(C);
    -+centringTurns(0);
    !viewFrom(C, Where);
    !findRobot(C, 0);
    .print("helper ready.");
    .send(C, tell, found(C)).

// Before the search: a caller that said where it is (at/3, the room's frame) and that I would
// see side-on from here, I first go to the vantage point ahead of or behind it (goto/2 takes my
// odometry's frame); then I face it, so the search starts with it in view. It stays where it
// called from: its move failed.
+!viewFrom(C, _) : inView(C, _, _, _) <- true.
+!viewFrom(C, at(X, Y, T))
    : mapPose(MX, MY, MT) & pos(PX, PY, PT) & sideOn(pose(X, Y, T), pose(MX, MY, MT))
    & vantagePoint(pose(X, Y, T), pose(MX, MY, MT), V) & V = pose(VX, VY, _)
    & relative(pose(MX, MY, MT), V, R) & compose(pose(PX, PY, PT), R, pose(GX, GY, _))
<- .print("I would see ", C, " side-on from here: I look from (", math.round(VX * 100) / 100, ", ",
           math.round(VY * 100) / 100, ") first");
    goto(GX, GY);
    !settle;
    !faceCaller(X, Y).
+!viewFrom(_, at(X, Y, _)) <- !faceCaller(X, Y).
+!viewFrom(_, _) <- true.
+!faceCaller(X, Y) : mapPose(MX, MY, MT) & clockwiseFacing(pose(MX, MY, MT), X, Y, B) & shortestTurn(B, A)
<- turn(A);
    !settle.
+!faceCaller(_, _) <- true.

// Where the robot I watch was seen last (helper_dialogue.asl notes it for a camera that names
// it as its agent is named).
+robot(N, D, _, _) : helping(R) & cameraName(R, N) <- -+lastSeen(R, D).

// Released, revoked, failed (I could not find it) or its caller gone: nothing of C is kept
// and nothing done for it goes on (a guide action under way stops). (The search and the
// drive to a goal are carryOut's: the contract net drops them on a revoke; dropping them
// here would also drop the failure plans that tell the caller.)
-committed(_, _, C) <- !stopWatching(C).
+!stopWatching(C)
<- .drop_desire(trackMe);
    .drop_desire(giveFeedback);
    -guiding(C);
    .drop_desire(keepGuiding(C));
    .drop_desire(guidedLost(C));
    .abolish(offered(_, _, _));
    -helping(C);
    -foundRobot(C, _, _, _);
    -viewpoint(_, _, _);
    -lastSeen(C, _).

// Awarded a guide: I face the caller, then guide it as the pair's helper does
// (helper_recovery.asl): robot_guide streams its pose as my camera sees it, and I turn to keep
// it in view. A full circle without seeing it fails the task: the caller awards the next.
+!carryOut(guide(C, Where), C)
<- .print("Guiding ", C);
    -+centringTurns(0);
    !viewFrom(C, Where);
    !findRobot(C, 0);
    !startGuiding(C).

// Lost sight of the robot I guide (robot_guide's guide ended lost: e.g. it turned side-on,
// one cylinder behind the other, and stopped there, its guided pose gone stale): I look for it
// again and guide it on, in the same odometry frame, so its drive goes on. Not found (a
// full circle): the task failed, and its caller awards the next bidder.
+!guidedLost(C) : committed(_, guide(C, _), C)
<- .print("I look for ", C, " again");
    -+centringTurns(0);
    !findRobot(C, 0);
    +guiding(C);
    !!keepGuiding(C).
-!guidedLost(C) : committed(Id, guide(C, Where), C)
<- !sendOrFail(C, tell, failed(Id));
    -committed(Id, guide(C, Where), C).

// Awarded a mission: I face the caller, then reach its goal as the pair's helper does
// (helper_recovery.asl's takeOver, which tells the caller done or failure).
+!carryOut(reach(C, F, L), C)
<- .print("Taking over the mission of ", C);
    -+centringTurns(0);
    !findRobot(C, 0);
    .wait(reachGoal(C, F, L, _, _, _), 5000);
    ?reachGoal(C, F, L, Seen, Goal, _);
    -+offered(reach(C, F, L), Seen, Goal);
    !takeOver(reach(C, F, L), C).

{ include("../case_study/helper_dialogue.asl") }

/* Recovery by another robot (recovery(on)): guided, or my mission delegated */

// The pair's Faulty asks the robot that watched it; I ask by contract net, as for the
// watcher: the guide among the robots that observe (odometry), the robot that takes my
// mission over among those that offer "reach" (both actuators). The plans that follow the
// choice are the pair's (faulty_recovery.asl's !guidedBy and !awaitDelegate; the
// contractor's are helper_recovery.asl's).
+!beGuided : .my_name(Me) & whereIAm(Where) <- !contract("observe", guide(Me, Where)).
+!delegateMission : delegatedTask(Task) <- !contract("reach", Task).

+!contracted(guide(_, _), P) <- .print(P, " will guide me"); !guidedBy(P).
+!contracted(reach(Me, F, L), P) <- .print(P, " takes my mission over"); !awaitDelegate(reach(Me, F, L), P).

// My decomposer reads the guided poses from the guide's robot_guide (/<its robot>/located/<me>:
// a robot's namespace is its name in the world, as in rason_sim's fleet.yaml).
+!guidedPoseFrom(H) : .my_name(Me) & cameraName(H, HN) & cameraName(Me, MN)
<- .concat("/", HN, "/located/", MN, Topic);
    pose_source(guided, Topic).

// The guide or the delegate did not do: the next bidder (a new intention: the contract net
// drops the one working with the contractor lost).
+!guidanceFailed(H) : .my_name(Me) & awarded(_, guide(Me, Where), H)
<- .print("Guided by ", H, " I could not complete the mission; the next bidder");
    !!contractFailed(guide(Me, Where)).
+!notDelegated(Task, P) : awarded(_, Task, P)
<- .print(P, " did not complete my mission; the next bidder");
    !!contractFailed(Task).

// Nobody can (any more): call again, recoveryCalls times at most, then the mission ends.
recoveryOf(guide(_, _), guided, odometry).
recoveryOf(reach(_, _, _), delegate, both_actuators).
+!uncontracted(Task, Reason) : recoveryOf(Task, _, Diagnosis) & recoveryCalls(N) & N > 1 & callAgain(W)
<- -+recoveryCalls(N - 1);
    .print("Nobody can do ", Task, " now (", Reason, "); I call again in ", W / 1000, " s");
    .wait(W);
    !!recover(Diagnosis).
+!uncontracted(Task, Reason) : recoveryOf(Task, Recovery, Diagnosis)
<- .print("Nobody could do ", Task, " (", Reason, ")");
    !missionOver(false, [], Recovery, Diagnosis).

{ include("../case_study/faulty_recovery.asl") }
+!afterDiagnosis(_) <- true.     // without recovery(on): the diagnosis ends my part

// The guide and the delegate: helper_recovery.asl's plans, started by carryOut above. (Its
// guideMe, cfp and acceptProposal are the pair's entry points, which no fleet robot sends.)
{ include("../case_study/helper_recovery.asl") }

{ include("../case_study/send_safely.asl") }
