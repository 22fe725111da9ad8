// Tests of the case study's pose rules (../poses.asl), written with
// Jason's agent-testing framework: the test_manager of the .mas2j gathers the results.
{ include("$jasonJar/test/jason/inc/tester_agent.asl") }
{ include("poses.asl") }

@[test]
+!test_compose_straight_ahead
    <- ?compose(pose(1, 2, 0), pose(1, 0, 0), pose(X, Y, T));
       !assert_equals(2, X);
       !assert_equals(2, Y);
       !assert_equals(0, T).

@[test]
+!test_compose_turned_left
    <- ?compose(pose(0, 0, math.pi / 2), pose(1, 0, 0), pose(X, Y, T));
       !assert_equals(0, X, 0.000001);
       !assert_equals(1, Y, 0.000001);
       !assert_equals(math.pi / 2, T, 0.000001).

@[test]
+!test_a_pose_seen_from_itself_is_the_origin
    <- ?relative(pose(3, -1, 0.7), pose(3, -1, 0.7), pose(X, Y, T));
       !assert_equals(0, X, 0.000001);
       !assert_equals(0, Y, 0.000001);
       !assert_equals(0, T, 0.000001).

@[test]
+!test_distance_ignores_the_heading
    <- ?distance(pose(0, 0, 1), pose(3, 4, -2), D);
       !assert_equals(5, D, 0.000001).

@[test]
+!test_sign_of_counts_zero_as_positive
    <- ?signOf(0.3, Left);
       !assert_equals(1, Left);
       ?signOf(0, Ahead);
       !assert_equals(1, Ahead);
       ?signOf(-0.3, Right);
       !assert_equals(-1, Right).
