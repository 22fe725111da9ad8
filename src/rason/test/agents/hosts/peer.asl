/* One agent of the robots-on-hosts acceptance test (src/rason/test/test_hosts_fleet.py).

   It exchanges numbered messages with peer(P), its counterpart on the other robot, and prints
   every step, so the test checks delivery, order and presence from the output alone.
   Message N is a tell when N mod 3 is 0, an achieve when 1, an askOne when 2. In the burst a
   sender sends one message at a time, in the stream one every period, so the order of its
   numbers is the order of its sends.
   Times are the wall clock in ms (system.time): every host shares the machine's clock. */

// presence of the peer; its first arrival starts the exchange
+present(P) : peer(P) <- .print("present ", P, " ", system.time); !!start.
-present(P) : peer(P) <- .print("absent ", P, " ", system.time).

// burst(Count) messages as fast as they go, then one every stream_period(Ms) until the test
// perceives stop
+!start : started <- true.
+!start : burst(Count)
   <- +started;
      for (.range(N, 1, Count)) { !send_one(N) };
      .print("burst done ", Count);
      !stream(Count + 1).

+!stream(N) : stopped <- .print("stream ended ", N - 1).
// each in an intention of its own: a send waits for its receipt (a partition holds it until the
// heal), and the stream goes on meanwhile; the period keeps the sends in the order of their numbers
+!stream(N) : stream_period(Ms) <- !!send_one(N); .wait(Ms); !stream(N + 1).

+stop <- +stopped.

+!send_one(N) : peer(P) & N mod 3 == 0
   <- .print("send ", N, " tell ", system.time); .send(P, tell, msg(N)); .print("sent ", N).
+!send_one(N) : peer(P) & N mod 3 == 1
   <- .print("send ", N, " achieve ", system.time); .send(P, achieve, job(N)); .print("sent ", N).
+!send_one(N) : peer(P) & ask_wait(Ms)
   <- .print("send ", N, " ask ", system.time); .send(P, askOne, val(N, _), A, Ms); .print("answer ", N, " ", A).
-!send_one(N)[error(E)] <- .print("failed ", N, " ", E).

// Receiving: these plans take every message of the peer as it leaves the mailbox (Jason turns
// each into a +!kqml_received event, in mailbox order, and runs intentions round robin), so the
// first step of each prints in the order the messages reached Jason.
+!kqml_received(S, tell, msg(N), _) <- .print("got ", S, " ", N, " tell").
+!kqml_received(S, achieve, job(N), _) <- .print("got ", S, " ", N, " achieve").
+!kqml_received(S, askOne, val(N, _), Id) <- .print("got ", S, " ", N, " ask"); .send(S, tell, val(N, N), Id).
-!kqml_received(S, askOne, val(N, _), _)[error(E)] <- .print("answer ", N, " to ", S, " failed ", E).
