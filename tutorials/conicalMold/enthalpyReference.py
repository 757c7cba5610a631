#!/usr/bin/python3
"""Independent reference for tutorials/conicalMold: the cone's conduction solved by an
axisymmetric finite-difference enthalpy method (no SPH, no flow, no shrinkage).

The melt (AC4CH, Table 1 of the paper: u(T) with the latent heat as its steep part, kappa(T))
fills the frustum r <= 25 mm + 30 mm z / 80 mm, 0 <= z <= H = 68.84 mm at 970 K; its walls
(floor and side) are held at 300 K, its top is adiabatic. Explicit in time on a grid of square
cells (the side wall is a staircase: cells whose centre lies inside belong to the melt, a face to
a cell outside is the wall, at 300 K, half a cell away). Density 2398.8 kg/m^3 throughout (the
mass of the melt in the mold's volume; shrinkage is left out). The solid fraction is the SPH's:
the share of the heat between liquidus and solidus given up, f_s = (u(T_liq) - u) / (u(T_liq)
- u(T_sol)), clamped to [0, 1].

Usage: enthalpyReference.py [cell size in mm, default 1] -> prints the times at which the mass
solid fraction reaches 0.1, 0.5, 0.9 and 1 and the last cell to freeze.
"""
import math
import sys

T_table = [803.0, 830.44, 848, 873, 888.64, 973]
u_table = [7.89e5, 8.44e5, 1.11e6, 1.23e6, 1.33e6, 1.431e6]
k_table = [174.35, 175.34, 114.78, 98.33, 83.3, 86.05]
LIQUIDUS, SOLIDUS = 888.64, 830.44
RHO = 2398.8
T_START, T_WALL = 970.0, 300.0
R_FLOOR, SLOPE, HEIGHT = 0.025, 0.030 / 0.080, 0.06884


def interpolate(x, xs, ys, extrapolate):
    if x <= xs[0]:
        k = 0
    elif x >= xs[-1]:
        k = len(xs) - 2
    else:
        k = max(i for i in range(len(xs) - 1) if xs[i] <= x)
    if not extrapolate:
        x = min(max(x, xs[0]), xs[-1])
    return ys[k] + (ys[k + 1] - ys[k]) * (x - xs[k]) / (xs[k + 1] - xs[k])


def energy(T):  # u(T), extended beyond the table with its end slopes
    return interpolate(T, T_table, u_table, True)


def temperature(u):
    return interpolate(u, u_table, T_table, True)


def conductivity(T):
    return interpolate(T, T_table, k_table, False)


U_LIQ, U_SOL = energy(LIQUIDUS), energy(SOLIDUS)


def solid_fraction(u):
    return min(max((U_LIQ - u) / (U_LIQ - U_SOL), 0.0), 1.0)


def solve(cell):
    nr = int(math.ceil((R_FLOOR + SLOPE * HEIGHT) / cell))
    nz = int(round(HEIGHT / cell))
    dz = HEIGHT / nz
    inside = [[(i + 0.5) * cell < R_FLOOR + SLOPE * (j + 0.5) * dz for j in range(nz)]
              for i in range(nr)]
    cells = [(i, j) for i in range(nr) for j in range(nz) if inside[i][j]]
    u = {c: energy(T_START) for c in cells}
    mass = {(i, j): RHO * (i + 0.5) * cell * cell * dz for (i, j) in cells}  # per radian
    total = sum(mass.values())
    # explicit limit: dt <= 0.2 min(dr, dz)^2 rho c_min / kappa_max
    c_min = min((u_table[k + 1] - u_table[k]) / (T_table[k + 1] - T_table[k])
                for k in range(len(T_table) - 1))
    dt = 0.2 * min(cell, dz) ** 2 * RHO * c_min / max(k_table)
    t, marks, reached = 0.0, [0.1, 0.5, 0.9, 1.0], {}
    last_liquid = None
    while len(reached) < len(marks):
        T = {c: temperature(u[c]) for c in cells}
        kappa = {c: conductivity(T[c]) for c in cells}
        rate = {c: 0.0 for c in cells}
        for (i, j) in cells:
            r = (i + 0.5) * cell
            # faces: (neighbour, face area per radian, distance)
            faces = [((i + 1, j), (r + 0.5 * cell) * dz, cell),
                     ((i, j + 1), r * cell, dz), ((i, j - 1), r * cell, dz)]
            if i > 0:
                faces.append(((i - 1, j), (r - 0.5 * cell) * dz, cell))
            for (n, area, distance) in faces:
                if n[1] >= nz:
                    continue  # the top: adiabatic
                if n in T:
                    if n < (i, j):
                        continue  # each inner face once
                    k = 2 * kappa[(i, j)] * kappa[n] / (kappa[(i, j)] + kappa[n])
                    flux = k * area * (T[n] - T[(i, j)]) / distance
                    rate[(i, j)] += flux
                    rate[n] -= flux
                else:  # the wall at 300 K on the face, half a cell away
                    rate[(i, j)] += kappa[(i, j)] * area * (T_WALL - T[(i, j)]) / (0.5 * distance)
        for c in cells:
            u[c] += dt * rate[c] / mass[c]
        t += dt
        fraction = sum(mass[c] * solid_fraction(u[c]) for c in cells) / total
        liquid = [c for c in cells if solid_fraction(u[c]) < 1]
        if liquid:
            last_liquid = liquid
        for mark in marks:
            if mark not in reached and (fraction >= mark if mark < 1 else not liquid):
                reached[mark] = t
    # the last cells to freeze: their mass-weighted centre
    weight = sum(mass[c] for c in last_liquid)
    r_last = sum(mass[c] * (c[0] + 0.5) * cell for c in last_liquid) / weight
    z_last = sum(mass[c] * (c[1] + 0.5) * dz for c in last_liquid) / weight
    return reached, (r_last, z_last), len(cells), dt


if __name__ == "__main__":
    cell = float(sys.argv[1]) * 1e-3 if len(sys.argv) > 1 else 1e-3
    reached, (r_last, z_last), count, dt = solve(cell)
    print(f"enthalpy FD, cells of {cell * 1e3:g} mm ({count} cells, dt {dt:.3g} s):")
    for mark, t in sorted(reached.items()):
        print(f"  solid fraction {mark:.1f} at t = {t:.3f} s")
    print(f"  last to freeze: r = {r_last * 1e3:.1f} mm, z = {z_last * 1e3:.1f} mm")
