"""Andrews' squeezing mechanism (IFToMM A03) in the test set's own
formulation — seven angles q = (beta, Theta, gamma, phi, delta, Omega,
epsilon), the mass matrix M(q), the forces f(q, q'), the six loop-closure
constraints g(q) = 0 (Hairer & Wanner, Solving ODEs II, VII.7) — written as
the index-1 system [M G^T; G 0][q''; lambda] = [f; -G'(q) q'] and integrated
by SciPy's DOP853. A second method for tests/api/andrews.rs, which builds the
same mechanism as bodies and joints and integrates it in the service.

    python3 -m venv .venv && .venv/bin/pip install numpy scipy
    .venv/bin/python bench/peers/andrews_scipy.py                    # the reference values
    .venv/bin/python bench/peers/andrews_scipy.py --work-precision   # timings, JSON lines
"""

import numpy as np
from numpy import cos, sin, sqrt
from scipy.integrate import solve_ivp

m1, m2, m3, m4, m5, m6, m7 = 0.04325, 0.00365, 0.02373, 0.00706, 0.07050, 0.00706, 0.05498
i1, i2, i3, i4, i5, i6, i7 = 2.194e-6, 4.410e-7, 5.255e-6, 5.667e-7, 1.169e-5, 5.667e-7, 1.912e-5
xa, ya, xb, yb, xc, yc = -0.06934, -0.00227, -0.03635, 0.03273, 0.014, 0.072
d, da, e, ea, rr, ra = 28e-3, 115e-4, 2e-2, 1421e-5, 7e-3, 92e-5
ss, sa, sb, sc, sd = 35e-3, 1874e-5, 1043e-5, 18e-3, 2e-2
ta, tb, u, ua, ub = 2308e-5, 916e-5, 4e-2, 1228e-5, 449e-5
zf, zt, fa = 2e-2, 4e-2, 1421e-5
mom, c0, l0 = 0.033, 4530.0, 0.07785

BETA, THETA, GAMMA, PHI, DELTA, OMEGA, EPSILON = range(7)


def angle(*idx):
    """The row vector picking the sum of these angles."""
    v = np.zeros(7)
    v[list(idx)] = 1.0
    return v


# g_i(q) = sum of c*cos(a.q) or c*sin(a.q): (c, "c" | "s", a)
LOOP_BETA = [(rr, "c", angle(BETA)), (-d, "c", angle(BETA, THETA))]
LOOP_BETA_Y = [(rr, "s", angle(BETA)), (-d, "s", angle(BETA, THETA))]
ROWS = [
    LOOP_BETA + [(-ss, "s", angle(GAMMA))],
    LOOP_BETA_Y + [(ss, "c", angle(GAMMA))],
    LOOP_BETA + [(-e, "s", angle(PHI, DELTA)), (-zt, "c", angle(DELTA))],
    LOOP_BETA_Y + [(e, "c", angle(PHI, DELTA)), (-zt, "s", angle(DELTA))],
    LOOP_BETA + [(-zf, "c", angle(OMEGA, EPSILON)), (-u, "s", angle(EPSILON))],
    LOOP_BETA_Y + [(-zf, "s", angle(OMEGA, EPSILON)), (u, "c", angle(EPSILON))],
]


def constraint_jacobian(q, qd):
    """G = dg/dq and gamma = -(dG/dt) q' (the constant parts of g drop out)."""
    jac, gamma = np.zeros((6, 7)), np.zeros(6)
    for i, row in enumerate(ROWS):
        for c, kind, a in row:
            th, w = a @ q, a @ qd
            if kind == "c":
                jac[i] -= c * sin(th) * a
                gamma[i] += c * cos(th) * w * w
            else:
                jac[i] += c * cos(th) * a
                gamma[i] += c * sin(th) * w * w
    return jac, gamma


def mass_and_forces(q, qd):
    _, th, ga, ph, _, om, _ = q
    bep, thp, _, php, dep, omp, epp = qd
    m = np.zeros((7, 7))
    m[0, 0] = m1 * ra**2 + m2 * (rr**2 - 2 * da * rr * cos(th) + da**2) + i1 + i2
    m[1, 0] = m[0, 1] = m2 * (da**2 - da * rr * cos(th)) + i2
    m[1, 1] = m2 * da**2 + i2
    m[2, 2] = m3 * (sa**2 + sb**2) + i3
    m[3, 3] = m4 * (e - ea) ** 2 + i4
    m[4, 3] = m[3, 4] = m4 * ((e - ea) ** 2 + zt * (e - ea) * sin(ph)) + i4
    m[4, 4] = m4 * (zt**2 + 2 * zt * (e - ea) * sin(ph) + (e - ea) ** 2) + m5 * (ta**2 + tb**2) + i4 + i5
    m[5, 5] = m6 * (zf - fa) ** 2 + i6
    m[6, 5] = m[5, 6] = m6 * ((zf - fa) ** 2 - u * (zf - fa) * sin(om)) + i6
    m[6, 6] = m6 * ((zf - fa) ** 2 - 2 * u * (zf - fa) * sin(om) + u**2) + m7 * (ua**2 + ub**2) + i6 + i7
    xd, yd = sd * cos(ga) + sc * sin(ga) + xb, sd * sin(ga) - sc * cos(ga) + yb
    length = sqrt((xd - xc) ** 2 + (yd - yc) ** 2)
    tension = -c0 * (length - l0) / length
    fx, fy = tension * (xd - xc), tension * (yd - yc)
    f = np.array([
        mom - m2 * da * rr * thp * (thp + 2 * bep) * sin(th),
        m2 * da * rr * bep**2 * sin(th),
        fx * (sc * cos(ga) - sd * sin(ga)) + fy * (sd * cos(ga) + sc * sin(ga)),
        m4 * zt * (e - ea) * dep**2 * cos(ph),
        -m4 * zt * (e - ea) * php * (php + 2 * dep) * cos(ph),
        -m6 * u * (zf - fa) * epp**2 * cos(om),
        m6 * u * (zf - fa) * omp * (omp + 2 * epp) * cos(om),
    ])
    return m, f


def accelerations(y):
    """(q'', lambda) at the state y = (q, q')."""
    q, qd = y[:7], y[7:]
    m, f = mass_and_forces(q, qd)
    jac, gamma = constraint_jacobian(q, qd)
    a = np.block([[m, jac.T], [jac, np.zeros((6, 6))]])
    x = np.linalg.solve(a, np.concatenate([f, gamma]))
    return x[:7], x[7:]


def rhs(_t, y):
    return np.concatenate([y[7:], accelerations(y)[0]])


Q0 = [-0.0617138900142764496358948458001, 0.0, 0.455279819163070380255912382449,
      0.222668390165885884674473185609, 0.487364979543842550225598953530,
      -0.222668390165885884674473185609, 1.23054744454982119249735015568]

def reference():
    """The state at 0.03 s at rtol 1e-11 and 1e-13 (the values in tests/api/andrews.rs)."""
    y0 = np.concatenate([Q0, np.zeros(7)])
    for rtol in (1e-11, 1e-13):
        y = solve_ivp(rhs, (0.0, 0.03), y0, method="DOP853", rtol=rtol, atol=rtol * 1e-2).y[:, -1]
        lam = [float(v) for v in accelerations(y)[1]]
        print(f"rtol {rtol:g}: beta {float(y[0])!r}, beta' {float(y[7])!r}, lambda {lam}")


def work_precision():
    """One JSON line per method and tolerance: the error of beta at 0.03 s
    against the rtol-1e-13 reference, the best wall time of 3 runs, and the
    right-hand-side evaluations (for benches/work_precision.rs)."""
    import json
    import time

    beta_ref = 15.810771195153972
    y0 = np.concatenate([Q0, np.zeros(7)])
    for method, tols in (("DOP853", (1e-4, 1e-6, 1e-8, 1e-10)), ("Radau", (1e-4, 1e-6, 1e-8))):
        for rtol in tols:
            best, sol = float("inf"), None
            for _ in range(3):
                start = time.perf_counter()
                sol = solve_ivp(rhs, (0.0, 0.03), y0, method=method, rtol=rtol, atol=rtol * 1e-2)
                best = min(best, time.perf_counter() - start)
            error = abs(float(sol.y[0, -1]) - beta_ref)
            print(json.dumps({"peer": f"SciPy {method}", "rtol": rtol, "error": error, "seconds": best, "evaluations": int(sol.nfev)}))


if __name__ == "__main__":
    import sys

    work_precision() if "--work-precision" in sys.argv else reference()
