/* Plans */

// the test publishes the percept go once it listens to rosout
+go <- !!try_move; !!try_curve; !!try_jam; !!try_spin.

// the reason as an annotation of the failure event
+!try_move <- move(1).
-!try_move[no_progress] <- .print("move failed: no_progress matched").
-!try_move[R|Rest] <- .print("move failed otherwise ", [R|Rest]).

// the reason found with .member, as the thesis's Appendix A does
+!try_curve <- curve(1).
-!try_curve[R|Rest] : .member(bad_move, [R|Rest]) <- .print("curve failed: member bad_move").
-!try_curve[R|Rest] <- .print("curve failed otherwise ", [R|Rest]).

// a reason that is not a Jason atom is kept as text
+!try_jam <- jam(1).
-!try_jam[failure_reason(T)] <- .print("jam failed: ", T).
-!try_jam[R|Rest] <- .print("jam failed otherwise ", [R|Rest]).

+!try_spin <- spin(-0.5); .print("spin ok").
-!try_spin[R|Rest] <- .print("spin failed ", [R|Rest]).
