// mylib.twice is a project's own internal action, and its class is nowhere here
!go.
+!go <- mylib.twice(21, X); .print(X).
