"""The peer for cam design: the PyPI package `mechanism` (gabemorris12).

Times `Cam.get_base_circle` on dwell 60° – cycloidal rise of 20 mm over
90° – dwell 60° – cycloidal fall over 90° – dwell 60°, the best of 5 runs,
on its own grid, for one of its two followers (the first argument):
- `roller` (the default): a 10 mm roller, a largest pressure angle of 30°;
- `flat`: a flat face, a least radius of curvature of 5 mm.
Prints one JSON line: {"peer", "follower", "seconds", "base_radius"}.
"""

import json
import sys
import time
import warnings

warnings.filterwarnings("ignore")
from mechanism import Cam  # noqa: E402

MOTION = [("Dwell", 60), ("Rise", 0.02, 90), ("Dwell", 60), ("Fall", 0.02, 90), ("Dwell", 60)]
FOLLOWER = sys.argv[1] if len(sys.argv) > 1 else "roller"


def size():
    cam = Cam(motion=MOTION, degrees=True, omega=10)
    if FOLLOWER == "flat":
        return cam.get_base_circle(kind="cycloidal", follower="flat", desired_min_rho=0.005)
    return cam.get_base_circle(kind="cycloidal", follower="roller", roller_radius=0.01, eccentricity=0, max_pressure_angle=30)


best, result = float("inf"), None
for _ in range(5):
    start = time.perf_counter()
    result = size()
    best = min(best, time.perf_counter() - start)
# The roller's Rb is its pitch radius less the roller (fsolve may land on
# the negative root of (Rb + Rf)²); the flat face's is the base radius.
rb = float(result["Rb"])
base = abs(rb + 0.01) - 0.01 if FOLLOWER == "roller" else rb
print(json.dumps({"peer": "mechanism (PyPI)", "follower": FOLLOWER, "seconds": best, "base_radius": base}))
