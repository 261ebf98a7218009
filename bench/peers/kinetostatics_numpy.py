"""Kinetostatics of reference case K1, the offset slider-crank, written the
way a NumPy user would: per crank position, closed-form kinematics and one
9 x 9 Newton-Euler system solved by numpy.linalg.solve for the driving torque
and the joint reactions. The peer of the service's kinetostatics in
benches/work_precision.rs and tests/api/peers.rs.

Data (library/requests/k1_offset_slider_crank.json): crank OA
r = 0.08 m at omega = 150 rad/s, rod AB L = 0.3 m, piston on y = e = 0.02 m;
masses 2, 1.2, 0.9 kg; inertias 0.004, 0.012, 0.001 kg m^2; G1 at 0.02 m
along the crank, G2 at 0.3 of AB from A, G3 at B; gravity -9.81 y; the gas
force -8000 exp(3 (cos(phi - 0.35) - 1)) N along x on the piston at B.

    .venv/bin/python bench/peers/kinetostatics_numpy.py STEPS   # JSON: torques and seconds
"""

import json
import sys
import time

import numpy as np

R, L, E, W, G = 0.08, 0.3, 0.02, 150.0, 9.81
M = (2.0, 1.2, 0.9)
I = (0.004, 0.012, 0.001)


def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def torque(phi):
    """Driving torque (ground on crank) and the residual of virtual power at phi."""
    c, s = np.cos(phi), np.sin(phi)
    sin_t = (E - R * s) / L
    cos_t = np.sqrt(1.0 - sin_t * sin_t)
    a = np.array([R * c, R * s])
    b = a + L * np.array([cos_t, sin_t])
    theta_d = -R * W * c / (L * cos_t)
    theta_dd = (R * W * W * s + L * theta_d**2 * sin_t) / (L * cos_t)
    acc_a = -W * W * a
    acc_b = np.array([-R * W * W * c - L * theta_dd * sin_t - L * theta_d**2 * cos_t, 0.0])
    g1, g2 = 0.25 * a, a + 0.3 * (b - a)
    acc_g1, acc_g2 = 0.25 * acc_a, 0.7 * acc_a + 0.3 * acc_b
    gas = -8000.0 * np.exp(3.0 * (np.cos(phi - 0.35) - 1.0))
    # Unknowns: R_O (ground on crank), R_A (crank on rod), R_B (rod on piston),
    # N (guide on piston, y), M_g (guide moment), T (driving torque).
    k = np.zeros((9, 9))
    rhs = np.zeros(9)
    k[0, 0] = k[1, 1] = 1.0  # crank: R_O - R_A = m1 a_G1 - m1 g
    k[0, 2] = k[1, 3] = -1.0
    rhs[0:2] = M[0] * acc_g1 - M[0] * np.array([0.0, -G])
    ro, ra = -g1, a - g1  # moments about G1: T + r_O x R_O - r_A x R_A = 0
    k[2, 0], k[2, 1], k[2, 2], k[2, 3], k[2, 8] = -ro[1], ro[0], ra[1], -ra[0], 1.0
    k[3, 2] = k[4, 3] = 1.0  # rod: R_A - R_B = m2 a_G2 - m2 g
    k[3, 4] = k[4, 5] = -1.0
    rhs[3:5] = M[1] * acc_g2 - M[1] * np.array([0.0, -G])
    ra2, rb2 = a - g2, b - g2  # moments about G2 = I2 theta_dd
    k[5, 2], k[5, 3], k[5, 4], k[5, 5] = -ra2[1], ra2[0], rb2[1], -rb2[0]
    rhs[5] = I[1] * theta_dd
    k[6, 4] = 1.0  # piston: R_B + (0, N) + gas + m3 g = m3 a_B
    k[7, 5] = k[7, 6] = 1.0
    rhs[6:8] = M[2] * acc_b - np.array([gas, 0.0]) - M[2] * np.array([0.0, -G])
    k[8, 7] = 1.0  # the piston does not turn: M_g = 0
    x = np.linalg.solve(k, rhs)
    t = x[8]
    # Virtual power: T w + gas x_B' + sum m g.v - sum (m a.v + I alpha w) = 0.
    vel_a = W * np.array([-a[1], a[0]])
    vel_b = np.array([-R * W * s - L * theta_d * sin_t, 0.0])
    vel_g2 = 0.7 * vel_a + 0.3 * vel_b
    power = t * W + gas * vel_b[0] - G * (M[0] * 0.25 * vel_a[1] + M[1] * vel_g2[1])
    power -= M[0] * (0.25 * acc_a) @ (0.25 * vel_a) + M[1] * acc_g2 @ vel_g2 + M[2] * acc_b @ vel_b
    power -= I[1] * theta_dd * theta_d
    return t, power / max(abs(t * W), 1.0)


if __name__ == "__main__":
    steps = int(sys.argv[1]) if len(sys.argv) > 1 else 3600
    phis = 2.0 * np.pi * np.arange(steps) / steps
    best = float("inf")
    for _ in range(3):
        start = time.perf_counter()
        values = [torque(p) for p in phis]
        best = min(best, time.perf_counter() - start)
    print(json.dumps({
        "peer": "NumPy",
        "steps": steps,
        "seconds": best,
        "torque": [float(v[0]) for v in values],
        "virtual_power_residual": max(abs(float(v[1])) for v in values),
    }))
