// A tank 1.0 m long, 0.4 m wide and 0.6 m high, open at the top: its floor and sides are the
// walls (Physical Surface "wall").
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1.0, 0.4, 0.6};
eps = 1e-3;
top() = Surface In BoundingBox{-eps, -eps, 0.6 - eps, 1.0 + eps, 0.4 + eps, 0.6 + eps};
wall() = Surface{:};
wall() -= top();
Physical Surface("wall") = wall();
Physical Volume("inside") = {1};
