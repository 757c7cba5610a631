// A 0.1 m x 0.1 m x 0.1 m tank open at the top: its floor and four sides are the wall.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 0.1, 0.1, 0.1};
Physical Surface("tankWall") = {1, 2, 3, 4, 5};   // x-, x+, y-, y+ sides and the floor
Physical Volume("cavity") = {1};
