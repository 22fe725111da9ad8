// Does not parse: the plan body never ends.
+!started <- .print("never"
