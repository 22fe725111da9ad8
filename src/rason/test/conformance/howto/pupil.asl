/* The pupil asks the teacher how to greet (askHow) and greets with the plan it got; it
   bows as soon as someone has taught it how (the teacher's tellHow). */
!start.
!practice.
+!start : .all_names(L) & .member(teacher, L)
   <- .send(teacher, askHow, {+!greet(_)}, Plans); .length(Plans, N); .print("result: learned ", N, " plan");
      .add_plan(Plans); !greet(everyone).
+!start <- .wait(100); !start.

+!practice : .relevant_plans({+!bow}, [_|_]) <- !bow.
+!practice <- .wait(100); !practice.
