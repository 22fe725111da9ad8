/* A hand made at run time: offers "lifting" in the directory. */
!start.
+!start <- .df_register("lifting").
