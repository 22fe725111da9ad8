/* The messenger, with a module: herald.asl's plans in the namespace herald. */
{ include("messenger.asl") }
{ include("lib/herald.asl", herald) }

+!run(Id, herald(X)) <- !herald::announce(X); .print(Id, " heralded").
