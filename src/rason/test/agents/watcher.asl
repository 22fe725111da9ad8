/* Plans */

+temp(S, V)[source(percept)] <- .print("+temp ", S, " ", V).
-temp(S, V)[source(percept)] <- .print("-temp ", S, " ", V).
