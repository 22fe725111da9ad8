/* A module kept once per kind of fruit (keeper.asl includes it into apples and into pears):
   ::count is the module's own, so each kind counts apart; the answer is the module's too. */
::count(0).
+!add(N)[source(S)] : ::count(C) <- -+::count(C + N); .send(S, tell, ::total(C + N)).
