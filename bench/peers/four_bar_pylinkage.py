"""The library's crank-rocker four-bar (library/four-bar.json: O2 = (0, 0),
crank 0.1 m, coupler 0.3 m, rocker 0.25 m about O4 = (0.3, 0)) in pylinkage
(PyPI), each position a circle-circle intersection: its numba path
(Linkage.step_fast) when numba is installed, plain Python otherwise. The
peer of the service's kinematics-only path in benches/work_precision and
tests/api/peers.rs.

    .venv/bin/python bench/peers/four_bar_pylinkage.py STEPS   # JSON: B per step, seconds

Step k (0-based) is the crank at (k + 1) * 2 pi / STEPS: pylinkage turns
the crank before it places the dyad.
"""

import json
import math
import sys
import time

from pylinkage.actuators import Crank
from pylinkage.components import Ground
from pylinkage.dyads import RRRDyad
from pylinkage.simulation import Linkage

B = (0.26875, 0.24803918541230538)
COUPLER = math.hypot(B[0] - 0.1, B[1])
ROCKER = math.hypot(B[0] - 0.3, B[1])


def main():
    steps = int(sys.argv[1])
    o2, o4 = Ground(0.0, 0.0, name="O2"), Ground(0.3, 0.0, name="O4")
    crank = Crank(anchor=o2, radius=0.1, angular_velocity=2 * math.pi / steps)
    rocker = RRRDyad(crank.output, o4, distance1=COUPLER, distance2=ROCKER, x=B[0], y=B[1], name="B")
    linkage = Linkage([o2, o4, crank, rocker], name="four-bar")
    linkage.step_fast(iterations=steps)  # compiled (numba) before timing
    best = math.inf
    for _ in range(20):
        start = time.perf_counter()
        trajectory = linkage.step_fast(iterations=steps)
        best = min(best, time.perf_counter() - start)
    try:
        import numba  # noqa: F401

        path = "numba"
    except ImportError:
        path = "python"
    print(json.dumps({"seconds": best, "path": path, "b": trajectory[:, 3, :].tolist()}))


if __name__ == "__main__":
    main()
