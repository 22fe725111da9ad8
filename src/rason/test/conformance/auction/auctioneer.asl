/* A sealed-bid auction: once three bidders are there, the auctioneer broadcasts the lot,
   takes one bid from each and tells everyone who won. */
!start.
+!start : .all_names(L) & .length(L, N) & N >= 4 <- .broadcast(tell, lot(vase)).
+!start <- .wait(100); !start.

+bid(Lot, _)[source(_)] : .count(bid(Lot, _), 3)
   <- .findall(b(V, B), bid(Lot, V)[source(B)], Bids);
      .max(Bids, b(Best, Winner));
      .broadcast(tell, sold(Lot, Winner, Best));
      .print("result: ", Lot, " sold to ", Winner, " for ", Best).
