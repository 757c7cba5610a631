// Upper mold (the press) of the crossDitchPress tutorial: a flat iron punch that fits the lower
// mold's pocket (a sliding fit, no gap) and presses the metal down to a 1.5 mm plate. Its
// dimensions are our assumption (see ../../README.md): 139.5 mm x 139.5 mm x 5.25 mm of iron at
// 7850 kg/m^3 weighs 0.802 kg, the paper's 800 g. It starts with its face flush with the lower
// mold's top, 20.25 mm above the pocket floor; the press stops it 1.5 mm above the floor.
SetFactory("OpenCASCADE");

pocket = 139.5e-3;       // as in lowerMold.geo (186 dx)
thickness = 5.25e-3;     // 7 dx
start = 20.25e-3;        // height of its face above the pocket floor at the start (27 dx)

Box(1) = {-pocket / 2, -pocket / 2, start, pocket, pocket, thickness};

Physical Volume("upperMold") = {1};

// The faces the metal meets (the pressing face, and the sides that slide along the pocket's
// walls), for a mold particleized at graded spacing (grading's fineSurfaces in
// system/particleizeMoldDict; ./setResolution DX graded). The top, to the air, may be coarse.
eps = 1e-6;
x0 = -pocket / 2; x1 = pocket / 2; z0 = start; z1 = start + thickness;
Physical Surface("upperMoldFace") = {
    Surface In BoundingBox{x0 - eps, x0 - eps, z0 - eps, x1 + eps, x1 + eps, z0 + eps},
    Surface In BoundingBox{x0 - eps, x0 - eps, z0 - eps, x0 + eps, x1 + eps, z1 + eps},
    Surface In BoundingBox{x1 - eps, x0 - eps, z0 - eps, x1 + eps, x1 + eps, z1 + eps},
    Surface In BoundingBox{x0 - eps, x0 - eps, z0 - eps, x1 + eps, x0 + eps, z1 + eps},
    Surface In BoundingBox{x0 - eps, x1 - eps, z0 - eps, x1 + eps, x1 + eps, z1 + eps}
};
