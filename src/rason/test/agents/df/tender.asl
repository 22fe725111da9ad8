/* A tender: every courier in the directory is asked for a price; once all have answered,
   the cheapest is awarded the parcel and the others are declined. */

+!tender(Id, Parcel) <-
    .df_search("delivery", Couriers);
    .length(Couriers, N);
    if (N == 0) { .print(Id, " no courier for ", Parcel) }
    else {
        +tendering(Id, Parcel, N);
        .send(Couriers, achieve, cfp(Parcel))
    }.

+propose(Parcel, _) : tendering(Id, Parcel, N) & .count(propose(Parcel, _), N) <- !close(Id, Parcel).

@close[atomic]
+!close(Id, Parcel) : tendering(Id, Parcel, N) <-
    -tendering(Id, Parcel, N);
    .findall(offer(Price, C), propose(Parcel, Price)[source(C)], Offers);
    .min(Offers, offer(Best, Winner));
    .findall(C, propose(Parcel, _)[source(C)], All);
    .sort(All, Bidders);
    .send(Winner, achieve, award(Parcel));
    for (.member(C, Bidders) & C \== Winner) { .send(C, achieve, decline(Parcel)) };
    .print(Id, " awarded ", Parcel, " to ", Winner, " for ", Best, " among ", Bidders).
+!close(_, _).
