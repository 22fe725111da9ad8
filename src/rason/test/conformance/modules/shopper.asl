/* The shopper adds to each kind of fruit through its namespace and reads the totals back
   (the second apples once the first is counted: the answers say what the keeper holds). */
!start.
+!start : .all_names(L) & .member(keeper, L)
   <- .send(keeper, achieve, apples::add(3)); .send(keeper, achieve, pears::add(5)).
+!start <- .wait(100); !start.

+apples::total(3)[source(K)] <- .send(K, achieve, apples::add(4)).
+apples::total(7)[source(K)] <- .print("result: ", K, " has 7 apples").
+pears::total(T)[source(K)] <- .print("result: ", K, " has ", T, " pears").
+total(T)[source(K)] <- .print("result: unexpected total ", T, " in the default namespace").
