// The conical mold of the paper's first result (§5.1, Fig. 12), open at the top. The paper
// gives no dimensions; ours hold its 95,625 particles of 8.10e-6 kg (0.323 litre of melt at
// 2398.8 kg/m^3) up to 68.84 mm: a frustum of revolution about z, radius 25 mm at the floor
// (z = 0) and 55 mm at the rim (z = 80 mm), its side 20.6 degrees off the vertical.
SetFactory("OpenCASCADE");
Cone(1) = {0, 0, 0, 0, 0, 0.08, 0.025, 0.055};
// The mold wall is every face but the open top (found by where it lies, tolerance 0.1 mm).
eps = 1e-4;
top() = Surface In BoundingBox{-0.06, -0.06, 0.08 - eps, 0.06, 0.06, 0.08 + eps};
wall() = Surface{:};
wall() -= top();
Physical Surface("moldWall") = wall();
Physical Volume("cavity") = {1};
