"""Three spatial problems in Exudyn (PyPI), the multibody code a user would
pick instead: the peer of the service's spatial dynamics for the
work-precision benchmark. Exudyn integrates each index-3 DAE with its
default implicit generalized-alpha method (spectral radius 0.9) at a fixed
step; the Newton tolerances are tightened to 1e-10 (relative and absolute)
so that they do not limit the error at the finest steps (1e-12, as the
slider-crank peer uses, is out of reach in double precision on the stiff
governor: Newton fails at 64000 steps), and the step is not allowed to
adapt: a step count either runs at exactly that many steps or the line
reports the failure.

a04 -- IFToMM A04, Bricard's mechanism (library/bricard-linkage.json): five
rods of 1 kg and 1 m, principal inertias 0.001667 about the rod and 0.084167
across, centre of mass mid-rod; P0..P5 = (0,0,0), (1,0,0), (1,-1,0),
(1,-1,1), (0,-1,1), (0,0,1), rod k from P(k-1) to P(k); revolutes at P0..P5
about y, z, x, y, z, x (J1 and J6 to ground); gravity -9.81 along y; from
rest, 10 s. The six revolutes have one redundant row (Kutzbach 0, mobility
1): J6 is a GenericJoint, ground first, that holds the point and only the
rotation row x_ground . z_rod5 = 0, releasing x_ground . y_rod5 = 0 (the
self-stress of the loop has a moment about z at J6, so the 29 rows left are
independent and the motion is the same; the all-revolute model with
Exudyn's EigenDense + ignoreSingularJacobian gives the same numbers but cuts
steps when Newton is asked for tight tolerances). value: the global
position of rod 2's end drawn at P2 at 10 s, [x, y, z]; energy: T + V at
10 s (-29.43 J at the start).

a05 -- IFToMM A05, stiff flyball governor (library/flyball-governor.json):
shaft 0.3 kg (1 x 0.01 x 0.01 m bar along z, centre (0,0,0.5)) on a revolute
about z at the origin; two arms, each a 0.3 kg 1 m bar plus a 5 kg tip mass
as one 5.3 kg body, hinged to the shaft at (+-0.05,0,1) about y along
u = (+-cos 30, 0, -1/2); a 3 kg sleeve (0.005 kg m^2 about each axis) on a
prismatic along z to the shaft at (0,0,0.5); from each side of the sleeve,
(+-0.05,0,0.5), to the middle of its arm a spring of 8e5 N/m, free length
0.5 m, and a damper of 4e4 N s/m; gravity -9.81 along z; every body turning
at 2 pi rad/s about z (v = w x r of its centre of mass), the shaft free;
10 s. value: [z of the sleeve] at 10 s (Exudyn's own test log: 0.61963 m).

cardan -- a Hooke's joint spinning free: input shaft 1 kg, inertia
diag(0.01, 0.05, 0.05), on a revolute about x at the origin; output shaft
1 kg, inertia 0.02 about e2 = (cos 30, sin 30, 0) and 0.05 across, on a
revolute about e2 at the origin; the cross holds a = (0,1,0) of the input
perpendicular to b = (0,0,1) of the output. The two revolutes already hold
the origin, so the cross is a GenericJoint with only the rotation row
y_input . z_output = 0 (constrainedAxes [0,0,0,1,0,0]): 12 - 5 - 5 - 1 = 1
dof and no redundant row. No gravity, no load; input at 10 rad/s, output at
r(0) 10 rad/s along e2 with r(theta) = cos b / (1 - sin^2 b cos^2 theta),
b = 30 deg; 2 s. The input's node uses Tait-Bryan (Rxyz) rotation
coordinates, so its first rotation coordinate is the unwrapped input angle.
value: [theta] at 2 s, rad. The reference (--reference) is exact up to
quadrature: T = 1/2 I1 w1^2 + 1/2 I2 (r w1)^2 is constant, so
t(theta) = int_0^theta sqrt((I1 + I2 r^2)/(2T)) dtheta, and scipy's quad and
brentq solve t(theta) = 2 s.

    .venv/bin/python bench/peers/spatial_exudyn.py MODEL [STEPS ...]       # MODEL: a04, a05, cardan; JSON lines
    .venv/bin/python bench/peers/spatial_exudyn.py MODEL --work-precision  # JSON lines over the steps in SWEEP
    .venv/bin/python bench/peers/spatial_exudyn.py cardan --reference      # {"model": "cardan", "reference": theta}

Each line: {"model": MODEL, "steps": N, "seconds": wall time of
exu.SolveDynamic alone (the best of three for solves under a second in the
sweep), "value": [...]} (and "energy" for a04); a failed solve prints
"value": null and "failed", and the exit status is 1.
"""

import json
import math
import sys
import time
from contextlib import redirect_stdout

import numpy as np

import exudyn as exu
from exudyn.itemInterface import ObjectGround
from exudyn.rigidBodyUtilities import RigidBodyInertia, RotationMatrixY, RotationMatrixZ

from scipy.integrate import quad
from scipy.optimize import brentq

NEWTON_TOL = 1e-10

# Each step list runs coarse to fine, 4x apart; the finest takes well under a minute.
SWEEP = {"a04": (250, 1000, 4000, 16000, 64000, 256000),
         "a05": (1000, 4000, 16000, 64000, 256000),  # 250 steps would need Newton to cut the step
         "cardan": (100, 400, 1600, 6400, 25600, 102400, 409600)}
DEFAULT_STEPS = {"a04": (4000, 16000), "a05": (16000, 64000), "cardan": (6400, 25600)}


def bar_inertia(mass, length, width, axis):
    """Inertia tensor at the centre of a square bar along the unit vector `axis`."""
    a = np.asarray(axis, float)
    along, across = mass * 2 * width**2 / 12, mass * (length**2 + width**2) / 12
    return across * np.eye(3) + (along - across) * np.outer(a, a)


def bricard(mbs):
    """IFToMM A04; returns the end time and the measurement at the end."""
    ground = mbs.AddObject(ObjectGround())
    points = [np.array(p, float) for p in ((0, 0, 0), (1, 0, 0), (1, -1, 0), (1, -1, 1), (0, -1, 1), (0, 0, 1))]
    # each rod's frame has x along the rod, from P(k-1) to P(k)
    frames = [np.eye(3), RotationMatrixZ(-0.5 * math.pi), RotationMatrixY(-0.5 * math.pi),
              RotationMatrixZ(math.pi), RotationMatrixZ(0.5 * math.pi)]
    inertia = np.diag([0.001667, 0.084167, 0.084167])
    rods = [mbs.CreateRigidBody(inertia=RigidBodyInertia(1.0, inertia), referencePosition=list(0.5 * (a + b)),
                                referenceRotationMatrix=frame, gravity=[0, -9.81, 0], show=False)
            for a, b, frame in zip(points, points[1:], frames)]
    axes = ([0, 1, 0], [0, 0, 1], [1, 0, 0], [0, 1, 0], [0, 0, 1])
    chain = [ground] + rods
    for j in range(5):
        mbs.CreateRevoluteJoint(itemNumbers=[chain[j], chain[j + 1]], position=list(points[j]), axis=axes[j],
                                show=False)
    # J6 about x: the point, and x_ground . z_rod5 = 0; x_ground . y_rod5 = 0 is the redundant row
    mbs.CreateGenericJoint(itemNumbers=[ground, rods[4]], position=list(points[5]), constrainedAxes=[1, 1, 1, 0, 1, 0],
                           show=False)

    def measure():
        tip = mbs.GetObjectOutputBody(rods[1], exu.OutputVariableType.Position, localPosition=[0.5, 0, 0])
        energy = 0.0
        for rod in rods:
            v = mbs.GetObjectOutputBody(rod, exu.OutputVariableType.Velocity)
            w = mbs.GetObjectOutputBody(rod, exu.OutputVariableType.AngularVelocityLocal)
            y = mbs.GetObjectOutputBody(rod, exu.OutputVariableType.Position)[1]
            energy += 0.5 * v @ v + 0.5 * w @ inertia @ w + 9.81 * y
        return {"value": [float(c) for c in tip], "energy": float(energy)}

    return 10.0, measure


def flyball(mbs):
    """IFToMM A05; returns the end time and the measurement at the end."""
    ground = mbs.AddObject(ObjectGround())
    gravity = [0, 0, -9.81]
    omega = np.array([0, 0, 2 * math.pi])

    def body(mass, inertia, centre):
        centre = np.asarray(centre, float)
        return mbs.CreateRigidBody(inertia=RigidBodyInertia(mass, inertia), referencePosition=list(centre),
                                   initialVelocity=list(np.cross(omega, centre)), initialAngularVelocity=list(omega),
                                   gravity=gravity, show=False)

    shaft = body(0.3, bar_inertia(0.3, 1.0, 0.01, [0, 0, 1]), [0, 0, 0.5])
    mbs.CreateRevoluteJoint(itemNumbers=[ground, shaft], position=[0, 0, 0], axis=[0, 0, 1], show=False)
    slider = body(3.0, 0.005 * np.eye(3), [0, 0, 0.5])
    mbs.CreatePrismaticJoint(itemNumbers=[shaft, slider], position=[0, 0, 0.5], axis=[0, 0, 1], show=False)
    for side in (1, -1):
        hinge = np.array([0.05 * side, 0, 1.0])
        u = np.array([side * math.cos(math.pi / 6), 0, -0.5])
        middle, tip = hinge + 0.5 * u, hinge + u
        com = (0.3 * middle + 5.0 * tip) / 5.3
        inertia = bar_inertia(0.3, 1.0, 0.01, u)
        for mass, at in ((0.3, middle), (5.0, tip)):
            d = at - com
            inertia = inertia + mass * ((d @ d) * np.eye(3) - np.outer(d, d))
        arm = body(5.3, inertia, com)
        mbs.CreateRevoluteJoint(itemNumbers=[shaft, arm], position=list(hinge), axis=[0, 1, 0], show=False)
        mbs.CreateSpringDamper(itemNumbers=[slider, arm], localPosition0=[0.05 * side, 0, 0],
                               localPosition1=list(middle - com), stiffness=8e5, damping=4e4, referenceLength=0.5,
                               show=False)

    def measure():
        return {"value": [float(mbs.GetObjectOutputBody(slider, exu.OutputVariableType.Position)[2])]}

    return 10.0, measure


BETA, OMEGA1, I1, I2, CARDAN_END = math.pi / 6, 10.0, 0.01, 0.02, 2.0


def ratio(theta):
    """Output over input speed of the Hooke's joint, theta = 0 with the input's cross arm in the shafts' plane."""
    return math.cos(BETA) / (1.0 - math.sin(BETA) ** 2 * math.cos(theta) ** 2)


def cardan(mbs):
    """Hooke's joint spinning free; returns the end time and the measurement at the end."""
    ground = mbs.AddObject(ObjectGround())
    e2 = np.array([math.cos(BETA), math.sin(BETA), 0.0])
    shaft1 = mbs.CreateRigidBody(inertia=RigidBodyInertia(1.0, np.diag([I1, 0.05, 0.05])), referencePosition=[0, 0, 0],
                                 initialAngularVelocity=[OMEGA1, 0, 0], nodeType=exu.NodeType.RotationRxyz,
                                 show=False, returnDict=True)
    # the output's frame has x along e2: Rz(30 deg), inertia diag(0.02, 0.05, 0.05) in it
    shaft2 = mbs.CreateRigidBody(inertia=RigidBodyInertia(1.0, np.diag([I2, 0.05, 0.05])), referencePosition=[0, 0, 0],
                                 referenceRotationMatrix=RotationMatrixZ(BETA),
                                 initialAngularVelocity=list(ratio(0.0) * OMEGA1 * e2), show=False)
    input_node, shaft1 = shaft1["nodeNumber"], shaft1["bodyNumber"]
    mbs.CreateRevoluteJoint(itemNumbers=[ground, shaft1], position=[0, 0, 0], axis=[1, 0, 0], show=False)
    mbs.CreateRevoluteJoint(itemNumbers=[ground, shaft2], position=[0, 0, 0], axis=list(e2), show=False)
    # the cross: joint frames are global as drawn; the one row is y of the input . z of the output = 0
    mbs.CreateGenericJoint(itemNumbers=[shaft1, shaft2], position=[0, 0, 0], constrainedAxes=[0, 0, 0, 1, 0, 0],
                           show=False)

    def measure():
        # Rxyz coordinates [x, y, z, phi_x, phi_y, phi_z]; the reference rotation is zero
        return {"value": [float(mbs.GetNodeOutput(input_node, exu.OutputVariableType.Coordinates)[3])]}

    return CARDAN_END, measure


def cardan_reference():
    """The input angle at CARDAN_END from energy conservation."""
    energy = 0.5 * I1 * OMEGA1**2 + 0.5 * I2 * (ratio(0.0) * OMEGA1) ** 2
    dt = lambda theta: math.sqrt((I1 + I2 * ratio(theta) ** 2) / (2.0 * energy))  # 1 / omega1(theta)

    def time_to(theta):
        n = int(theta / (0.5 * math.pi)) + 1  # quarter turns: the integrand has period pi
        edges = [k * theta / n for k in range(n + 1)]
        return sum(quad(dt, a, b, epsabs=1e-14, epsrel=1e-13, limit=500)[0] for a, b in zip(edges, edges[1:]))

    return brentq(lambda theta: time_to(theta) - CARDAN_END, 0.5 * OMEGA1 * CARDAN_END, 2.0 * OMEGA1 * CARDAN_END,
                  xtol=1e-14, rtol=8.9e-16)


MODELS = {"a04": bricard, "a05": flyball, "cardan": cardan}


def solve(model, steps):
    """The measurement at the end with `steps` fixed steps, and the wall time of the solve."""
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    end, measure = MODELS[model](mbs)
    mbs.Assemble()

    settings = exu.SimulationSettings()
    settings.timeIntegration.numberOfSteps = steps
    settings.timeIntegration.endTime = end
    settings.timeIntegration.verboseMode = 0
    settings.timeIntegration.adaptiveStep = False  # fixed steps: fail rather than cut the step
    settings.timeIntegration.newton.relativeTolerance = NEWTON_TOL
    settings.timeIntegration.newton.absoluteTolerance = NEWTON_TOL
    settings.solution.file.write = False  # solutionSettings.writeSolutionToFile, under its 1.13 name
    start = time.perf_counter()
    with redirect_stdout(sys.stderr):  # Exudyn's failure banner stays off the JSON lines
        exu.SolveDynamic(mbs, settings)
    seconds = time.perf_counter() - start
    return measure(), seconds


def point(model, steps, runs=1):
    best, result = float("inf"), None
    for _ in range(runs):
        try:
            result, seconds = solve(model, steps)
        except exu.SolverError as err:
            return {"model": model, "steps": steps, "seconds": None, "value": None, "failed": str(err)}
        best = min(best, seconds)
        if best > 1.0:
            break
    return {"model": model, "steps": steps, "seconds": best, **result}


if __name__ == "__main__":
    args = sys.argv[1:]
    if not args or args[0] not in MODELS:
        sys.exit("usage: spatial_exudyn.py {a04,a05,cardan} [STEPS ...] [--work-precision] [--reference (cardan)]")
    model, rest = args[0], args[1:]
    failed = False
    if "--reference" in rest:
        if model != "cardan":
            sys.exit("--reference: only cardan has a closed-form reference")
        print(json.dumps({"model": "cardan", "reference": cardan_reference()}), flush=True)
    if "--work-precision" in rest:
        counts, runs = SWEEP[model], 3
    else:
        counts = [int(a) for a in rest if not a.startswith("--")]
        if not counts and "--reference" not in rest:
            counts = DEFAULT_STEPS[model]
        runs = 1
    for n in counts:
        line = point(model, n, runs)
        failed |= line["value"] is None
        print(json.dumps(line), flush=True)
    sys.exit(1 if failed else 0)
