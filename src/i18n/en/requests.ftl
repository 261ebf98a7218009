# The kinds' requests: what a field of a mechanism, a cam, a rotor, a gear
# train… must be, in English (Spanish in ../es/requests.ftl, same ids and
# arguments).

## A mechanism: its points, bodies, gravity and the errors of its assembly

mechanism-too-many = at most { $max } bodies and { $max } joints
mechanism-coordinates = coordinates must be finite
mechanism-unknown-point = unknown point '{ $name }'
mechanism-unknown-body = unknown body '{ $name }' (the bodies: { $known })
mechanism-unknown-joint = unknown joint '{ $name }'
mechanism-duplicate-body = duplicate body name '{ $name }' (ground is implicit)
mechanism-duplicate-joint = duplicate joint name '{ $name }'
mechanism-cg = a body with mass needs "cg"
mechanism-not-negative = must not be negative
mechanism-gravity = must be [gx, gy], finite
mechanism-vector = must be a finite, non-zero vector [x, y]
mechanism-vector-in-space = three components, a vector in space: a spatial mechanism says "space": "spatial"; in the plane [x, y]
mechanism-not-finite = { $function } is not finite at phi = { $phi } rad
mechanism-negative-inertia = { $function } is negative ({ $value } kg*m^2) at phi = { $phi } rad
mechanism-not-steady = the cycle is not in steady state: the net work of the torques over a cycle is { $net_work } J (largest lobe { $largest_area } J); add a torque with "balance": true or correct the loads
mechanism-newton = the mechanism cannot be assembled at input { $input } (step { $step }): the loop through { $joint } does not close (Newton-Raphson stopped { $residual } short; e.g. a non-Grashof crank asked for a full turn)
mechanism-locked = the mechanism is locked: its joints leave it no degree of freedom (0 by the rank of the joint Jacobian; Grübler's count 3(N - 1) - 2 P_I - P_II = { $grubler }), so no input can move it; remove a joint or make one a slider
mechanism-singular = the mechanism is at a singular position at step { $step } (input { $input }): the constraint Jacobian loses rank
mechanism-singular-cycle = the machine cannot pass { $count } { $count ->
    [one] position
   *[other] positions
    } of its cycle, the first at input { $input }: the mechanism is singular there, or a point runs out to infinity (a slot on the wrong body makes y = d·tan φ), so its reduced inertia I* and torque M* are not finite over the cycle and no flywheel can be sized for it
mechanism-dof = the mechanism has { $dof } degree(s) of freedom but { $inputs } input(s): give one input per degree of freedom (a body with too few joints moves freely; too many inputs conflict)
mechanism-friction = no finite effort drives the mechanism at input { $input } (step { $step }) with this friction (self-locking): it would move only with friction coefficients below { $percent } % of those given
mechanism-unactuated = the actuator(s) { $actuators } cannot drive the inputs at input { $input } (step { $step }): moving the inputs does not move them (their effort would be carried by the joints); choose an actuator the input's motion moves
mechanism-not-finite-result = the computation produced a non-finite number; the input is numerically degenerate

## A mechanism's joints

joint-two-bodies = must name exactly two bodies
joint-same-body = a joint cannot tie a body to itself
joint-at = "at" is required
joint-axis = "axis" is required for this joint type
joint-gear-ratio = a gear needs a finite non-zero "ratio" or "teeth": [z1, z2] (positive)
joint-gear-teeth = a gear with a module needs "teeth": [z1, z2]
joint-gear-bearings = a gear with a module needs a revolute joint (its bearing) on each gear, to find its centre
joint-gear-friction = friction is not modelled for gears
joint-length-prismatic = applies to prismatic joints only (a guide's length)
joint-length-one = give "length" (the guide's, on the first body) or "slider_length" (the block's, on the second), not both
joint-mu = must be a finite number ≥ 0
joint-friction-radius = a revolute joint's friction needs the pin "radius"
joint-radius-revolute = applies to revolute joints only
joint-contact-only = applies to contact joints only

## A contact joint: its curves, and where they touch

contact-needs-curves = a contact joint needs "curves": one per body
contact-two-curves = must hold exactly two curves, the first body's and the second's
contact-point-rolling = a point cannot roll: rolling needs two curves
contact-gap = the curves do not touch as drawn: { $gap } m apart near ({ $x }, { $y }) (they must meet within { $tolerance } m, 1e-6 of the mechanism's size)
contact-cross = the curves cross at ({ $x }, { $y }) at { $angle }° instead of touching (a common tangent): draw them touching
contact-lines = two lines do not make a contact (they touch along their length or cross): use a prismatic joint
contact-spline-points = must hold 4 to { $max } points
contact-no-spline = no spline passes through these points
contact-circle-fills = a circle of radius { $radius } m inside a circle of the same radius touches it all round: it cannot roll or slide in it (make the inner one smaller)
contact-spline-repeated = repeats point { $other }: a spline through a point twice draws a loop nobody drew; give each point once (a closed spline joins its last point to its first by itself)
contact-polar-positive = must be positive over the whole turn: r({ $angle }°) = { $value }
contact-cam-ccw = a cam curve's program runs counter-clockwise: write it in the cam's ccw angle
contact-cam-segments = a cam curve takes a program of segments
contact-cam-offset = must be less than the pitch circle's radius (base + roller)
contact-cam-oscillating = a cam curve is made for a translating follower: for an oscillating one, draw the profile its design gives (POST /v1/cams: the samples' profile_point) as a closed spline

## A mechanism's dimensions

dimensions-too-many = at most { $max } dimensions
dimensions-one-of = give exactly one of "distance", "angle", "x", "y" and "on"
dimensions-between = give the two points "between" [A, B] the point "on" lies between
dimensions-ratio = give "ratio", the fraction of A→B at which the point lies (0.5: the midpoint)
dimensions-value = give the dimension's "value" (a length, or an angle for "angle")
dimensions-two-points = must name two points
dimensions-unknown-point = unknown point '{ $name }' (dimensions join named points)
dimensions-positive = must be positive
dimensions-conflict = the dimensions cannot all hold: this one and those named with it (off by { $residual } at the least change)
dimensions-reversed = the sketch draws this line the other way round: swap its points, or the angle by 180°

## A mechanism's loads

load-too-many = at most { $max } loads
load-needs = a { $type } load needs "{ $field }"
load-not-this-type = does not apply to this load type
load-ground = a load on the ground does nothing; name a moving body

## The points a request follows

track-too-many = at most { $max } points
track-pin = '{ $point }' is the pin of the slot '{ $slot }': its two bodies move differently there; give {"{"}"name": "{ $point }", "body": ...{"}"}
track-no-body = '{ $point }' is on no body (no joint or centre of mass is there); give {"{"}"name": "{ $point }", "body": ...{"}"}

## A mechanism's inputs

input-ground = the ground does not move: name a moving body
input-joint-kind = an input must be a revolute, prismatic or contact joint (the arc length along its curve)
input-on-ground = '{ $point }' is on the ground: it does not move
input-direction-of-point = belongs to a "point" input
input-none = name the input's "joint", or a "point" and its "direction", or a "body"
input-one-of = name one of "joint", "point" (with "direction") or "body"
input-needs-direction = a "point" input needs its "direction" [x, y]
input-direction = must be a finite, non-zero [x, y]
input-flywheel-shaft = a flywheel's input is its shaft: a revolute "joint"
input-shaft-revolute = the flywheel's shaft must be a revolute joint
input-shaft-rotation = the flywheel's shaft turns: name a revolute joint, or a cylindrical one with "coordinate": "rotation"
input-name-shaft = name the shaft, a revolute joint
input-count = give 1 to 10 inputs
input-steps = must be 1 to { $max }
input-same-steps = all inputs share the steps of the first
input-actuators = give one actuator per input: { $inputs } input(s), { $actuators } actuator(s)
input-own-actuator = each input needs its own actuator: '{ $name }' drives another
input-actuator-kind = an actuator must be a revolute joint (a torque) or a prismatic one (a force)
input-needs-end = an input in metres (a prismatic joint, a point on a guide, a contact's arc length) needs "end" (or "steps": 1, one position)
input-speed = "speed" is required

## Kinetostatics: what it asks of its outputs, and the positions a mechanism cannot reach

kinetostatics-points-track = "points" follows the points of "track": give them
balance-fraction = the reciprocating fraction is between 0 and 1, not { $value }
balance-unknown-body = no body is named '{ $body }'
balance-not-linkage = counterweights are found for a four-bar (crank, coupler, rocker) or a slider-crank (crank, rod, slider), each link joined by revolute joints and the slider by a prismatic joint to the frame: this mechanism is neither
balance-not-pivoted = '{ $body }' is not pivoted to the frame: counterweights go on the crank and, of a four-bar, the rocker
balance-missing = a four-bar's full force balance needs a counterweight on '{ $body }' too
balance-missing-crank = a slider-crank's counterweight goes on its crank, '{ $body }'
balance-twice = '{ $body }' is named twice
kinetostatics-at = { $what } at input { $value } (step { $step } of { $steps }): { $why }
kinetostatics-at-start = { $what } at input { $value } (step { $step } of { $steps }, the start): { $why }
kinetostatics-on-the-way = { $said }; on the way there from the drawn configuration (input "reference") it stops closing at { $value }
kinetostatics-value-rad = { $value } rad = { $degrees } deg
kinetostatics-not-assembled = the mechanism cannot be assembled
kinetostatics-loop = the loop through { $joint } does not close (Newton-Raphson ends { $residual } short); check start, end and the lengths ({ $why })
kinetostatics-loop-crank = a non-Grashof crank, say, cannot make a full turn
kinetostatics-loop-slider = a slider driven to or through a dead centre, say, where the linkage's position is no function of the slider's: start and end short of it, or drive the crank; or a follower past where its curve holds it
kinetostatics-singular = the mechanism is at a singular position
kinetostatics-dead-centre = a dead centre or toggle the input cannot pass (the constraint Jacobian loses rank)
kinetostatics-friction = the joints' friction locks the mechanism
kinetostatics-self-locking = no finite effort drives it there with this friction (self-locking): it would move only with friction coefficients below { $percent } % of those given
kinetostatics-unactuated = the actuators cannot drive the inputs
kinetostatics-unactuated-why = moving the inputs does not move { $actuators } there, so its effort would be carried by the joints; name in "actuators" a joint the input's motion moves

## Direct dynamics: its two forms, how a run ends, and a run that cannot be made

dynamics-machine-or-reduced = give either "machine" or the reduced form, not both
dynamics-reduced-or-machine = give either the reduced form ("torques" with "reduced_inertia") or "machine", not both
dynamics-machine-required = required: give "machine" (a mechanism and its loads) or the reduced form "torques" with "reduced_inertia"
dynamics-samples = must be 2 to { $max }
dynamics-torques-count = must hold 1 to { $max } items
dynamics-inertia-required = required with "torques": the reduced inertia I*(φ), kg·m²
dynamics-at-most-seconds = must be at most { $max } s
dynamics-max-duration = applies only with "until_angle" (the longest a run to an angle may take): a run of a "duration" ends at it
dynamics-until-initial = must differ from the initial angle
dynamics-duration-or-angle = give either "duration" or "until_angle", not both
dynamics-angle-or-duration = give either "until_angle" or "duration", not both
dynamics-duration-required = required: give "duration" (how long to run) or "until_angle" (the input angle at which to stop)
dynamics-conserve-energy = needs every load to have a potential (springs, constant forces and torques): /machine/loads/{ $load } is { $what }
dynamics-varying-force = a force whose magnitude varies
dynamics-varying-torque = a torque whose value varies
dynamics-damper = a damper
dynamics-sliding-friction = friction in dynamics is modelled at a rolling contact ("rolling": true: it rolls while |tangential| ≤ mu·normal and slips otherwise); a sliding contact slides freely: leave it out
dynamics-joint-friction = joint friction is not supported in dynamics
dynamics-not-applicable = does not apply to dynamics (the motion is the result)
dynamics-initial-once = give the first input's state once: in "initial" or in its "start"/"speed"
dynamics-speed-constant = must be a constant: the input's speed at t = 0
dynamics-inertia-not-positive = the reduced inertia is not positive at phi = { $phi } rad
dynamics-integration = the integration failed at t = { $t } s: { $reason }
dynamics-initial = the initial state cannot be assembled: { $reason }
dynamics-step-too-small = the step size fell below round-off: the motion runs away there (a torque without bound, an inertia near zero)
dynamics-too-many-steps = more than { $steps } steps
dynamics-not-finite = the derivative is not finite
dynamics-singular-motion = the equations of motion are singular here (a singular position)
dynamics-start-singular = the start is a singular position of the inputs (a dead centre or toggle)
dynamics-start-dof = the mechanism has { $dof } degree(s) of freedom but { $inputs } input(s) name its coordinates
dynamics-start-no-mass = the equations of motion are singular at the start: some motion of the inputs moves no mass (bodies without mass or inertia where the motion needs them)

## A cam: its follower, program, size, speed and dynamics

cam-base-or-size = give "base_radius" or "size", not both
cam-base-required = give the cam's "base_radius", or "size" to find the smallest
cam-size = give "max_pressure_angle" and/or "min_curvature_radius"
cam-size-any = every base radius meets it, down to 0 (a cam with no body): a program that never rises has no pressure angle to keep down; give the base radius (base_radius) instead, or size it by a least radius of curvature (min_curvature_radius)
cam-no-base = no base radius meets it: ask for { $asked ->
        [angle] a larger pressure angle
        [rho] a smaller radius of curvature
       *[both] a larger pressure angle or a smaller radius of curvature
    }
cam-no-base-arm = no base radius the arm can start its follower from meets it: ask for { $asked ->
        [angle] a larger pressure angle
        [rho] a smaller radius of curvature
       *[both] a larger pressure angle or a smaller radius of curvature
    }, or move the pivot or lengthen the arm
cam-no-base-best = no base radius meets it: the least largest pressure angle any of them gives is { $angle }°, at a base radius of { $base } mm; ask for at least that, or move the follower's offset
cam-no-base-arm-best = no base radius the arm can start its follower from meets it: the least largest pressure angle any of them gives is { $angle }°, at a base radius of { $base } mm; ask for at least that, or move the pivot or lengthen the arm
cam-speed = must be greater than 0 (the sense is "direction")
cam-roller-radius = a roller follower needs its "roller_radius"
cam-roller-only = applies to a roller follower only
cam-not-oscillating = does not apply to an oscillating follower
cam-not-translating = does not apply to a translating follower
cam-needs-pivot = an oscillating follower needs its "pivot" (the distance from the cam centre to its pivot)
cam-needs-arm = an oscillating follower needs its "arm" (from its pivot to the roller's centre, or to the face's line)
cam-not-negative = must not be negative
cam-mu = must be a finite number ≥ 0
cam-friction-flat = applies to a flat face (a roller rolls; a knife's friction is not modelled)
cam-lift-closed = must return to its start over a turn: s(0) = { $start }, s(360°) = { $end }
cam-segments-count = must hold 1 to { $max } segments
cam-unknown-law = unknown law '{ $law }': one of { $laws }
cam-needs-lift = a segment that moves needs its "lift" at its end
cam-after-previous = must be after the end of the segment before, { $end } rad ({ $degrees }°)
cam-dwell = a dwell holds the lift of the segment before
cam-full-turn = the last segment must end at 360°
cam-closed = the last segment must end at lift 0
cam-gap = segment { $segment } starts at { $start } rad where the one before ends at { $expected } rad
cam-jump = segment { $segment } starts at lift { $from } where the one before ends at { $expected }
cam-offset = the offset { $offset } m is not inside the pitch circle (radius { $pitch } m): the follower's axis misses the cam
cam-reach = an arm of { $arm } m pivoted { $pivot } m from the cam centre cannot start the follower on the circle of radius { $radius } m (the base circle, plus a roller's radius, or a face's distance from the pivot)
cam-below-base = the lift goes below the base circle: s = { $lift } at θ = { $theta } rad

## A rotor: its body, bearings, spin and the instants asked

rotor-components = components must be finite numbers
rotor-bearings = two different, finite positions along the axis
rotor-symmetric = the body must be symmetric about its spin axis (its inertia would change in the frame)
rotor-inertia-finite = must be finite numbers
rotor-principal = principal moments [{ $first }, { $second }, { $third }] are not those of a body
rotor-angles-or-times = give at most one of "angles" and "times"
rotor-instants = give 1 to { $max } values
rotor-never = the frame never reaches this angle
rotor-never-alias = the frame never reaches this angle (angles count its turns from the start, in the sense it turns); it is at this position first at { $degrees }° ({ $radians } rad): write that

## A gear: its module, teeth, pressure angle and proportions

gear-teeth = must be a number from 1 to 10000
gear-pressure-angle = must be between 0 and 1.5 rad
gear-share = must be between 0 and 5 modules
gear-overflow = a module of { $module } m overflows the gear's radii (beyond double precision)
gear-inside-base = { $radius } m is inside the base circle ({ $base } m): there is no involute there
gear-thickness = the thickness at { $radius } m cannot be computed in double precision

## A gear train: its members, meshes, speeds and torques

train-members-count = give 1 to { $max } members
train-frame-or-repeat = '{ $name }' is the frame or repeats a member
train-unknown-member = unknown member '{ $name }' (or 'ground')
train-meshes-count = give 1 to { $max } meshes
train-teeth = must be a number of teeth from 1 to 100000
train-mesh-wheels = a mesh needs two different wheels on members other than its carrier
train-frame-torque = the frame's torque is not an unknown of the train
train-locked = the train cannot move: its meshes lock every member (0 degrees of freedom); an odd loop of external meshes, such as three wheels meshing in a ring, turns each wheel both ways at once
train-speeds = the train has { $dof } degree(s) of freedom: give exactly { $dof } speed(s) that fix it (given { $given })
train-inconsistent = the given speeds cannot all hold: the meshes contradict them (residual { $residual } rad/s)
train-torques = the train has { $dof } degree(s) of freedom: ask for exactly { $dof } unknown torque(s) (asked { $asked })
train-torques-singular = the unknown torques cannot be found: those members do not take independent power
train-degenerate = the train's numbers overflow (teeth, ratios or speeds too large to compute with)

## Equivalent masses of a link

equivalent-not-negative = must not be negative
equivalent-cg = must be [x, y], finite
equivalent-points = give 1 to { $max } points
equivalent-coordinates = coordinates must be finite
equivalent-too-far = the points are too far from G to compute with (their squared distances overflow double precision)

## Mobility: a drawn mechanism or counted pairs

mobility-one-of = give either "mechanism" (without inputs) or "counts"
mobility-bodies = must be 1 to { $max } (the ground counted)
mobility-pairs = must be 0 to { $max }
mobility-unknown-class = unknown class '{ $class }' for a { $space } count (one of { $known })
mobility-planar = planar
mobility-spatial = spatial

## A Function of the cycle angle: its form, segments, table and CSV

function-one-of = give exactly one of "expr", "segments", "table" or "csv"
function-table-only = applies to a table only
function-parse = expression does not parse: { $why } (at character { $position })
function-segments-count = must hold 1 to { $max } segments
function-segment-inside = segment [{ $from }, { $to }] must lie inside [0, period = { $period }]
function-to-after-from = "to" must be greater than "from"
function-overlaps = overlaps segment { $other }
function-angles-count = must hold 1 to { $max } angles
function-rows = "angle" has { $angles } rows but "value" has { $values }
function-repeat-first = the row at the first angle + period must repeat the first value
function-increasing = angles must be strictly increasing
function-angles-period = angles must lie in [0, period = { $period })
function-spline-rows = a spline needs at least 3 rows
function-csv-row = row { $row }: { $why }
function-csv-numbers = row { $row }: '{ $angle }', '{ $value }' are not two finite numbers
function-csv-rows = more than { $max } rows (the limit on a table)
function-csv-empty = no rows of numbers: give two columns, angle and value

## A request's constants

constants-too-many = at most { $max } constants (has { $has })
constants-not-name = '{ $name }' is not a name: letters, digits and _, not starting with a digit (e.g. F, r_crank)
constants-name-length = a name has at most { $max } characters
constants-reserved = '{ $name }' is taken by the expressions (phi, t, omega, pi, e and the functions)

## An expression

expression-derivative-too-large = its derivative of order { $order } would have more than { $max } terms: write the expression more compactly (a power such as sin(theta)^16 rather than a product of equal factors)
expr-too-long = expression has { $length } characters; the maximum is { $max }
expr-malformed-number = malformed number '{ $text }'
expr-unexpected-character = unexpected character '{ $char }'
expr-empty = empty expression
expr-decimal-comma = '{ $number }' is written with a decimal comma: in an expression a number takes a point (0.05), and a comma parts a function's arguments
expr-after-end = unexpected { $token } after the end of the expression
expr-too-deep = expression nested deeper than { $max } levels
expr-ends-early = expression ends where a value was expected
expr-unexpected = unexpected { $token } where a value was expected
expr-needs-parentheses = function '{ $name }' needs parentheses
expr-none = none
expr-unknown-name = unknown name '{ $name }' (variables here: { $variables }; constants: { $constants })
expr-takes-one = 1 argument
expr-takes-two = 2 arguments
expr-takes-at-least-two = at least 2 arguments
expr-arity = function '{ $name }' takes { $takes }, got { $got }
expr-unknown-function = unknown function '{ $name }' (known: { $known })
expr-expected = expected '{ $op }'
expr-token-number = number { $value }
expr-token-name = name '{ $name }'
expr-token-operator = '{ $op }'
dynamics-budget = the compute budget of { $seconds } s ran out at t = { $t } s of simulated time after { $steps } steps; the motion is too fast for the tolerance (a stiff spring?) or the run too long: ask for a shorter run or a looser tolerance{ $hint }
dynamics-budget-dop853 = ; for a long smooth run at a tight tolerance, "integrator": "dop853" takes far fewer steps

## Balancing: the rotor's masses or body, and the correction planes
balancing-masses-or-rotor = give the unbalance either as "masses" (point masses) or as "rotor" (a rotor request's body), one of them
balancing-masses-count = give 1 to { $max } point masses
balancing-planes-count = give one correction plane (static balancing) or two (dynamic balancing)
balancing-planes-apart = the two correction planes must be at different z
balancing-reactions-need = the bearing forces need both the speed and the bearings' z: give "{ $field }" too (or neither)
mechanism-spatial-point = three coordinates, a point in space: a spatial mechanism says "space": "spatial" (or a decimal comma split a number: 0,5 is written 0.5 or "0,5")
joint-spatial-type = a pair of spatial mechanisms: give the mechanism "space": "spatial"
joint-spatial-friction = friction is not modelled in the spatial pairs
mechanism-inertia-planar = a planar body's inertia is one number, I_G about its cg
mechanism-inertia-spatial = a body in space needs its inertia tensor about the cg: [Ixx, Iyy, Izz] or the 3×3 matrix
mechanism-inertia-symmetric = must be a symmetric 3×3 matrix of finite numbers
mechanism-inertia-physical = no rigid body has these moments: each principal moment is at least 0 and at most the sum of the other two
mechanism-planar-point = a point of a spatial mechanism has three coordinates [x, y, z]
mechanism-spatial-dimensions = a spatial mechanism is drawn by its points' coordinates: "dimensions" are for the plane
mechanism-gravity-spatial = must be [gx, gy, gz], finite
mechanism-vector-spatial = must be a finite, non-zero vector [x, y, z]
joint-universal-axes = a universal joint takes "axes": [a, b], a fixed in the first body and b in the second
joint-universal-perpendicular = a universal joint's two axes are perpendicular as drawn
joint-planar-type = a planar pair: a spatial mechanism's pairs are revolute, prismatic, cylindrical, spherical, universal and sphere_in_cylinder
joint-not-spatial = not for the pairs of a spatial mechanism
mechanism-spatial-not-here = a spatial mechanism is answered by /v1/mobility, /v1/kinetostatics, /v1/dynamics and as a flywheel's machine (/v1/flywheel)
input-coordinate-planar = a planar joint has one coordinate: "coordinate" is for the joints of a spatial mechanism
input-spatial-joint = an input of a spatial mechanism is a joint's coordinate: give "joint" (and "coordinate" for a cylindrical one)
input-cylindrical-coordinate = a cylindrical joint has two coordinates: say which, "coordinate": "rotation" or "slide"
input-spatial-coordinate = this joint has no such coordinate: a revolute turns (rotation), a prismatic slides (slide), a cylindrical does both, a spherical turns about its "axis"
kinetostatics-not-spatial = not for a spatial mechanism yet
