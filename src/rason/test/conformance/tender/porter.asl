/* A porter: registers for "haul", answers a call for offers with its rate, hauls if awarded. */
!start.
+!start <- .df_register("haul").

+cfp(Job)[source(C)] : rate(R) <- .send(C, tell, offer(Job, R)).
+!haul(Job, Price)[source(C)] <- .my_name(Me); .print("result: ", Me, " hauls ", Job, " for ", Price).
+rejected(Job)[source(C)] <- .my_name(Me); .print("result: ", Me, " not chosen for ", Job).
