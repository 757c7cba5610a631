#!/usr/bin/env python3
"""Checks every written time of a case against the exact mold surface, independently of the
solver: no fluid particle behind the wall surface (signed distance from the shape's formula,
not from the wall particles), and the largest density deviation |rho / rho_s - 1|.

usage: checkAgainstAnalyticWalls.py CASE CLOUD SHAPE PARAMETERS... --spacing DX
       --max-deviation FRACTION [--min-gap SPACINGS] [--min-times N (3)]
shapes (mm-free, SI units):
  sphere R                       centred at the origin, fluid inside
  horizontalCylinder R L         axis along y, from -L/2 to L/2, fluid inside
  box XMIN YMIN ZMIN XMAX YMAX ZMAX   fluid inside
  cone R0 R1 H                   axis z, radius R0 at z = 0 growing to R1 at z = H, open top
  boxAroundRotatedCore XMIN YMIN ZMIN XMAX YMAX ZMAX CX CY CZ HX HY HZ AX AY AZ ANGLE
                                 fluid inside the box and outside a core: a box of half-sizes
                                 HX HY HZ about (CX, CY, CZ), turned by ANGLE (radians) about
                                 the axis (AX, AY, AZ) through its centre, as gmsh's Rotate
Reads the .vtp files with VTK's Python XML reader. Prints one line per time; exits 1 on failure.
"""
import math
import os
import sys

import vtk


def signed_gap(shape, p, x):
    """Distance of x in front of the mold surface (negative: behind it)."""
    if shape == "sphere":
        return p[0] - math.sqrt(x[0] ** 2 + x[1] ** 2 + x[2] ** 2)
    if shape == "horizontalCylinder":
        radius, length = p
        return min(radius - math.hypot(x[0], x[2]), 0.5 * length - abs(x[1]))
    if shape == "box":
        return min(x[0] - p[0], x[1] - p[1], x[2] - p[2], p[3] - x[0], p[4] - x[1], p[5] - x[2])
    if shape == "cone":
        r0, r1, height = p
        slope = (r1 - r0) / height  # dr/dz of the side
        side = (r0 + slope * x[2] - math.hypot(x[0], x[1])) / math.sqrt(1 + slope * slope)
        return min(side, x[2])  # the floor at z = 0; the top is open
    if shape == "boxAroundRotatedCore":
        tank = min(x[0] - p[0], x[1] - p[1], x[2] - p[2], p[3] - x[0], p[4] - x[1], p[5] - x[2])
        return min(tank, outside_turned_box(p[6:9], p[9:12], p[12:15], p[15], x))
    raise SystemExit("unknown shape " + shape)


def outside_turned_box(centre, half, axis, angle, x):
    """Signed distance of x outside a box turned by angle about axis through its centre."""
    norm = math.sqrt(sum(a * a for a in axis))
    k = [a / norm for a in axis]
    v = [x[i] - centre[i] for i in range(3)]
    # into the box's own frame: Rodrigues' rotation by -angle
    c, s = math.cos(-angle), math.sin(-angle)
    kv = sum(k[i] * v[i] for i in range(3))
    cross = [k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]]
    local = [v[i] * c + cross[i] * s + k[i] * kv * (1 - c) for i in range(3)]
    q = [abs(local[i]) - half[i] for i in range(3)]
    outside = math.sqrt(sum(max(a, 0.0) ** 2 for a in q))
    return outside + min(max(q), 0.0)


def main():
    args = sys.argv[1:]
    case, cloud, shape = args[0], args[1], args[2]
    options = {}
    params = []
    rest = args[3:]
    i = 0
    while i < len(rest):
        if rest[i].startswith("--"):
            options[rest[i][2:]] = float(rest[i + 1])
            i += 2
        else:
            params.append(float(rest[i]))
            i += 1
    dx = options["spacing"]
    max_deviation = options["max-deviation"]
    min_gap = options.get("min-gap", 0.0)
    min_times = int(options.get("min-times", 3))
    times = []
    for name in os.listdir(case):
        try:
            times.append((float(name), name))
        except ValueError:
            pass
    ok = True
    checked = 0
    worst_gap, worst_deviation = math.inf, 0.0
    for _, name in sorted(times):
        path = os.path.join(case, name, cloud + ".vtp")
        if not os.path.exists(path):
            continue
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(path)
        reader.Update()
        data = reader.GetOutput()
        checked += 1
        fields = data.GetPointData()
        rho, rest_density = fields.GetArray("rho"), fields.GetArray("restDensity")
        gap = math.inf
        deviation = 0.0
        for k in range(data.GetNumberOfPoints()):
            gap = min(gap, signed_gap(shape, params, data.GetPoint(k)) / dx)
            if rho is not None and rest_density is not None:
                deviation = max(deviation, abs(rho.GetValue(k) / rest_density.GetValue(k) - 1))
        worst_gap, worst_deviation = min(worst_gap, gap), max(worst_deviation, deviation)
        print(f"time {name}: {data.GetNumberOfPoints()} particles, nearest to the wall surface "
              f"{gap:.3f} dx, largest density deviation {100 * deviation:.2f} %")
        if gap < min_gap:
            print(f"FAIL: a particle {gap:.3f} dx from the wall surface (at least {min_gap} dx)")
            ok = False
        if deviation > max_deviation:
            print(f"FAIL: density deviation {100 * deviation:.2f} % > {100 * max_deviation:.2f} %")
            ok = False
    print(f"nearest to the wall surface {worst_gap:.3f} dx, largest density deviation "
          f"{100 * worst_deviation:.2f} %")
    if checked < min_times:
        print(f"FAIL: only {checked} written time(s) to check")
        ok = False
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
