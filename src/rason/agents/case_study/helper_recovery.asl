// The helper's part in Faulty's recovery (issue 15), included by helper.asl: it guides a
// robot whose encoders failed, and takes over the mission of a robot that cannot move
// (contract net participant). Perceptions: located/4 (robot_guide: where a robot seen by the
// camera is, in this robot's odometry frame) and pos/3 (this robot's odometry).

{ include("poses.asl") }

guideSlice(20).        // s per guide action (below the bridge's 60 s action timeout)
sightingSettle(1000).  // ms the guided robot is watched before its pose is sent
detour(0.5, 0.75).     // m ahead of and beside a robot whose mission I take over: the
                       // waypoint that keeps me clear of it on the way to its goal

// The name robot_guide knows robot R by (located/4, guide/2): its agent's name, unless the
// including program names it otherwise (cameraName/2, agents/fleet/fleet_robot.asl).
guideName(R, N) :- cameraName(R, N).
guideName(R, R) :- not cameraName(R, _).
locatedAs(R, X, Y, Yaw) :- guideName(R, N) & located(N, X, Y, Yaw).

// The task reach(R, Forward, Left) from where I see R: R's pose (Seen) and the goal (Goal) in
// my odometry frame, and how far I would drive to it (Cost, metres).
reachGoal(R, F, L, pose(X, Y, T), Goal, Cost)
    :- locatedAs(R, X, Y, T) & pos(HX, HY, HT)
     & compose(pose(X, Y, T), pose(F, L, 0), Goal) & distance(pose(HX, HY, HT), Goal, Cost).

/* Guiding: keep the robot centred in the camera; robot_guide streams its pose */

+!guideMe[source(R)] <- !startGuiding(R).

// Also the fleet's guide (agents/fleet/fleet_robot.asl), once its contract net chose it.
+!startGuiding(R)
<- +guiding(R);
    !!keepGuiding(R);
    !tellSighting(R).

+!tellSighting(R) : sightingSettle(T)
<- .wait(locatedAs(R, _, _, _), 5000, _);
    .wait(T);
    ?locatedAs(R, X, Y, Yaw);
    .print("Guiding ", R, ", seen at (", X, ", ", Y, ")");
    .send(R, tell, seenAt(X, Y, Yaw)).
-!tellSighting(R) <- .print("I cannot see ", R, " to guide it").

+!keepGuiding(R) : guiding(R) & guideSlice(S) & guideName(R, N)
<- guide(N, S);
    !keepGuiding(R).
+!keepGuiding(R) <- true.
-!keepGuiding(R) <- .print("I lost sight of ", R); -guiding(R); !guidedLost(R).
+!guidedLost(R) <- true.     // the including program may hand the guiding on (fleet_robot.asl)

+!stopGuiding[source(R)] : guiding(R)
<- -guiding(R);
    .drop_desire(keepGuiding(R));
    .print("Stopped guiding ", R).
+!stopGuiding[source(R)] <- true.

// A robot out of reach while I guide it may only be behind a lossy link (presence drops
// for seconds at 20-30 % loss): its pose still goes out through the relay, so I go on
// guiding for partnerGrace and stop only if it is not back by then.
-present(R) : guiding(R) <- !awaitGuided(R).
+!awaitGuided(R) : partnerGrace(G) <- .wait(present(R), G).
-!awaitGuided(R) : guiding(R) & not present(R)
<- .print(R, " left; I stop guiding it");
    -guiding(R);
    .drop_desire(keepGuiding(R)).
-!awaitGuided(_) <- true.

/* Contract net: a robot that cannot move calls for proposals to reach a point */

// The task reach(R, Forward, Left): the point Forward m ahead of R and Left m to its left.
// The offer is the distance I would drive; I can only offer while I see R.
+cfp(reach(R, F, L))[source(R)] : reachGoal(R, F, L, Seen, Goal, Cost)
<- -+offered(reach(R, F, L), Seen, Goal);
    .send(R, tell, propose(reach(R, F, L), Cost)).
+cfp(Task)[source(R)]
<- .print("I cannot offer to do ", Task, ": I do not see ", R, " or do not know where I am");
    .send(R, tell, refuse(Task)).

+acceptProposal(Task)[source(R)] <- !takeOver(Task, R).
+rejectProposal(Task)[source(R)] <- -offered(Task, _, _).

+!takeOver(Task, R)
: offered(Task, Robot, pose(GX, GY, GT)) & pos(HX, HY, HT) & detour(Ahead, Beside)
  & relative(Robot, pose(HX, HY, HT), pose(_, HL, _)) & signOf(HL, Side)   // the side I am on
  & compose(Robot, pose(Ahead, Side * Beside, 0), pose(WX, WY, _))
<- .print("Taking over the mission of ", R, ": to (", GX, ", ", GY, ")");
    goto(WX, WY);
    goto(GX, GY);
    .print("I reached the goal of ", R);
    -offered(Task, _, _);
    .send(R, tell, done(Task)).
-!takeOver(Task, R)
<- .print("I could not do the mission of ", R);
    !sendSafely(R, tell, failure(Task)).
