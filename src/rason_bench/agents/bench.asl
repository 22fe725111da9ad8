/* Thesis Listing 5.4, driven by the benchmark harness (rason_bench). The thesis ran
   the loop once from !start with a fixed 3700 iterations and its modified .time;
   here the harness starts each run with a percept, chooses the iterations, and
   rason.time_ms is the millisecond clock. The perception plans are the thesis's,
   for the literals its synthesizer-like node publishes (perceptionK(Seq)). */

/* Initial beliefs and rules */
value(0).

/* Plans */

// thesis Listing 5.4: the loop whose time per iteration is the "reasoning cycle time"
+go_cycle(Me, Run, N)[source(percept)] : .my_name(Me)
<- -+value(0); -+limit(N); -+run(Run); rason.time_ms(X); -+init(X); !goToDestination.

+!goToDestination : value(X) & limit(L) & X < L <- -+value(X+1); !!goToDestination.
+!goToDestination : value(X) & rason.time_ms(T) & init(I) & run(R) <- cycle(R, X, T - I).

// action round trip: act -> decomposer -> OK -> intention resumed
+go_ping(Me, Run, N)[source(percept)] : .my_name(Me) <- !ping(Run, 0, N).
+!ping(Run, I, N) : I < N
<- rason.time_ms(T0); ping(I); rason.time_ms(T1); rtt(Run, I, T1 - T0); !ping(Run, I + 1, N).
+!ping(_, _, _).

// perception published -> belief event (the time is read when the plan is chosen)
+stamp(Run, Seq, T)[source(percept)] : rason.time_ms(Now) <- seen(Run, Seq, Now - T).

// reaction: a trigger percept -> an action at once (the harness times publish -> action)
+trigger(Run, Seq, T)[source(percept)] <- react(Run, Seq, T).

// busy intentions: N loops, each doing a step of work per turn while go_spin(_, Run, _) is
// perceived (the harness's next control percept replaces it), then reporting its turns
+go_spin(Me, Run, N)[source(percept)] : .my_name(Me)
<- for (.range(I, 1, N)) { !!spin(Run, I, 0) }; spinning(Run, N).
+!spin(Run, I, K) : go_spin(_, Run, _)[source(percept)] <- X = (K * 7) mod 13; !!spin(Run, I, K + 1).
+!spin(Run, I, K) <- spun(Run, I, K).

// perception rate limit: every update of the tick source that reaches this agent, timed here
+tick(Run, Seq)[source(percept)] : .my_name(Me) & rason.time_ms(T) <- ticked(Run, Me, Seq, T).

// thesis Listing 5.4: one plan per perception
+perception1(_) <- .print("p1").
+perception2(_) <- .print("p2").
+perception3(_) <- .print("p3").
+perception4(_) <- .print("p4").
+perception5(_) <- .print("p5").
+perception6(_) <- .print("p6").
+perception7(_) <- .print("p7").
+perception8(_) <- .print("p8").
+perception9(_) <- .print("p9").
+perception10(_) <- .print("p10").
