// Martin & Moyce (1952) in 2D, as tests/unit/sph/DamBreak2DTest.cpp: a tank 5a long and 3a
// high (a = 0.1 m), open at the top, in the plane z = 0. Its floor and sides are the walls
// (Physical Curve "tankWall"); the plane surface is the cavity they go around.
a = 0.1;
Point(1) = {0, 0, 0};
Point(2) = {5 * a, 0, 0};
Point(3) = {5 * a, 3 * a, 0};
Point(4) = {0, 3 * a, 0};
Line(1) = {1, 2};   // floor
Line(2) = {2, 3};   // far wall
Line(3) = {3, 4};   // open top
Line(4) = {4, 1};   // wall behind the column
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("tankWall") = {1, 2, 4};
Physical Surface("tank") = {1};
