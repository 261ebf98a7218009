"""Start-up of a slider-crank in Exudyn (PyPI), the multibody code a user
would pick instead: the peer of the service's direct dynamics in
benches/work_precision/ and tests/api/peers.rs.

Model (library/requests/slider_crank_startup.json, the same numbers):
crank OA 0.5 m, 2 kg, I_G = 2/12 * 0.5^2, G at mid-length; rod AB 1 m,
4 kg, I_G = 4/12 * 1^2, G at mid-length; slider 1 kg on the x axis; the
crank and rod lie along +x at rest (outer dead centre); a constant torque of
10 N m on the crank; no gravity; 2 s. Exudyn integrates the index-3 DAE with
its default implicit generalized-alpha method at a fixed step; the result
is the crank angle at 2 s.

The reference angle comes from neither integrator: with a constant torque
and no gravity the kinetic energy is 10 phi, so t(phi) = int_0^phi
sqrt(I*/(20 phi)) dphi with the slider-crank's closed-form reduced inertia
I*(phi); scipy's quad (phi = u^2 removes the 1/sqrt(phi) at rest) and
brentq solve t(phi) = 2 s.

    .venv/bin/python bench/peers/slider_crank_exudyn.py [STEPS ...]        # JSON, default 8000 32000
    .venv/bin/python bench/peers/slider_crank_exudyn.py --work-precision   # JSON lines over the steps
"""

import json
import math
import sys
import time

import exudyn as exu
from exudyn.itemInterface import (LoadTorqueVector, MarkerBodyPosition, MarkerBodyRigid, MarkerNodeCoordinate,
                                  NodePoint2D, NodePointGround, NodeRigidBody2D, ObjectConnectorCoordinate,
                                  ObjectGround, ObjectJointRevolute2D, ObjectMassPoint2D, ObjectRigidBody2D)

from scipy.integrate import quad
from scipy.optimize import brentq

R, L, END, TORQUE = 0.5, 1.0, 2.0, 10.0


def reduced_inertia(phi):
    """I*(phi) of crank, rod and slider from the closed-form velocity coefficients."""
    s, c = math.sin(phi), math.cos(phi)
    sin_b = -R * s / L
    cos_b = math.sqrt(1.0 - sin_b * sin_b)
    db = -R * c / (L * cos_b)
    vg = (-R * s - 0.5 * L * sin_b * db, R * c + 0.5 * L * cos_b * db)
    vs = -R * s - L * sin_b * db
    return 2.0 / 12 * R**2 + 2.0 * (R / 2) ** 2 + 4.0 * (vg[0] ** 2 + vg[1] ** 2) + 4.0 / 12 * L**2 * db**2 + vs**2


def reference_angle():
    """The crank angle at END from the energy balance 1/2 I* w^2 = TORQUE * phi."""

    def time_to(phi):
        # phi = u^2: dphi / w = 2 sqrt(I*/(2 TORQUE)) du, smooth at rest.
        f = lambda u: 2.0 * math.sqrt(reduced_inertia(u * u) / (2.0 * TORQUE))
        n = int(phi / math.pi) + 1
        edges = [math.sqrt(k * phi / n) for k in range(n + 1)]
        return sum(quad(f, a, b, epsabs=0.0, epsrel=1e-13, limit=200)[0] for a, b in zip(edges, edges[1:]))

    return brentq(lambda p: time_to(p) - END, 20.0, 24.0, xtol=1e-14, rtol=8.9e-16)


def crank_angle(steps):
    """Crank angle at END with `steps` fixed steps, and the wall time of building and solving."""
    start = time.perf_counter()
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    ground = mbs.AddObject(ObjectGround(referencePosition=[0, 0, 0]))
    ground_node = mbs.AddNode(NodePointGround(referenceCoordinates=[0, 0, 0]))
    crank_node = mbs.AddNode(NodeRigidBody2D(referenceCoordinates=[R / 2, 0, 0]))
    crank = mbs.AddObject(ObjectRigidBody2D(mass=2.0, inertia=2.0 / 12 * R**2, nodeNumber=crank_node))
    rod_node = mbs.AddNode(NodeRigidBody2D(referenceCoordinates=[R + L / 2, 0, 0]))
    rod = mbs.AddObject(ObjectRigidBody2D(mass=4.0, inertia=4.0 / 12 * L**2, nodeNumber=rod_node))
    slider_node = mbs.AddNode(NodePoint2D(referenceCoordinates=[R + L, 0]))
    slider = mbs.AddObject(ObjectMassPoint2D(mass=1.0, nodeNumber=slider_node))

    def at(body, x, rigid=False):
        marker = MarkerBodyRigid if rigid else MarkerBodyPosition
        return mbs.AddMarker(marker(bodyNumber=body, localPosition=[x, 0, 0]))

    crank_o = at(crank, -R / 2, rigid=True)
    mbs.AddObject(ObjectJointRevolute2D(markerNumbers=[at(ground, 0.0), crank_o]))
    mbs.AddObject(ObjectJointRevolute2D(markerNumbers=[at(crank, R / 2), at(rod, -L / 2)]))
    mbs.AddObject(ObjectJointRevolute2D(markerNumbers=[at(rod, L / 2), at(slider, 0.0)]))
    guide = [mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=ground_node, coordinate=0)),
             mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=slider_node, coordinate=1))]
    mbs.AddObject(ObjectConnectorCoordinate(markerNumbers=guide))
    mbs.AddLoad(LoadTorqueVector(markerNumber=crank_o, loadVector=[0, 0, TORQUE]))
    mbs.Assemble()

    settings = exu.SimulationSettings()
    settings.timeIntegration.numberOfSteps = steps
    settings.timeIntegration.endTime = END
    settings.timeIntegration.verboseMode = 0
    settings.timeIntegration.newton.relativeTolerance = 1e-12
    settings.timeIntegration.newton.absoluteTolerance = 1e-12
    settings.solution.file.write = False
    exu.SolveDynamic(mbs, settings)
    angle = mbs.GetNodeOutput(crank_node, exu.OutputVariableType.Coordinates)[2]
    return angle, time.perf_counter() - start


def point(steps, runs, reference):
    best, angle = float("inf"), None
    for _ in range(runs):
        angle, seconds = crank_angle(steps)
        best = min(best, seconds)
    return {"peer": "Exudyn generalized-alpha", "steps": steps, "angle": angle, "seconds": best,
            "error": abs(angle - reference), "reference_angle": reference}


if __name__ == "__main__":
    ref = reference_angle()
    if "--work-precision" in sys.argv:
        for steps in (500, 2000, 8000, 32000, 128000):
            print(json.dumps(point(steps, 3 if steps <= 8000 else 1, ref)), flush=True)
    else:
        steps = [int(a) for a in sys.argv[1:]] or [8000, 32000]
        print(json.dumps({"reference_angle": ref, "points": [point(n, 1, ref) for n in steps]}))
