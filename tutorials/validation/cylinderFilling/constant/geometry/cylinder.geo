// The paper's filling test (section 2, Fig. 2; no drawing or dimensions given): metal enters a
// cylinder at 1 m/s. Our assumption: a cylinder of inner radius 25 mm and height 120 mm, open at
// the top, with its axis on z and its floor at z = 0.
SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 0, 0.12, 0.025};

// The mold wall is every face but the open top (found by where it lies, tolerance 0.1 mm).
eps = 1e-4;
top() = Surface In BoundingBox{-0.03, -0.03, 0.12 - eps, 0.03, 0.03, 0.12 + eps};
wall() = Surface{:};
wall() -= top();
Physical Surface("moldWall") = wall();
Physical Volume("cavity") = {1};
