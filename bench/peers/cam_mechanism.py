"""The peer for cam design: the PyPI package `mechanism` (gabemorris12).

Times `Cam.get_base_circle` for a roller follower (10 mm, a largest
pressure angle of 30°) on dwell 60° – cycloidal rise of 20 mm over 90° –
dwell 60° – cycloidal fall over 90° – dwell 60°: the best of 5 runs, its
own grid. Prints one JSON line: {"peer", "seconds", "base_radius"}.
"""

import json
import time
import warnings

warnings.filterwarnings("ignore")
from mechanism import Cam  # noqa: E402

MOTION = [("Dwell", 60), ("Rise", 0.02, 90), ("Dwell", 60), ("Fall", 0.02, 90), ("Dwell", 60)]


def size():
    cam = Cam(motion=MOTION, degrees=True, omega=10)
    return cam.get_base_circle(kind="cycloidal", follower="roller", roller_radius=0.01, eccentricity=0, max_pressure_angle=30)


best, result = float("inf"), None
for _ in range(5):
    start = time.perf_counter()
    result = size()
    best = min(best, time.perf_counter() - start)
base = abs(float(result["Rb"]) + 0.01) - 0.01
print(json.dumps({"peer": "mechanism (PyPI)", "seconds": best, "base_radius": base}))
