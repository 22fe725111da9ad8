// Included by faulty.asl and helper.asl.
// IMPROVED: a failure plan sends through sendSafely, which cannot fail: Jason runs a failure
// plan that fails again when its goal is the first of the intention (e.g. a message to a
// robot that left makes .send fail), over and over, and the plan's later steps never run.
+!sendSafely(R, Performative, Content) <- .send(R, Performative, Content).
-!sendSafely(R, Performative, Content) <- .print("could not send ", Content, " to ", R).
