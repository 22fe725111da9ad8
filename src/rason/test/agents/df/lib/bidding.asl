/* Bidding in a tender: answer a call for proposals with our cost, then hear the outcome. */

+!cfp(Parcel)[source(D)] : cost(C) <- .send(D, tell, propose(Parcel, C)).
+!award(Parcel)[source(D)] <- .print("won ", Parcel, " from ", D).
+!decline(Parcel)[source(D)] <- .print("lost ", Parcel).
