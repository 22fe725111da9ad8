// Works a while, notes it is done and stops the MAS in the same cycle: the state it ends in
// (finished, no intention) exists only after its last cycle.
!work.

+!work <- .wait(1500); +finished; .stopMAS.
