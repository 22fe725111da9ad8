/* The tally watches the directory for hands and tells the foreman when there are two. */
!start.
+!start <- .df_subscribe("lifting").
+provider(_, "lifting")[source(df)] : .count(provider(_, "lifting")[source(df)], 2) & not told
   <- +told; .findall(H, provider(H, "lifting"), Hs); .sort(Hs, S); .print("result: counted ", S); .send(foreman, tell, counted(2)).
-provider(H, "lifting")[source(df)] <- .print("result: ", H, " is gone").
