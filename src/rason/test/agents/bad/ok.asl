// A program that works: the projects in this folder fail for other reasons.
!started.
+!started <- .print("started").
