/* The Listing 5.4 agent's perception plans without their .print (node CPU per printed line:
   this agent's CPU per message against bench.asl's is what its ten .print lines cost). The
   burst's literals become beliefs and events and a plan runs for each, as in bench.asl. */

{ include("quiet.asl") }

+perception1(_) <- true.
+perception2(_) <- true.
+perception3(_) <- true.
+perception4(_) <- true.
+perception5(_) <- true.
+perception6(_) <- true.
+perception7(_) <- true.
+perception8(_) <- true.
+perception9(_) <- true.
+perception10(_) <- true.
