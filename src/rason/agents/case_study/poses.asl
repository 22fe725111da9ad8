// Planar poses for the recovery plans (issue 15): pose(X, Y, Yaw), metres and radians,
// counter-clockwise (REP 103), as the pos/3, cmd_pos/3 and located/4 perceptions give them.

// compose(A, B, C): C is pose B, given in the frame of pose A, in A's own frame of reference
// (A (+) B). E.g. compose(Start, pose(1, 0, 0), Goal): the point 1 m ahead of Start.
compose(pose(X1, Y1, T1), pose(X2, Y2, T2), pose(X, Y, T))
    :- X = X1 + X2 * math.cos(T1) - Y2 * math.sin(T1)
     & Y = Y1 + X2 * math.sin(T1) + Y2 * math.cos(T1)
     & T = T1 + T2.

// inverse(A, B): the pose B such that compose(A, B) is the origin.
inverse(pose(X, Y, T), pose(IX, IY, -T))
    :- IX = 0 - X * math.cos(T) - Y * math.sin(T)
     & IY = X * math.sin(T) - Y * math.cos(T).

// relative(A, B, R): where pose B is seen from pose A (A^-1 (+) B).
relative(A, B, R) :- inverse(A, IA) & compose(IA, B, R).

distance(pose(X1, Y1, _), pose(X2, Y2, _), D)
    :- D = math.sqrt((X2 - X1) * (X2 - X1) + (Y2 - Y1) * (Y2 - Y1)).

// signOf(V, S): S is 1 when V >= 0, -1 when V < 0 (which side of a robot a point lies on:
// ahead or behind from its forward offset, left or right from its lateral one).
signOf(V, 1) :- V >= 0.
signOf(V, -1) :- V < 0.
