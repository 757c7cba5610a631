// The die of the gradedDie validation case: an iron block 100 x 100 x 60 mm with a pocket
// 60 x 60 x 20 mm in its top, which the casting fills. Its lower corner lies off the lattices of
// 4 and 8 mm, as a user's die would. Coordinates in metres; the pocket's floor at z = -8.7 mm.
SetFactory("OpenCASCADE");

Box(1) = {-0.0487, -0.0487, -0.0487, 0.1, 0.1, 0.06};
Box(2) = {-0.0287, -0.0287, -0.0087, 0.06, 0.06, 0.02};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };

Physical Volume("die") = {3};
// The faces the metal meets (the pocket's floor and walls), kept at the finest spacing when the
// die is graded (system/particleizeMoldDict.graded).
e = 1e-6;
Physical Surface("pocket") = Surface In BoundingBox{-0.0287 - e, -0.0287 - e, -0.0087 - e, 0.0313 + e, 0.0313 + e, 0.0113 + e};
