// SPHERIC Test 2 (Kleefsman et al. 2005, J. Comput. Phys. 206:363, doi:10.1016/j.jcp.2004.12.007):
// a 3.22 m x 1 m x 1 m tank, the water column 1.228 m x 1 m x 0.55 m at the far end
// (x > 1.992 m), and a box obstacle 0.161 m x 0.403 m x 0.161 m on the floor between
// x = 0.6635 and 0.8245 m, centred across the tank. Origin at the tank's floor corner, z up.
// The tank is left open at the top (the water does not reach z = 1 m in the first second).
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 3.22, 1, 1};
Box(2) = {0.6635, 0.2985, 0, 0.161, 0.403, 0.161};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };

// Faces of the cavity, found by where they lie (tolerance 1 mm).
eps = 1e-3;
top() = Surface In BoundingBox{-eps, -eps, 1 - eps, 3.22 + eps, 1 + eps, 1 + eps};
obstacle() = Surface In BoundingBox{0.6635 - eps, 0.2985 - eps, -eps, 0.8245 + eps, 0.7015 + eps, 0.161 + eps};
all() = Surface{:};
tank() = all();
tank() -= top();
tank() -= obstacle();
Physical Surface("tankWall") = tank();
Physical Surface("obstacle") = obstacle();
Physical Volume("cavity") = {3};
