// Agent faulty: thesis Appendix A, Listing A.1, run unchanged except where the listing
// does not work on real Jason, marked FIX: the failure reason read from Jason's sorted
// annotations, the helper's giveFeedback instead of givemeFeedback, the sender R printed
// instead of an unbound Helper.

/* Initial beliefs and rules */

/* Initial goals */

!start.

/* Plans */

+!start <- .wait(4000); !goToDestination.

+!goToDestination
<- .print("Moving to Destination");
    move(1);
    move(-1);
    .print("Arriving at destination").

// FIX: the thesis stored +reason(R1), but Jason sorts the failure annotations, so R1 is
// code(move(1)); the reason is the member no_progress or bad_move of [R1|Rest].
-!goToDestination[R1 | Rest]
: triedAlone & .member(Reason, [no_progress, bad_move]) & .member(Reason, [R1 | Rest])
<- .print("Cannot solve problem alone, asking for help.");
    +reason(Reason);
    .broadcast(achieve, helpme).

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

//Plans to help diagnose
+!tryMove[source(R)]
<- .print("Trying to bit for ",R);
    move(0.3);
    .print("It was just a false positive.");
    -reason(_);
    -triedAlone;
    .send(R,achieve,thanks).

// FIX: the helper's plan is +!giveFeedback; the thesis sent givemeFeedback.
-!tryMove[source(R)]
<- .print(" requesting some feedback from ",R);
    .send(R,achieve,giveFeedback).

+found(Me)[source(R)]
: .my_name(Me)
<- .print(R," found me, asking to track me");
    .send(R,achieve,trackMe).

// FIX (all feedback plans): the thesis printed an unbound Helper; the sender is R.
+!feedback(initPos(Deg,Depth,Yaw),currPos(Deg1,Depth1,Yaw1))[source(R)]
: reason(no_progress)
  & ( not (Depth == Depth1) | not (Deg == Deg1) )
<- .print(R," has reported as initial info( pos ",Deg," degrees, depth ",Depth," meters and yaw ",Yaw," degrees )");
    .print("and current info( pos ",Deg1," degrees, depth ",Depth1," meters and yaw",Yaw1," degrees )");
    .print("fault in odometry system, thanks ", R);
    .send(R,achieve,thanks).

+!feedback(initPos(Deg,Depth,Yaw),currPos(Deg1,Depth1,Yaw1))[source(R)]
: reason(no_progress)
  & Depth == Depth1
  & Deg == Deg1
<- .print(R," has reported as initial info( pos ",Deg," degrees, depth ",Depth," meters and yaw ",Yaw," degrees )");
    .print("and current info( pos ",Deg1," degrees, depth ",Depth1," meters and yaw",Yaw1," degrees )");
    .print("fault in both actuators, thanks ",R);
    .send(R, achieve, thanks).

+!feedback(initPos(Deg,Depth,Yaw),currPos(Deg1,Depth1,Yaw1))[source(R)]
: reason(bad_move)
  & math.abs(Yaw1 - (Yaw + (Deg1 - Deg))) < 8
<- .print(R," has reported as initial info( pos ",Deg," degrees, depth ",Depth," meters and yaw ",Yaw," degrees )");
    .print("and current info( pos ",Deg1," degrees, depth ",Depth1," meters and yaw",Yaw1," degrees )");
    .print("it was a false positive for bad_move, thanks ",R);
    .send(R, achieve, thanks).

+!feedback(initPos(Deg,Depth,Yaw),currPos(Deg1,Depth1,Yaw1))[source(R)]
: reason(bad_move)
  & ((Yaw1 - (Yaw + (Deg1 - Deg))) > 8)
<- .print(R," has reported as initial info( pos ",Deg," degrees, depth ",Depth," meters and yaw ",Yaw," degrees )");
    .print("and current info( pos ",Deg1," degrees, depth ",Depth1," meters and yaw",Yaw1," degrees )");
    .print("right actuator has problems, thanks ",R);
    .send(R, achieve, thanks).

+!feedback(initPos(Deg,Depth,Yaw),currPos(Deg1,Depth1,Yaw1))[source(R)]
: reason(bad_move)
  & ((Yaw1 - (Yaw + (Deg1 - Deg))) < -8)
<- .print(R," has reported as initial info( pos ",Deg," degrees, depth ",Depth," meters and yaw ",Yaw," degrees )");
    .print("and current info( pos ",Deg1," degrees, depth ",Depth1," meters and yaw",Yaw1," degrees )");
    .print("left actuator has problems, thanks ",R);
    .send(R, achieve, thanks).
