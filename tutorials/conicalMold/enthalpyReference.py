#!/usr/bin/python3
"""Independent reference for tutorials/conicalMold: the cone's conduction solved by an
axisymmetric finite-difference enthalpy method (no SPH, no flow; the shrinkage only as the
feeding below).

The melt (AC4CH, Table 1 of the paper: u(T) with the latent heat as its steep part, kappa(T))
fills the frustum r <= 25 mm + 30 mm z / 80 mm, 0 <= z <= H = 68.84 mm at 970 K; its walls
(floor and side) are held at 300 K, its top is adiabatic. Explicit in time on a grid of square
cells (the side wall is a staircase: cells whose centre lies inside belong to the melt, a face to
a cell outside is the wall, at 300 K, half a cell away). Density 2398.8 kg/m^3 throughout (the
mass of the melt in the mold's volume; the conduction leaves the shrinkage out). The solid
fraction is the SPH's: the share of the heat between liquidus and solidus given up, f_s =
(u(T_liq) - u) / (u(T_liq) - u(T_sol)), clamped to [0, 1].

Feeding (the sink's shape, the classic level-drop picture of a pipe): a cell feeds until its
solid fraction reaches the frozen fraction f_c (the SPH's frozenSolidFraction, 0.5); while it
feeds, its contraction by Table 1's rho_s(T) is drawn from the pool's free surface, which sinks
by the volume over the pool's open area (the top row's cells that still feed). A column's top
keeps the level at which its surface cell froze: that is the sink's profile. Feeding cells cut
off from the pool by frozen ones put their contraction into an enclosed cavity instead. Frozen
cells keep their volume (the solid's own contraction opens no cavity, as in the SPH). The
conduction does not see the sink (its grid keeps the full cone; the cells above the level are
left out of the contraction): an approximation of the order of the sink over the height, 7 %.

Usage: enthalpyReference.py [cell size in mm, default 1] -> prints the times at which the mass
solid fraction reaches 0.1, 0.5, 0.9 and 1, the last cell to freeze and the sink's profile.
"""
import math
import sys

T_table = [803.0, 830.44, 848, 873, 888.64, 973]
u_table = [7.89e5, 8.44e5, 1.11e6, 1.23e6, 1.33e6, 1.431e6]
k_table = [174.35, 175.34, 114.78, 98.33, 83.3, 86.05]
rho_table = [2571.9, 2565.5, 2517, 2474.3, 2426.6, 2398.8]
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


def rest_density(T):
    return interpolate(T, T_table, rho_table, False)


U_LIQ, U_SOL = energy(LIQUIDUS), energy(SOLIDUS)


def solid_fraction(u):
    return min(max((U_LIQ - u) / (U_LIQ - U_SOL), 0.0), 1.0)


class Feeding:
    """The level-drop picture of the sink (module docstring): the pool's level, each column's
    frozen top, the volume drawn from the top and the volume enclosed (all per radian)."""

    def __init__(self, cells, cell, dz, frozen_fraction):
        self.cells, self.cell, self.dz, self.f_c = set(cells), cell, dz, frozen_fraction
        self.level = HEIGHT
        self.frozen = set()
        self.top = {}  # column -> the level at which its surface cell froze
        self.drawn = self.enclosed = 0.0
        self.volume = sum((i + 0.5) * cell * cell * dz for (i, j) in cells)  # the melt's, at start
        self.columns = sorted({i for (i, j) in cells})

    def surface_row(self):
        return min(int(self.level / self.dz), int(round(HEIGHT / self.dz)) - 1)

    def advance(self, T_old, u_new, mass):
        row = self.surface_row()
        feeding = {c for c in self.cells if c not in self.frozen and c[1] <= row}
        # the pool: feeding cells connected to the level's row through feeding cells
        pool = {c for c in feeding if c[1] == row}
        front = list(pool)
        while front:
            i, j = front.pop()
            for n in ((i + 1, j), (i - 1, j), (i, j + 1), (i, j - 1)):
                if n in feeding and n not in pool:
                    pool.add(n)
                    front.append(n)
        drawn = 0.0
        for c in feeding:
            shrink = mass[c] * (1 / rest_density(T_old[c])
                                - 1 / rest_density(temperature(u_new[c])))
            if c in pool:
                drawn += shrink
            else:
                self.enclosed += shrink
        self.drawn += drawn
        open_area = sum((i + 0.5) * self.cell * self.cell for (i, j) in pool if j == row)
        if open_area > 0:
            self.level -= drawn / open_area
        for c in feeding:
            if solid_fraction(u_new[c]) >= self.f_c:
                self.frozen.add(c)
        row = self.surface_row()
        for i in self.columns:
            if i not in self.top and ((i, row) in self.frozen or (i, row) not in self.cells):
                self.top[i] = self.level

    def sink(self, r):
        """The sink's depth at radius r: the start's level less the column's frozen top."""
        i = int(r / self.cell)
        return HEIGHT - self.top.get(i, self.level)


def solve(cell, frozen_fraction=0.5):
    nr = int(math.ceil((R_FLOOR + SLOPE * HEIGHT) / cell))
    nz = int(round(HEIGHT / cell))
    dz = HEIGHT / nz
    inside = [[(i + 0.5) * cell < R_FLOOR + SLOPE * (j + 0.5) * dz for j in range(nz)]
              for i in range(nr)]
    cells = [(i, j) for i in range(nr) for j in range(nz) if inside[i][j]]
    u = {c: energy(T_START) for c in cells}
    mass = {(i, j): RHO * (i + 0.5) * cell * cell * dz for (i, j) in cells}  # per radian
    total = sum(mass.values())
    feeding = Feeding(cells, cell, dz, frozen_fraction)
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
        feeding.advance(T, u, mass)  # T: the step's start
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
    return reached, (r_last, z_last), len(cells), dt, feeding


if __name__ == "__main__":
    cell = float(sys.argv[1]) * 1e-3 if len(sys.argv) > 1 else 1e-3
    reached, (r_last, z_last), count, dt, feeding = solve(cell)
    print(f"enthalpy FD, cells of {cell * 1e3:g} mm ({count} cells, dt {dt:.3g} s):")
    for mark, t in sorted(reached.items()):
        print(f"  solid fraction {mark:.1f} at t = {t:.3f} s")
    print(f"  last to freeze: r = {r_last * 1e3:.1f} mm, z = {z_last * 1e3:.1f} mm")
    print(f"  feeding to f_s = {feeding.f_c}: {2e6 * math.pi * feeding.drawn:.1f} cm^3 drawn "
          f"from the top, {2e6 * math.pi * feeding.enclosed:.2f} cm^3 enclosed; the sink "
          + ", ".join(f"{feeding.sink(r * 1e-3) * 1e3:.1f} mm at r = {r}"
                      for r in (0, 5, 10, 20, 30, 40, 45)))
