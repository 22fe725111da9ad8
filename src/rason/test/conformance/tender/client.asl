/* A contract net over the directory facilitator: the client subscribes to "haul", and once
   three porters provide it, calls for offers, awards the cheapest and rejects the others. */
!start.
+!start <- .df_subscribe("haul").

+provider(_, "haul")[source(df)] : .count(provider(_, "haul")[source(df)], 3) & not called
   <- +called; .df_search("haul", Porters); .send(Porters, tell, cfp(crate)).

+offer(Job, _)[source(_)] : .count(offer(Job, _), 3)
   <- .findall(o(P, A), offer(Job, P)[source(A)], Offers);
      .min(Offers, o(Price, Winner));
      .findall(A, offer(Job, _)[source(A)] & A \== Winner, Losers);
      .send(Winner, achieve, haul(Job, Price));
      .send(Losers, tell, rejected(Job));
      .print("result: awarded ", Job, " to ", Winner, " at ", Price, " among 3 offers").
