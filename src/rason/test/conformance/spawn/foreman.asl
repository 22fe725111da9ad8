/* The foreman makes two hands at run time; once the tally has counted them it lets them go
   and reports who is left. */
!start.
+!start : .all_names(L) & .member(tally, L) <- .create_agent(hand, "hand.asl"); .create_agent(hand, "hand.asl").

+counted(2)[source(tally)]
   <- .df_search("lifting", Hands); .sort(Hands, S);
      for (.member(H, S)) { .kill_agent(H) };
      !report(S).
+!start <- .wait(100); !start.

+!report(Killed) : .all_names(L) & not (.member(H, Killed) & .member(H, L))
   <- .print("result: let go of ", Killed, "; left ", L).
+!report(Killed) <- .wait(50); !report(Killed).
