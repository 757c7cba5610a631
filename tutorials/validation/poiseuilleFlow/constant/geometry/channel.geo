// Poiseuille flow between plates (Morris, Fox & Zhu 1997): plates at y = 0 and y = L = 1 mm, a
// periodic interval 0 <= x < Lx = 0.8 mm, in the plane z = 0. Each plate is a Physical Curve
// spanning the periodic interval exactly, so that its particles, at x = (i + 1/2) dx, continue
// across x = Lx as a periodic lattice (Lx a multiple of dx: 0.8 mm is one at 10, 20 and 40 rows
// across). The ends x = 0 and x = Lx are no walls; the plane surface is the cavity between.
L = 1e-3;
Lx = 0.8e-3;
Point(1) = {0, 0, 0};
Point(2) = {Lx, 0, 0};
Point(3) = {Lx, L, 0};
Point(4) = {0, L, 0};
Line(1) = {1, 2};   // lower plate
Line(2) = {2, 3};   // periodic end
Line(3) = {3, 4};   // upper plate
Line(4) = {4, 1};   // periodic end
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("lowerPlate") = {1};
Physical Curve("upperPlate") = {3};
Physical Surface("channel") = {1};
