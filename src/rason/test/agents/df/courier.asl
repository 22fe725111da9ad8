/* A courier of the directory facilitator tests: offers the "delivery" service and bids
   its cost (a belief from the .mas2j) when a dispatcher calls for proposals. The bidding
   plans come from lib/ (the project's aslSourcePath). */

{ include("bidding.asl") }

!offer.
+!offer <- .df_register("delivery"); .print("offering delivery").
