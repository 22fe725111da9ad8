// Variables Jason renames print as Jason prints them (shortUnnamedVars: _12, not _12Count).
!show.

+!show
    <- .relevant_plans({+!named(_)}, [Plan|_]);
       Plan = {@_ +!Trigger : _ <- Body};
       .print("trigger ", Trigger, ", body ", Body);
       .stopMAS.

+!named(Count) <- .print(Count).
