/* A bidder: bids its limit for any lot, and says whether it won. */
+lot(Lot)[source(A)] : limit(V) <- .send(A, tell, bid(Lot, V)).
+sold(Lot, W, P)[source(_)] : .my_name(W) <- .print("result: I won ", Lot, " for ", P).
+sold(Lot, W, _)[source(_)] : .my_name(Me) & Me \== W <- .print("result: I lost ", Lot, " to ", W).
