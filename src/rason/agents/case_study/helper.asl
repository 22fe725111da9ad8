// Helper: the robot with the camera (thesis §6.4, Appendix A Listing A.2), on a robot of
// its own with its own rason_mas. The plans are the thesis's; changes are marked
//   FIX       needed on real Jason or with a real camera,
//   IMPROVED  asked for by thesis §8.1, or an explicit answer when it cannot see.

{ include("helper_dialogue.asl") }

partnerGrace(60000).   // IMPROVED: ms I go on helping a robot out of reach (see -present):
                       // a cut of 10 s plus the reconnection over a lossy link, in ROS
                       // time, which runs up to twice as fast as the wall at rate 0

/* Initial goals */
!start.

/* Plans */

+!start : true <- .print("ZZzzz...").

// IMPROVED: one robot at a time.
+!helpme[source(R)] : helping(Other)
<- .print("Already helping ", Other, "; ", R, " has to wait").

+!helpme[source(R)]
  <- +helping(R);
  -+centringTurns(0);
  !findRobot(R,0);
  .print("helper ready.");
  .send(R,tell,found(R)).

// IMPROVED: the robot asking for help is out of reach. It may only be behind a broken
// link (robots on hosts of their own): what I send it meanwhile waits in the fleet channel
// and arrives if it comes back (each send ends by its receipt), so I go on for up to
// partnerGrace ms. If it is not back by then it left (its agents stopped, or it is gone):
// I stop searching for it or tracking it; a turn under way stops at once (the bridge
// cancels it).

-present(R) : helping(R) <- !awaitReturn(R).

+!awaitReturn(R) : partnerGrace(G)
<- .print(R, " is out of reach; I go on helping it for up to ", G / 1000, " s");
  .wait(present(R), G);
  .print(R, " is back in reach").

-!awaitReturn(R) : helping(R) & not present(R)
<- .print(R, " left; I stop helping it");
  .drop_desire(helpme);
  .drop_desire(trackMe);
  .drop_desire(giveFeedback);
  -helping(R);
  -foundRobot(R,_,_,_);
  -viewpoint(_,_,_);
  -lastSeen(R,_).
-!awaitReturn(_) <- true.

// IMPROVED: say so when the robot was not found, instead of searching for ever.
-!helpme[source(R)]
  <- .print("I could not find ", R);
  -helping(R);
  !sendSafely(R,tell,notFound(R)).

{ include("helper_recovery.asl") }

{ include("send_safely.asl") }
