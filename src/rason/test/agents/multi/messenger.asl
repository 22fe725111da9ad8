/* A test agent driven by the rostests: each new percept cmd(Id, C) runs command C,
   and every outcome is printed, so the test reads what happened on rosout.
   The same program runs in every process of the multi-robot tests. */

/* Initial beliefs and rules */

// secret/1 comes from the .mas2j, so each agent answers askOne with its own

/* Plans */

// commands from the test, one goal each so a failure has a -! plan
+cmd(Id, C) <- !run(Id, C).

+!run(Id, send(To, P, C)) <- .send(To, P, C); .print(Id, " sent").
// a variable matches literals of the default namespace only: NS::C takes the others (inv::item(1))
+!run(Id, send(To, P, NS::C)) <- .send(To, P, NS::C); .print(Id, " sent").
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
// a namespaced query: ask_ns(bob, inv, item) asks bob askOne inv::item(_)
+!run(Id, ask_ns(To, NS, F)) <- NS::Q =.. [NS, F, [_], []]; .send(To, askOne, NS::Q, AN::A); .print(Id, " answer ", AN::A).
// percepts are ground: believes_any(alarm) asks whether some alarm(_) is believed
+!run(Id, believes_any(F)) : Q =.. [F, [_], []] & Q <- .print(Id, " believes ", Q).
+!run(Id, believes_any(F)) <- .print(Id, " believes no ", F).
+!run(Id, create(N, Src)) <- .create_agent(N, Src); .print(Id, " created ", N).
+!run(Id, kill(N)) <- .kill_agent(N); .print(Id, " killed ", N).

-!run(Id, _)[error(E), error_msg(M)] <- .print(Id, " failed ", E, ": ", M).

// what other agents tell, untell and ask
+hello(X)[source(S)] <- .print("told hello(", X, ") by ", S).
-hello(X)[source(S)] <- .print("untold hello(", X, ") by ", S).
+!greet(X)[source(S)] <- .print("asked to greet ", X, " by ", S).
// namespaced content: inv::item and ::item (the default namespace) are different beliefs
+inv::item(X)[source(S)] <- .print("told inv::item(", X, ") by ", S).
+item(X)[source(S)] <- .print("told ::item(", X, ") by ", S).
// a signal is an event only: nothing is believed
+alarm(X)[source(S)] <- .print("signalled alarm(", X, ") by ", S).
+herald::news(X)[source(S)] <- .print("herald::news ", X, " from ", S).
+bulletin(X)[source(S)] <- .print("bulletin ", X, " from ", S).
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
