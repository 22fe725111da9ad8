/* Uses what agents commonly use in their first cycles (rules, arithmetic, strings, lists,
   sub-goals, a perception, an action, a timed wait, failure handling), then prints the line
   rason_bridge.cds waits for. */
limit(3).
twice(X, Y) :- Y = X * 2.

!warm_up.

+!warm_up : limit(L) & twice(L, T)
<- .my_name(Me); .concat("agent ", Me, Text); .length(Text, N);
   .findall(I, .member(I, [1, 2, 3]), Is); .nth(0, Is, First); .sort([c, a, b], Sorted);
   rason.time_ms(T0); .wait(10);
   !count(0, T + N + First);
   !!act;
   .wait({+seen(_)[source(percept)]}, 2000, _);
   !fails;
   .print("cds warm-up done ", Me, " ", Sorted, " ", math.sqrt(T0) > 0).

+!count(I, N) : I < N <- !count(I + 1, N).
+!count(_, _).

+!act <- move(1, "ahead").
-!act.

+!fails <- .fail.
-!fails <- -+failed(yes).
