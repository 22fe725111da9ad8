/* Watches the directory from a robot that joins late: it hears of every courier already
   registered elsewhere. On the test's commands it lists the couriers the directory finds
   (cmd(Id, search)) and those it was told of (cmd(Id, providers)). */

!watch.
+!watch <- .df_subscribe("delivery").

+provider(A, S)[source(df)] <- .print("provider + ", A, " ", S).
-provider(A, S)[source(df)] <- .print("provider - ", A, " ", S).

+cmd(Id, search) <- .df_search("delivery", L); .sort(L, S); .print(Id, " found ", S).
+cmd(Id, providers) <- .findall(A, provider(A, _)[source(df)], L); .sort(L, S); .print(Id, " told ", S).
