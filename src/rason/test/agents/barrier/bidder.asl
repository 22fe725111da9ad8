/* A bidder: registers in the directory and answers a call for proposals with its price. */

!register.
+!register <- .df_register("bidding").

+!cfp(Task)[source(A)] : price(P) <- .send(A, tell, propose(Task, P)).
+!cfp(Task)[source(A)] <- .send(A, tell, propose(Task, 10)).
