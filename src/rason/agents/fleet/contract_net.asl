// Choosing a robot for a task by contract net (FIPA's call for proposals), for a program
// that every robot of a fleet runs: the same agent is a caller when it needs a task done and
// a contractor when another calls. Include it; docs/guides/fleet-program.md explains it.
//
// The program provides
//   bid(Task, Caller, Bid)        a rule: what doing Task for Caller would cost me (lower is
//                                 better); no solution means I do not bid
//   +!contracted(Task, Contractor)  the caller's plan once Contractor has taken Task
//   +!uncontracted(Task, Reason)    the caller's plan once nobody (more) can take it
//   +!carryOut(Task, Caller)        the contractor's plan for the task; when it fails the
//                                   caller is told and awards the next bidder
// and calls !contract(Service, Task) (ask every agent registered for Service in the
// directory), !contractFailed(Task) (the contractor's work did not do: next bidder) and
// !contractDone(Task) (release the contractor).
//
// A bid binds nothing: an award is the commitment, and a contractor already committed
// declines it, so a robot never works for two callers at once and a stale bid costs the
// caller one round trip. The caller keeps the other bids, ranked, and awards the next when
// its contractor declines, does not answer within awardTimeout, fails, or leaves (its
// present/1 drops: a robot whose process died; one only out of reach is told the award is
// revoked, which reaches it when it is back).

bidWindow(1000).        // ms the caller waits for every bid
awardTimeout(3000).     // ms a contractor has to take or decline an award
callerGrace(15000).     // ms a contractor stays committed to a caller out of reach

answeredAll(Id, N) :- .count(propose(Id, _), P) & .count(refuse(Id), R) & P + R >= N.

// A program that believes firstAnswerWins (fleet_robot_mission_broadcast.mas2j) chooses as
// the thesis's broadcast did: the first robot to offer, whatever its bid, and nobody else; when
// it does not do, the caller calls again. The fleet campaign compares the two in the same runs.
bidsAwaited(Id, N) :- firstAnswerWins & (propose(Id, _) | answeredAll(Id, N)).
bidsAwaited(Id, N) :- not firstAnswerWins & answeredAll(Id, N).
ranked([First | _], [First]) :- firstAnswerWins.
ranked([], []) :- firstAnswerWins.
ranked(Offers, Ranked) :- not firstAnswerWins & .sort(Offers, Ranked).

/* The caller */

+!contract(Service, Task)
<- .my_name(Me);
   .df_search(Service, Found);
   .delete(Me, Found, Candidates);
   !callForProposals(Service, Task, Candidates).

+!callForProposals(Service, Task, [])
<- !uncontracted(Task, no_candidates(Service)).
+!callForProposals(Service, Task, Candidates) : bidWindow(W)
<- !newContractId(Id);
   +collecting(Id);
   .send(Candidates, achieve, callForBids(Id, Task));
   .length(Candidates, N);
   .wait(bidsAwaited(Id, N), W, _);
   -collecting(Id);
   .findall(offer(Bid, P), propose(Id, Bid)[source(P)], Offers);
   .abolish(propose(Id, _));
   .abolish(refuse(Id));
   ?ranked(Offers, Ranked);
   .print("contract ", Id, " for ", Task, ": bids ", Ranked, " from ", N, " called");
   +contract(Id, Task, Ranked);
   !awardNext(Id).

+!newContractId(contract(Me, N1)) : .my_name(Me) & contractsCalled(N)
<- N1 = N + 1; -+contractsCalled(N1).
+!newContractId(contract(Me, 1)) : .my_name(Me) <- +contractsCalled(1).

// A bid after the window closed (a slow or lossy link) is no offer.
+propose(Id, _)[source(P)] : not collecting(Id) <- .abolish(propose(Id, _)[source(P)]).
+refuse(Id)[source(P)] : not collecting(Id) <- .abolish(refuse(Id)[source(P)]).

+!awardNext(Id) : contract(Id, Task, [offer(Bid, P) | Rest]) & awardTimeout(T)
<- -contract(Id, Task, _);
   +contract(Id, Task, Rest);
   +awarded(Id, Task, P);
   .print("awarding ", Task, " to ", P, " (bid ", Bid, ")");
   !sendOrFail(P, achieve, award(Id, Task));
   .wait(accepted(Id)[source(P)] | declined(Id)[source(P)] | not awarded(Id, Task, P), T, _);
   !awardAnswered(Id, Task, P).
+!awardNext(Id) : contract(Id, Task, [])
<- -contract(Id, Task, _);
   !uncontracted(Task, no_contractor_left).

-!awardNext(Id) : awarded(Id, Task, P)
<- .print("could not award ", Task, " to ", P);
   !lose(Id, Task, P).

+!awardAnswered(Id, Task, P) : accepted(Id)[source(P)] & awarded(Id, Task, P)
<- -accepted(Id)[source(P)];
   .print(P, " took ", Task);
   !!contracted(Task, P).
+!awardAnswered(Id, Task, P) : awarded(Id, Task, P)
<- .abolish(declined(Id)[source(P)]);
   .print(P, " did not take ", Task);
   !lose(Id, Task, P).
+!awardAnswered(_, _, _) <- true.     // lost meanwhile (left, failed): already handled

// The contractor is lost to this contract: stop what I do with it, award the next. The revoke
// is not waited for: to a robot out of reach it is delivered only when it is back.
+!lose(Id, Task, P)
<- -awarded(Id, Task, P);
   .drop_desire(contracted(Task, P));
   !!sendOrFail(P, achieve, revoke(Id));
   !awardNext(Id).

+!contractFailed(Task) : awarded(Id, Task, P) <- !lose(Id, Task, P).
+!contractFailed(Task) <- true.

+!contractDone(Task) : awarded(Id, Task, P)
<- -awarded(Id, Task, P);
   -contract(Id, Task, _);
   !sendOrFail(P, achieve, release(Id)).
+!contractDone(_) <- true.

+failed(Id)[source(P)] : awarded(Id, Task, P)
<- -failed(Id)[source(P)];
   .print(P, " failed at ", Task);
   !lose(Id, Task, P).
+failed(Id)[source(P)] <- -failed(Id)[source(P)].

-present(P) : awarded(Id, Task, P)
<- .print(P, " left while working on ", Task);
   !lose(Id, Task, P).

// A message that cannot be sent (the receiver left) must not end the plan sending it.
+!sendOrFail(R, Performative, Content) <- .send(R, Performative, Content).
-!sendOrFail(R, Performative, Content) <- .print("could not send ", Content, " to ", R).

/* The contractor */

+!callForBids(Id, Task)[source(C)] : not committed(_, _, _) & bid(Task, C, Bid)
<- .send(C, tell, propose(Id, Bid)).
+!callForBids(Id, _)[source(C)] <- .send(C, tell, refuse(Id)).

+!award(Id, Task)[source(C)] : not committed(_, _, _)
<- +committed(Id, Task, C);
   .send(C, tell, accepted(Id));
   !!work(Id, Task, C).
+!award(Id, _)[source(C)] <- .send(C, tell, declined(Id)).

+!work(Id, Task, C)
<- !carryOut(Task, C).
-!work(Id, Task, C) : committed(Id, Task, C)
<- -committed(Id, Task, C);
   !sendOrFail(C, tell, failed(Id)).
-!work(_, _, _) <- true.

+!revoke(Id)[source(C)] : committed(Id, Task, C)
<- .print(C, " revoked ", Task);
   -committed(Id, Task, C);
   .drop_desire(work(Id, Task, C));
   .drop_desire(carryOut(Task, C)).
+!revoke(_) <- true.

+!release(Id)[source(C)] : committed(Id, Task, C)
<- -committed(Id, Task, C);
   .drop_desire(work(Id, Task, C)).
+!release(_) <- true.

// The caller out of reach: it may be behind a broken link, so I stay committed for
// callerGrace; if it is not back by then it left, and I am free again.
-present(C) : committed(Id, Task, C) <- !awaitCaller(Id, Task, C).
+!awaitCaller(Id, Task, C) : callerGrace(G) <- .wait(present(C), G).
-!awaitCaller(Id, Task, C) : committed(Id, Task, C) & not present(C)
<- .print(C, " left; ", Task, " is dropped");
   -committed(Id, Task, C);
   .drop_desire(work(Id, Task, C));
   .drop_desire(carryOut(Task, C)).
-!awaitCaller(_, _, _) <- true.
