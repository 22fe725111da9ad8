/* The agents of the benchmark's fleet part (rason_bench.fleet), in rason_mas processes that
   talk over ~fleet_channel mqtt. They start by themselves (no harness reaches a robot on a
   host of its own) and print what they measure; times are rason.time_ms, the machine's
   monotonic clock, which the simulated robots (rason.messaging.mqtt.SimulatedFleet) read too. */

// the pinger (a belief peer(P)): once P is present, achieve round trips one after the other,
// ping -> P -> pong, each printed; the second gives P's process a moment to see this one too
+present(P) : peer(P) & not pinging <- +pinging; .wait(1000); !!ping(0).
+!ping(I) : peer(P) <- rason.time_ms(T0); .send(P, achieve, ping(I, T0)).
+!pong(I, T0)[source(P)] : peer(P) <- rason.time_ms(T1); .print("rtt ", I, " ", T1 - T0); !!ping(I + 1).

// every agent answers pings, and the load of the simulated robots
+!ping(I, T0)[source(S)] <- .send(S, achieve, pong(I, T0)).
+!echo(R, I)[source(S)] <- .send(S, achieve, echoed(R, I)).

// every agent reports arrivals and departures, timed
+present(A) <- rason.time_ms(T); .print("present ", A, " ", T).
-present(A) <- rason.time_ms(T); .print("absent ", A, " ", T).
