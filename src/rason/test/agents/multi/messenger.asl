/* A test agent driven by the rostests: each new percept cmd(Id, C) runs command C,
   and every outcome is printed, so the test reads what happened on rosout.
   The same program runs in every process of the multi-robot tests. */

/* Initial beliefs and rules */

// secret/1 comes from the .mas2j, so each agent answers askOne with its own

/* Plans */

// commands from the test, one goal each so a failure has a -! plan
+cmd(Id, C) <- !run(Id, C).

+!run(Id, send(To, P, C)) <- .send(To, P, C); .print(Id, " sent").
// percepts are ground, so the test names the functor and the query gets a variable: ask(bob, askOne, secret)
+!run(Id, ask(To, P, F)) <- Q =.. [F, [_], []]; .send(To, P, Q, A); .print(Id, " answer ", A).
+!run(Id, ask(To, P, F, Timeout)) <- Q =.. [F, [_], []]; .send(To, P, Q, A, Timeout); .print(Id, " answer ", A).
+!run(Id, broadcast(P, C)) <- .broadcast(P, C); .print(Id, " broadcast").
+!run(Id, names) <- .all_names(L); .print(Id, " names ", L).
+!run(Id, present) <- .findall(A, present(A), L); .sort(L, S); .print(Id, " present ", S).
+!run(Id, desire(G)) : .desire(G) <- .print(Id, " desires ", G).
+!run(Id, desire(G)) <- .print(Id, " does not desire ", G).
+!run(Id, pingpong(To, N)) <- .nano_time(T0); -+pingpong(Id, To, N, N, T0); .send(To, achieve, ping).
+!run(Id, perceive_only(L)) <- rason.perceive_only(L); .print(Id, " perceiving only ", L).
+!run(Id, perceive_all) <- rason.perceive_all; .print(Id, " perceiving all").

-!run(Id, _)[error(E), error_msg(M)] <- .print(Id, " failed ", E, ": ", M).

// what other agents tell, untell and ask
+hello(X)[source(S)] <- .print("told hello(", X, ") by ", S).
-hello(X)[source(S)] <- .print("untold hello(", X, ") by ", S).
+!greet(X)[source(S)] <- .print("asked to greet ", X, " by ", S).
+!linger[source(S)] <- .print("lingering for ", S); .wait(60000); .print("lingered").

// achieve round trips: the other agent answers ping with pong; N rounds, then the mean
+!ping[source(S)] <- .send(S, achieve, pong).
+!pong[source(S)] : pingpong(Id, To, Left, N, T0) & Left > 1 <- -+pingpong(Id, To, Left - 1, N, T0); .send(To, achieve, ping).
+!pong[source(S)] : pingpong(Id, To, 1, N, T0) <- .nano_time(T1); -pingpong(Id, To, 1, N, T0);
    .print(Id, " round trip ", (T1 - T0) / N / 1000, " us").

// presence, as the bridge keeps it
+present(A) <- .print("present ", A).
-present(A) <- .print("absent ", A).

// an askOne answered only after a minute, so a test can take the asked agent away meanwhile
+!kqml_received(S, askOne, slow(_), M) <- .print("slow answer for ", S); .wait(60000); .send(S, tell, slow(late), M).
