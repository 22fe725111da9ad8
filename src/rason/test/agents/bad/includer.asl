{ include("no_such_file.asl") }
!start.
+!start <- .print("started").
