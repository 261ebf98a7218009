"""Flywheel of reference case F1 (the course's P.103) written the way a SciPy
user would: scipy.integrate.quad for the works, scipy.optimize.brentq for the
sign changes of M* and for the stationary points of Wittenbauer's functions.
The peer of the service's flywheel in benches/work_precision/ and
tests/api/peers.rs.

Data: load torque -500 sin(phi) N m on (0, pi), 0 on (pi, 2 pi); a constant
motor torque balancing it over the cycle; I*(phi) = 5 sin^2(phi) kg m^2;
mean speed 2 pi rad/s; irregularity 0.04.

Method (the same as the service's): with kappa = 2/w^2, a = (1 + e/2)^2,
b = (1 - e/2)^2 and W(phi) the work of M* from 0,
    I = (max[b I* - kappa W] - min[a I* - kappa W]) / (a - b),
the extrema taken at the ends of the smooth pieces and at the roots of
k I*'(phi) = kappa M*(phi) (k = a, b), bracketed on a grid and refined by
brentq. The approximate inertia is dE/(e w^2) with dE from the lobes of M*.

    .venv/bin/python bench/peers/flywheel_scipy.py            # JSON, default tolerance 1e-10
    .venv/bin/python bench/peers/flywheel_scipy.py --work-precision
"""

import json
import math
import sys
import time

from scipy.integrate import quad
from scipy.optimize import brentq

OMEGA, EPS, PERIOD = 2.0 * math.pi, 0.04, 2.0 * math.pi
BREAKS = [0.0, math.pi, 2.0 * math.pi]
GRID = 512  # bracketing intervals per smooth piece: 1024 per period, as the service

calls = 0


def load(phi):
    global calls
    calls += 1
    return -500.0 * math.sin(phi) if phi < math.pi else 0.0


def inertia(phi):
    return 5.0 * math.sin(phi) ** 2


def inertia_slope(phi):
    return 10.0 * math.sin(phi) * math.cos(phi)


def solve(tol):
    """Approximate and exact flywheel inertia at quadrature/root tolerance tol."""
    opts = {"epsabs": tol * 1e3, "epsrel": tol, "limit": 200}
    pieces = list(zip(BREAKS, BREAKS[1:]))
    balance = -sum(quad(load, lo, hi, **opts)[0] for lo, hi in pieces) / PERIOD

    def torque(phi):
        return load(phi) + balance

    def work(phi):
        # W(phi) piece by piece, so quad never straddles the jump at pi.
        total = 0.0
        for lo, hi in pieces:
            if phi <= lo:
                break
            total += quad(torque, lo, min(phi, hi), **opts)[0]
        return total

    def roots(f):
        found = []
        for lo, hi in pieces:
            # Stay inside the piece: f uses the one-sided torque there.
            xs = [lo + (hi - lo) * (k + 0.5e-9) / GRID for k in range(GRID)] + [hi - (hi - lo) * 1e-12]
            for x0, x1 in zip(xs, xs[1:]):
                f0, f1 = f(x0), f(x1)
                if f0 == 0.0:
                    found.append(x0)
                elif f0 * f1 < 0.0:
                    found.append(brentq(f, x0, x1, xtol=tol * 1e-3, rtol=max(tol, 4.5e-16)))
        return found

    # Lobes of M*: crossings, running works, their spread.
    crossings = roots(torque)
    cumulative = [work(x) for x in crossings + [PERIOD]] + [0.0]
    delta_e = max(cumulative) - min(cumulative)
    approximate = delta_e / (EPS * OMEGA**2)

    kappa = 2.0 / OMEGA**2
    a, b = (1.0 + EPS / 2.0) ** 2, (1.0 - EPS / 2.0) ** 2
    ends = [0.0, math.pi, 2.0 * math.pi]
    extremes = []
    for k, pick in ((a, min), (b, max)):
        candidates = ends + roots(lambda x, k=k: k * inertia_slope(x) - kappa * torque(x))
        extremes.append(pick(k * inertia(x) - kappa * work(x) for x in candidates))
    exact = (extremes[1] - extremes[0]) / (a - b)
    return approximate, exact


def timed(tol, runs):
    global calls
    best = math.inf
    for _ in range(runs):
        calls = 0
        start = time.perf_counter()
        approximate, exact = solve(tol)
        best = min(best, time.perf_counter() - start)
    return {"tolerance": tol, "inertia_approximate": approximate, "inertia_exact": exact,
            "seconds": best, "evaluations": calls}


if __name__ == "__main__":
    if "--work-precision" in sys.argv:
        points = [timed(tol, 5) for tol in (1e-4, 1e-6, 1e-8, 1e-10, 1e-12)]
        print(json.dumps({"peer": "SciPy quad + brentq", "points": points}))
    else:
        print(json.dumps(timed(1e-10, 3)))
