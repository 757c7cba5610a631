#!/usr/bin/python3
"""Independent reference for chvorinovPlates: the plate's conduction by an explicit 1D
finite-difference enthalpy method (no SPH), AC4CH of Table 1 (u(T) with the latent heat as its
steep part, kappa(T)) at 970 K between two faces held at 300 K from t = 0, density 2399.8 kg/m^3
(rho_s at 970 K, the particles' start). Half the plate, cells of equal size from the held face
(T_w half a cell from the first centre) to the mid-plane (adiabatic by symmetry).

The problem has no length of its own: x -> s x, t -> s^2 t maps the plate of thickness D onto
the one of thickness s D, so every plate's solidification is that of one plate scaled
(Chvorinov's rule t_s = B (V/A)^n with n = 2 exactly for faces held at a fixed temperature,
V/A = D/2). solve() returns, for the 10 mm plate, the times at which each cell reached the
solidus; times(D, x) scales them.

Usage: plateReference.py [cells across the half plate, default 100] -> prints t_s of the 10 mm
plate. Standard library only."""
import sys

T_TABLE = [803.0, 830.44, 848, 873, 888.64, 973]
U_TABLE = [7.89e5, 8.44e5, 1.11e6, 1.23e6, 1.33e6, 1.431e6]
K_TABLE = [174.35, 175.34, 114.78, 98.33, 83.3, 86.05]
SOLIDUS, LIQUIDUS = 830.44, 888.64
CRITICAL = SOLIDUS + 0.1 * (LIQUIDUS - SOLIDUS)  # the Niyama criterion's T_c
RHO, T_START, T_WALL, D_REF = 2399.8, 970.0, 300.0, 0.010


def interpolate(x, xs, ys, extrapolate=True):
    k = 0 if x <= xs[0] else len(xs) - 2 if x >= xs[-1] else \
        max(i for i in range(len(xs) - 1) if xs[i] <= x)
    if not extrapolate:
        x = min(max(x, xs[0]), xs[-1])
    return ys[k] + (ys[k + 1] - ys[k]) * (x - xs[k]) / (xs[k + 1] - xs[k])


def solve(cells=100, with_gradients=False):
    """Solidus times of the cells of the 10 mm plate's half (centres at (i + 1/2) D/2 / cells);
    with_gradients: also |dT/dx| (K/m) and -dT/dt (K/s) of each cell when it passed T_c."""
    dx = D_REF / 2 / cells
    c_min = min((U_TABLE[k + 1] - U_TABLE[k]) / (T_TABLE[k + 1] - T_TABLE[k]) for k in range(5))
    dt = 0.2 * dx * dx * RHO * c_min / max(K_TABLE)
    u = [interpolate(T_START, T_TABLE, U_TABLE)] * cells
    u_solidus = interpolate(SOLIDUS, T_TABLE, U_TABLE)
    reached = [None] * cells
    u_critical = interpolate(CRITICAL, T_TABLE, U_TABLE)
    gradient, rate = [None] * cells, [None] * cells
    t = 0.0
    while reached[-1] is None:
        T = [interpolate(v, U_TABLE, T_TABLE) for v in u]
        k = [interpolate(v, T_TABLE, K_TABLE, False) for v in T]
        flux = [0.0] * (cells + 1)  # into cell i through its left face
        flux[0] = -k[0] * (T[0] - T_WALL) / (dx / 2)
        for i in range(1, cells):
            flux[i] = -0.5 * (k[i - 1] + k[i]) * (T[i] - T[i - 1]) / dx
        new = [u[i] + dt * (flux[i] - flux[i + 1]) / (RHO * dx) for i in range(cells)]
        for i in range(cells):
            if reached[i] is None and new[i] <= u_solidus < u[i]:
                reached[i] = t + dt * (u[i] - u_solidus) / (u[i] - new[i])
            if gradient[i] is None and new[i] <= u_critical < u[i]:
                left = T[i - 1] if i > 0 else T_WALL
                right = T[i + 1] if i + 1 < cells else T[i]  # the mid-plane: symmetric
                span = (2 if i > 0 else 1.5) * dx
                gradient[i] = abs(right - left) / span
                rate[i] = (interpolate(u[i], U_TABLE, T_TABLE) -
                           interpolate(new[i], U_TABLE, T_TABLE)) / dt
        u, t = new, t + dt
    return (reached, gradient, rate) if with_gradients else reached


def times(reference, thickness, distance, power=2):
    """The solidus time at `distance` from the nearer held face of a plate `thickness` thick (a
    quantity of the reference that scales as s^power: times 2, gradients -1, rates -2)."""
    s = thickness / D_REF
    cells = len(reference)
    x = min(distance, thickness - distance) / s  # in the 10 mm plate
    position = x / (D_REF / 2) * cells - 0.5
    if position <= 0:
        # between the held face and the first cell: times from 0 there, the rest as the cell's
        value = reference[0] * (max(position + 0.5, 0) / 0.5 if power == 2 else 1)
    elif position >= cells - 1:
        value = reference[-1]
    else:
        i = int(position)
        value = reference[i] + (reference[i + 1] - reference[i]) * (position - i)
    return value * s ** power


if __name__ == "__main__":
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100
    print(f"10 mm plate, {n} cells across its half: solid at {solve(n)[-1]:.5f} s")
