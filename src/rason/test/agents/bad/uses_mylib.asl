// mylib.twice is the project's own internal action: without its class the agent cannot be made
!go.
+!go <- mylib.twice(21, X); .print(X).
