// The jet's box: the jet falls 30 mm onto the floor, its splashes reach every side.
// A closed box 0.1 m wide and 0.1 m high in the plane z = 0: its four sides are the walls
// (Physical Curve "wall"); the plane surface is the cavity they go around.
w = 0.1;
h = 0.1;
Point(1) = {0, 0, 0};
Point(2) = {w, 0, 0};
Point(3) = {w, h, 0};
Point(4) = {0, h, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("wall") = {1, 2, 3, 4};
Physical Surface("inside") = {1};
