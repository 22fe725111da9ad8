/* A call for proposals written for one MAS: give the bidders a second to register in the
   directory, then ask every one of them. Split over robots, it runs unchanged behind the
   start barrier (~await_agents). */

!call_for_proposals.

+!call_for_proposals <-
    .wait(1000);
    .df_search("bidding", Found);
    .sort(Found, Bidders);
    .length(Bidders, N);
    .print("found ", N, " bidders: ", Bidders);
    .send(Bidders, achieve, cfp(job)).

+propose(job, Price)[source(B)] <- .print("proposal of ", B, ": ", Price).
