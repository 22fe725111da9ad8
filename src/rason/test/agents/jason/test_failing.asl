// Jason's agent-testing framework with a test that fails on purpose: the MAS ends with
// Jason's summary of one failed test and exit status 1.
{ include("$jasonJar/test/jason/inc/tester_agent.asl") }

@[test]
+!test_that_passes
    <- !assert_equals(6, 2 * 3).

@[test]
+!test_that_fails_on_purpose
    <- !assert_equals(7, 2 * 3).
