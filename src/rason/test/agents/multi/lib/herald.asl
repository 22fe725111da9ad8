/* A module (herald.asl includes it into the namespace herald): broadcasts from a plan of the
   module. As Jason reads a module, ::news/1 is the module's (herald::news) and bulletin/1 is
   the default namespace's: the receivers get exactly that, on this robot and the others. */
+!announce(X) <- .broadcast(tell, ::news(X)); .broadcast(tell, bulletin(X)).
