/* The dispatcher of the directory facilitator tests: watches who offers "delivery" and,
   on the test's command cmd(Id, tender(Parcel)), finds the couriers in the directory,
   calls them for proposals and gives the parcel to the cheapest. The tender plans are
   in tender.asl, next to this file. */

{ include("tender.asl") }

!watch.
+!watch <- .df_subscribe("delivery").

+provider(A, S)[source(df)] <- .print("provider + ", A, " ", S).
-provider(A, S)[source(df)] <- .print("provider - ", A, " ", S).

+cmd(Id, C) <- !run(Id, C).
+!run(Id, tender(Parcel)) <- !tender(Id, Parcel).
+!run(Id, search) <- .df_search("delivery", L); .sort(L, S); .print(Id, " found ", S).
-!run(Id, _)[error(E), error_msg(M)] <- .print(Id, " failed ", E, ": ", M).
