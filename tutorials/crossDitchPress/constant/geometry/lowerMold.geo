// Lower mold of the crossDitchPress tutorial (paper section 5.2, Figs. 15-16): an iron block
// with a square pocket that the casting fills, and a cross-shaped ditch in the middle of the
// pocket's floor. The paper gives no dimensions: these are our assumption (see ../../README.md),
// chosen so that the pressed casting (1.5 mm plate + the ditch) holds the paper's metal,
// 232,570 particles of 1.012e-6 kg at 2398.8 kg/m^3. Every length is a whole multiple of the
// particle spacing dx = 0.75 mm, so the flat walls lie half-way between lattice planes.
// Coordinates: pocket floor at z = 0, the mold's axis on z; metres.
SetFactory("OpenCASCADE");

pocket = 139.5e-3;       // side of the square pocket (186 dx)
pocketDepth = 20.25e-3;  // from the pocket floor to the mold's top face (27 dx)
ditchWidth = 24e-3;      // width of each arm of the cross (32 dx); the arms span the pocket
ditchDepth = 11.25e-3;   // depth of the ditch below the pocket floor (15 dx)
wall = 15e-3;            // iron around the pocket and under the ditch (20 dx)

outer = pocket + 2 * wall;
Box(1) = {-outer / 2, -outer / 2, -ditchDepth - wall, outer, outer, wall + ditchDepth + pocketDepth};
Box(2) = {-pocket / 2, -pocket / 2, 0, pocket, pocket, pocketDepth};
Box(3) = {-pocket / 2, -ditchWidth / 2, -ditchDepth, pocket, ditchWidth, ditchDepth};
Box(4) = {-ditchWidth / 2, -pocket / 2, -ditchDepth, ditchWidth, pocket, ditchDepth};
BooleanDifference(5) = { Volume{1}; Delete; }{ Volume{2, 3, 4}; Delete; };

Physical Volume("lowerMold") = {5};

// The faces the metal meets (the pocket and the ditch), for a mold particleized at graded spacing
// (grading's fineSurfaces in system/particleizeMoldDict; ./setResolution DX graded).
eps = 1e-6;
Physical Surface("lowerMoldCavity") = Surface In BoundingBox{-pocket / 2 - eps, -pocket / 2 - eps, -ditchDepth - eps, pocket / 2 + eps, pocket / 2 + eps, pocketDepth + eps};
