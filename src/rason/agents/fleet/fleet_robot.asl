// The case study as one program for every robot of a fleet (issue 34; docs/guides/
// fleet-program.md, "The case study as one fleet program"). Each robot drives the case
// study's mission; a robot whose move fails and that cannot diagnose it alone asks for a
// robot to watch it by contract net (contract_net.asl) and runs Faulty's dialogue with the
// robot awarded; a robot with a camera offers to watch ("observe" in the directory) and,
// awarded, runs Helper's dialogue for that caller. Roles come from what happens and what a
// robot has, never from its name. Unlike the pair, no robot stops the MAS after its
// diagnosis: the others may still need it to watch them.

// contract_net.asl first: its -present plans (a contractor that leaves, a caller that
// leaves) are the ones a fleet robot runs.
{ include("contract_net.asl") }
{ include("../case_study/poses.asl") }

callAgain(2000).       // ms before a caller that nobody could help calls again (within helpTimeout)
searchCost(360).       // the bid of a robot that must search for the caller: a full turn at worst

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

// I watch others only once my own mission ended without a fault.
canWatch :- diagnosed(none).

// Seen now: the camera's angle to it.
bid(help(C, _), C, B) :- canWatch & inView(C, Deg, _, _) & B = math.abs(Deg).
// Not seen, but both poses known in a frame every robot shares (mapPose/3): the clockwise
// turn (the search turns clockwise) that faces it.
bid(help(C, at(X, Y)), C, B)
    :- canWatch & not inView(C, _, _, _) & mapPose(MX, MY, MT)
     & relative(pose(MX, MY, MT), pose(X, Y, 0), pose(F, L, _))
     & D = math.sqrt(F * F + L * L) & D > 0 & Ratio = F / D & cosine(Ratio, Cos)
     & A = math.acos(Cos) * 180 / math.pi
     & clockwiseTo(L, A, T) & B = math.round(T * 100) / 100.
// Neither: a search from where I face.
bid(help(C, Where), C, B)
    :- canWatch & not inView(C, _, _, _) & not (Where = at(_, _) & mapPose(_, _, _)) & searchCost(B).

// A ratio that rounding may have put just outside [-1, 1], as a cosine.
cosine(R, 1) :- R > 1.
cosine(R, -1) :- R < -1.
cosine(R, R) :- R >= -1 & R <= 1.
clockwiseTo(Left, A, A) :- Left <= 0.
clockwiseTo(Left, A, B) :- Left > 0 & B = 360 - A.

// The robot watching me: the one I awarded the help, from the award on (its found(Me) may
// come before its acceptance is handled).
watchedBy(R) :- .my_name(Me) & awarded(_, help(Me, _), R).

// Where I am for a watcher that does not see me: in the shared frame, when I know it.
whereIAm(at(X, Y)) :- mapPose(X, Y, _).
whereIAm(unknown) :- not mapPose(_, _, _).

/* Initial goals */

!start.

/* Plans */

// A camera (its frames) makes me a robot that can watch others.
+cameraFrame(_, _) : not offering(observe)
<- +offering(observe);
    .df_register("observe").

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
+!finish <- true.

{ include("../case_study/faulty_dialogue.asl") }

/* The watcher: the robot awarded the help */

+!carryOut(help(C, _), C)
<- .print("Watching ", C, " for its diagnosis");
    +helping(C);
    -+centringTurns(0);
    !findRobot(C, 0);
    .print("helper ready.");
    .send(C, tell, found(C)).

// Where the robot I watch was seen last (helper_dialogue.asl notes it for a camera that names
// it as its agent is named).
+robot(N, D, _, _) : helping(R) & cameraName(R, N) <- -+lastSeen(R, D).

// Released, revoked, failed (I could not find it) or its caller gone: nothing of C is kept
// and nothing done for it goes on. (The search is carryOut's: the contract net drops it on a
// revoke; dropping it here would also drop the failure plan that tells the caller.)
-committed(_, help(C, _), C) <- !stopWatching(C).
+!stopWatching(C)
<- .drop_desire(trackMe);
    .drop_desire(giveFeedback);
    -helping(C);
    -foundRobot(C, _, _, _);
    -viewpoint(_, _, _);
    -lastSeen(C, _).

{ include("../case_study/helper_dialogue.asl") }

// Recovery in the fleet so far: compensating a one-wheel fault, and going on after a false
// positive. Being guided (odometry) and delegating the mission (both actuators) need a
// watcher that runs helper_recovery.asl, which no fleet robot does yet: those missions end
// as not completed, with the reason in the log.
{ include("../case_study/faulty_recovery.asl") }
+!afterDiagnosis(_) <- true.     // without recovery(on): the diagnosis ends my part

{ include("../case_study/send_safely.asl") }
