// Everything it prints comes from the project's own classes: an internal action, the belief
// base's count, a belief its agent class adds, the environment's answer to an action.
!show.

+!show : made_by(Who)
<- mylib.twice(21, X);
   .print("twice 21 is ", X);
   +seen(X);
   +seen(X + 1);
   mylib.seen_adds(N);
   .print("the belief base counted ", N, " seen beliefs");
   .print("made by ", Who);
   ring.

+rang(Times)[source(percept)] <- .print("the environment rang ", Times, " times"); .stopMAS.
