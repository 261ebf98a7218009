# mechdyn's messages in English: every text a person reads.
# Each message has its Spanish in ../es/service.ftl with the same arguments
# (src/i18n/tests.rs fails otherwise).

## Problem documents: titles

problem-malformed-json = The body is not valid JSON
problem-unsupported-media-type = Unsupported content type
problem-payload-too-large = Request body too large
problem-invalid-request = The request is not a valid problem
problem-invalid-query = Invalid query parameters
problem-invalid-table = The CSV table is not valid
problem-job-not-found = Job not found
problem-not-found = Not found
problem-template-not-found = Template not found
problem-conflict = The name is taken
problem-in-progress = The same request is being answered
problem-interrupted = The job was interrupted
problem-job-not-done = The job has no result
problem-no-such-part = No such part of the result
problem-no-such-plot = No such plot of the job
problem-no-such-file = No such file of the job
problem-no-such-solution = The job has no worked solution
problem-method-not-allowed = Method not allowed
problem-compute-budget = The job ran out of its compute budget
problem-result-too-large = The result would be too large
problem-saturated = The service is saturated
problem-storage-full = The service's storage is full
problem-database-unavailable = The database is unavailable
problem-unauthorized = Missing or wrong bearer token
problem-request-timeout = The request's body did not arrive in time
problem-length-required = The body's length is required
problem-internal = Internal server error
problem-job-memory = The job ran out of its memory
problem-compute-failed = The job's computation failed

## Problem documents: details

detail-malformed-json = the body is not valid JSON: { $why }
detail-unsupported-media-type = the content type must be application/json
detail-unsupported-table = the content type must be text/csv or application/json
detail-payload-too-large = the body is larger than the limit of { $limit } bytes
detail-invalid =
    { $count ->
        [one] 1 invalid field
       *[other] { $count } invalid fields
    }
detail-bad-query = invalid query parameters
detail-bad-table =
    { $count ->
        [one] 1 error in the CSV table
       *[other] { $count } errors in the CSV table
    }
detail-not-found = no job with id '{ $id }'
detail-no-part = job '{ $id }' has no part of its result at '{ $pointer }'
detail-no-plot = job '{ $id }' has no plot '{ $name }' (its plots: { $known })
detail-no-plot-none = job '{ $id }' has no plot '{ $name }' (it has no plots)
detail-no-file = job '{ $id }' has no file '{ $name }' (its files: { $known })
detail-no-file-none = job '{ $id }' has no file '{ $name }' (it has none)
detail-no-solution = job '{ $id }' is a { $kind } job, which has no free bodies to solve (a kinetostatics job has)
detail-no-template = no template with id '{ $id }' (GET /v1/templates lists them)
text-as-is = { $why }
text-nothing = { "" }
text-value-unit = { $value } { $unit }
detail-in-progress = a request with Idempotency-Key '{ $key }' is still being answered; retry after 1 s
detail-failed = job '{ $id }' failed and has no result: GET /v1/jobs/{ $id } says why (its `problem`)
detail-not-done = job '{ $id }' is { $status }: its result is not there yet; retry after 1 s
detail-interrupted = the job was claimed { $times } times and each time its replica stopped before it ended; it was not tried again
detail-no-route = no such resource
detail-method-not-allowed = method not allowed
detail-result-too-large = the result would be larger than the limit of { $limit } bytes on a result
detail-saturated = the service is saturated ({ $reason }); retry after { $seconds } s
saturated-slots = every job slot and queue place is taken
saturated-stopping = the service is stopping
saturated-queue = the jobs ahead in the queue did not finish in time
saturated-memory = too many large answers are being sent
saturated-bodies = too many request bodies are being received
saturated-anonymous = the share of computation for requests without the token is taken: ask again shortly, or sign in
saturated-deferred = { $waiting } deferred jobs are waiting, the most this service keeps
saturated-connections = the service holds its most connections ({ $max }); retry in a second
detail-storage-full = { $what }: the service's storage is full; reads still work, and writes resume once space returns
detail-unavailable = the database is unavailable; retry later
detail-unauthorized = this service stores and deletes jobs only for a request with "Authorization: Bearer <token>": every POST and DELETE, and a GET of a template's job or page that would store a new job
detail-private-jobs = this service keeps its stored jobs to the holders of its token: send "Authorization: Bearer <token>", or sign in once at /signin in a browser; a template's values (GET /v1/templates/{"{"}id{"}"}/result/…) and variants need no token
detail-length-required = an HTTP/1.0 POST needs a Content-Length header: its body's end cannot be told otherwise
detail-internal = internal error; the x-request-id header of this answer finds it in the service's log
detail-job-memory = the job needed more than the { $mib } MiB of memory a job may use; ask for fewer steps, samples or bodies
detail-compute-failed = the job's computation stopped without an answer: a fault of the service, which the x-request-id header of this answer finds in its log; no other job was affected

## Quantities and units

unit-malformed = '{ $text }' is not a number followed by a unit, e.g. "300 rpm"
unit-thousands = '{ $text }' has a thousands separator, which is not read: write { $plain }
unit-unknown = unknown unit '{ $unit }'; known units: { $known }
unit-unknown-hint = unknown unit '{ $unit }'; did you mean { $hint }? Known units: { $known }
unit-wrong-dimension = a value in { $found } where { $expected } is expected
unit-none = 1 (dimensionless)

## A field of a request

field-unknown = unknown field
field-unknown-known = unknown field (the fields here: { $known })
field-missing = required field is missing
field-finite = must be finite
field-positive = must be greater than 0
field-too-long = must be at most { $max } characters (has { $has })
field-not-angle = '{ $text }' is neither an angle (e.g. "90 deg") nor a constant expression (e.g. "7*pi/4")
field-angle-degrees = '{ $text }' is not an angle as written: degrees are written "{ $n }°" or "{ $n } deg"
field-bare-angle = the bare number { $value } is read in radians ({ $degrees }°); for degrees write "{ $value }°"
field-bare-length = the bare number { $value } is read in metres; for millimetres write "{ $value } mm"
field-expression = '{ $text }' is an expression, not a quantity: write it as {"{"}"expr": "{ $text }"{"}"}
field-expected = expected { $expected }, got { $got }
field-between = must be between { $min } and { $max }
field-between-open = must be greater than { $min } and less than { $max }
field-at-most = must be at most { $max }
field-at-most-characters = must be at most { $max } characters
field-samples = must be 0 (no table) or at least 2
field-less-than = must be less than { $other }
field-finite-nonzero = must be a finite, non-zero number

## The query of a URL

query-unknown = unknown parameter (known: { $known })
query-decimal = must be point or comma
query-angles = must be rad or deg
query-twice = is given more than once: give it once
query-format = '{ $value }': must be csv or json

## A template's parameters

parameter-unknown = no parameter { $name } in template { $template } (its parameters: { $known })
parameter-not-quantity = '{ $text }' is neither a number nor a quantity: { $why }
parameter-finite = must be finite
parameter-below = { $text } is below the least value, { $min }{ $unit }
parameter-above = { $text } is above the largest value, { $max }{ $unit }
parameter-not-choice = { $text } is not one of { $choices }
parameter-dimension = '{ $text }' is in { $found }, where { $expected } is expected
parameter-own-unit = the parameter's unit { $unit }: { $why }
parameter-nameless = a parameter without a name (`?=...`)

## CSV tables

csv-ragged = row { $row } has { $cells } cells for { $columns } columns
csv-ragged-comma = row { $row } has { $cells } cells for { $columns } columns; a decimal comma in a CSV separated by commas is written in quotes ("0,02"), or the columns separated by ;
csv-columns = row { $row } has { $cells } columns; give two: angle, value
csv-columns-comma = row { $row } has { $cells } columns; give two: angle, value; a decimal comma in a CSV separated by commas is written in quotes ("0,02"), or the columns separated by ;

## JSON as a person reads it

json-number = a number
json-whole = a whole number, 0 or more
json-integer = a whole number
json-bool = true or false
json-text = a text in quotes
json-array = an array [...]
json-object = an object {"{"}...{"}"}
json-struct = an object {"{"}...{"}"} with named fields
json-array-of = an array of { $n } numbers
json-tuple = an array of { $n } items
json-got-array = an array
json-got-object = an object
json-got-text = the text { $text }
json-got-number = the number { $value }
json-got-items = { $n } item(s)
json-variant = unknown variant { $got }, expected { $expected }
json-syntax = { $cause } { $at }{ $hint }
json-at = at line { $line }, column { $column }
json-at-near = at line { $line }, column { $column }, near `{ $near }`
json-hint-nan = ; NaN and Infinity are not JSON numbers: give a finite number
json-hint-quotes = ; JSON strings take double quotes
json-hint-comma = ; is there a comma before it?
json-hint-decimal-comma = ; a decimal comma splits a JSON number: write { $dot }, or the text "{ $comma }"
json-eof-list = EOF while parsing a list
json-eof-object = EOF while parsing an object
json-eof-string = EOF while parsing a string
json-eof-value = EOF while parsing a value
json-expected-colon = expected `:`
json-expected-comma-bracket = expected `,` or `]`
json-expected-comma-brace = expected `,` or `{ "}" }`
json-expected-value = expected value
json-expected-ident = expected ident
json-invalid-escape = invalid escape
json-invalid-number = invalid number
json-number-out-of-range = number out of range
json-key-not-string = key must be a string
json-trailing-comma = trailing comma
json-trailing-characters = trailing characters
json-too-deep = recursion limit exceeded
json-control-character = control character (\u0000-\u001F) found while parsing a string
json-not-utf8 = the body is not UTF-8
json-unreadable = the body could not be read: { $why }
json-variant-one-of = unknown variant { $got }, expected one of { $expected }
json-variant-either = unknown variant { $got }, expected { $a } or { $b }
json-expect-quantity = a number (SI) or a text "VALUE UNIT" such as "300 rpm"
json-expect-function = a number, a quantity text, or an object with expr, segments or table
json-expect-program = a list of segments or an object {"{"}"lift": ...{"}"}
json-expect-inputs = an input object or a list of them
json-expect-track = a point's name or an object {"{"}"name", "body", "at"{"}"}
json-expect-point = a point's name or coordinates [x, y] (in space [x, y, z])
json-expect-inertia = a moment of inertia, or in space [Ixx, Iyy, Izz] or a 3×3 matrix
json-expect-length = a length: a number in m, or with its unit ("8 cm")
json-expect-fewer = fewer items (a decimal comma splits a JSON number in two: 0,45 is written 0.45, or as the text "0,45")

## Pages

page-nav-home = Jobs and templates
page-nav-docs = API documentation
page-nav-openapi = OpenAPI document
page-footer = mechdyn { $version }: machine dynamics, every job stored. These pages need no JavaScript.
page-back = Back to the jobs and templates
page-home-intro = Machine dynamics: flywheels, kinetostatics, direct dynamics, rotors, gears and cams. Every job is stored; open one to see its values, accuracy and plots, or start from a template's form.
page-templates = Templates
page-col-template = template
page-col-kind = kind
page-col-problem = problem
page-recent = Recent jobs
page-no-job = No job yet: open a template, or POST a request:
page-signin-title = Sign in
page-signin-intro = The jobs stored on this service are kept to the holders of its token. Give the token once: this browser then keeps a cookie that stands for it (30 days, or until you sign out). A template's form, and its values by URL, need no token; without it, a job computed from the form is shown but not stored.
page-signin-token = Token
page-signin-button = Sign in
page-signin-wrong = That is not this service's token.
page-signed-in = Signed in.
page-signout-button = Sign out
page-not-stored = This job was computed for this page and stored nowhere: a browser that has not signed in keeps no job on this service. Sign in to store the jobs you compute, and read them again by their address.
page-col-job = job
page-col-label = label
page-col-created = created (UTC)
page-col-time = engine time, or status
page-for-programs = For programs
page-jobs-json = jobs (JSON)
page-templates-json = templates (JSON)
page-job-title = { $kind } job
page-job-title-label = { $kind } job: { $label }
page-job = job
page-created = created
page-label = label
page-engine = engine
page-csv-table = CSV table
page-every-value = every value (CSV)
page-plots-json = plots (JSON)
page-values = Values
page-long-tables = Tables of the result (their rows are in the CSV):
page-rows = { $n } rows
page-request = Request
page-request-sent = The request as sent
page-failed = Failed: { $title }
page-waiting = This job is { $status }; this page shows its result once it is done.
page-accuracy = Accuracy and time
page-accuracy-check-relative-difference = check against a second method (relative difference)
page-accuracy-constraint-drift = drift of the constraints
page-accuracy-energy-form-time-difference = energy form against time form (difference)
page-accuracy-energy-residual = energy residual
page-accuracy-estimated-error = estimated error
page-accuracy-estimated-relative-error = estimated relative error
page-accuracy-function-evaluations = function evaluations
page-accuracy-integrator = integrator
page-accuracy-max-constraint-residual = largest constraint residual
page-accuracy-max-friction-iterations = most friction iterations
page-accuracy-max-newton-iterations = most Newton iterations
page-accuracy-method = method
page-accuracy-quadrature-error = quadrature error
page-accuracy-steps = steps
page-accuracy-virtual-power-residual = virtual power residual
page-computed-in = Computed in { $time } of engine time.
page-no-accuracy = This kind reports no accuracy estimate of its own.
page-warnings = Warnings
page-plots = Plots
page-draw-at = Draw the mechanism at step
page-draw = Draw
page-more-plots = More plots of this job:
page-col-quantity = quantity (JSON pointer)
page-col-value = value
page-col-unit = unit
page-full-value = the full value
page-template-meta = template { $id } · a { $kind } job
page-form-help = A number is read in the unit beside its name; a quantity with its own unit ("300 rpm", "4 %", "20°") is read in that unit; a field left blank keeps its default.
page-compute = Compute
page-form-url = The same job by URL, for a spreadsheet or a script:
page-form-url-json = (JSON), or one number:
page-name-value = NAME=VALUE
page-pointer = POINTER
page-one-of = one of { $choices }
page-from-to = from { $min } to { $max }{ $unit }
page-at-least = at least { $min }{ $unit }
page-at-most = at most { $max }{ $unit }

## Plots

plot-phi-shaft = angle of the reference shaft φ
plot-torque-shaft = torque on the reference shaft
plot-work-since = work since φ = 0, W(φ)
plot-speed-shaft = speed of the reference shaft ω
plot-reduced-inertia = reduced inertia I*(φ)
plot-flywheel-torque = Reduced torque M*(φ) and the lobes of work A_i
plot-flywheel-work = Work W(φ) over the cycle and the energy fluctuation ΔE
plot-flywheel-speed = Speed ω(φ) over the cycle with the exact inertia
plot-flywheel-wittenbauer = Wittenbauer's diagram: W against I*(φ), and the tangents that give the inertia
plot-flywheel-other-torques = M_b − M*: the other torques, sign changed
plot-flywheel-balance = balance torque M_b = { $value } N·m
plot-flywheel-lobes =
    { $n ->
        [one] 1 lobe; shaded green where the torques give work (A_i > 0), red where they take it
       *[other] { $n } lobes; shaded green where the torques give work (A_i > 0), red where they take it
    }
plot-flywheel-speed-note = ε = (ω_max − ω_min)/ω_a = { $eps }; I = { $inertia } kg·m² (exact)
plot-wittenbauer-curve = W against I* over the cycle
plot-tangent-max = tangent of slope ω_max²/2, ω_max = { $value } rad/s
plot-tangent-min = tangent of slope ω_min²/2, ω_min = { $value } rad/s
plot-wittenbauer-note = The tangents meet at (−I, −T₀) = ({ $x } kg·m², { $y } J), off this view: I = { $inertia } kg·m² (exact), T₀ = { $t0 } J
plot-joint = joint { $joint }
plot-most-joints = the { $most } largest of { $total } joints; each joint's own plot shows the rest
plot-reactions-to-scale = joint reactions to scale: the largest, { $force } N, drawn { $length } m long
plot-free-body = Free body of { $body } ({ $number }), step { $step }
plot-free-body-sums = ΣFx = { $fx } N, ΣFy = { $fy } N, ΣM_G = { $moment } N·m
plot-free-body-sums-spatial = isometric view, { $up } up; ΣF = ({ $forces }) N, ΣM_G = ({ $moments }) N·m
plot-moments-to-scale = couples as moment vectors (double head): the largest, { $moment } N·m, drawn { $length } m long
plot-forces-to-scale = forces to scale: the largest, { $force } N, drawn { $length } m long
plot-ks-driving = Driving action against the input
plot-ks-reactions = Joint reactions |R| against the input
plot-ks-polar = Polar diagram of the reaction at joint { $joint }
plot-ks-reduced-inertia = Reduced inertia I*(φ)
plot-ks-reduced-torque = Reduced torque M*(φ) of the loads
plot-ks-mechanism = The mechanism at a step, with its joint reactions to scale
plot-ks-reduced-torque-line = M*(φ), the loads reduced to the input
plot-ks-input-angle = input angle at joint { $joint }
plot-ks-input = input at joint { $joint }
plot-ks-driving-force = driving force
plot-ks-driving-torque = driving torque
plot-ks-at-joint = at joint { $joint }
plot-ks-mean = mean { $value }
plot-ks-reaction-force = reaction force |R|
plot-ks-force-on-by = force on { $on } by { $by } over the sweep
plot-ks-origin = origin (0, 0)
plot-ks-first-step = first step
plot-ks-first-step-at = first step (input { $value })
plot-ks-polar-note = the force is the vector from the origin to the curve; largest { $value } N
plot-ks-step = step { $step } of 0 to { $last }: input { $value }
plot-flywheel-motion = The machine in motion over a cycle, at the flywheel's speed
plot-flywheel-motion-at = φ = { $phi }° · ω = { $omega } rad/s
plot-cursor = step { $step }
plot-ks-motion = The mechanism in motion over the sweep
plot-ks-motion-at = input { $value } · step { $step }
plot-dyn-motion = The mechanism in motion over the run
plot-dyn-motion-at = t = { $t } s · sample { $step }
plot-motion-note-paths = one loop in { $seconds } s; dashed: the paths
plot-motion-note = one loop in { $seconds } s; dashed: the paths; reactions to one scale
plot-ks-shaking = Shaking force on the frame (polar diagram)
plot-ks-shaking-moment = Shaking moment on the frame against the input
plot-ks-shaking-moment-axis = shaking moment about the origin
plot-ks-shaking-force = −Σ m·a_G over the sweep
plot-ks-shaking-balanced = with the counterweights
plot-time = time t
plot-angle = angle φ
plot-speed = speed ω
plot-dyn-angle = Angle against time, with the events
plot-dyn-speed = Speed against time, with the events
plot-dyn-phase = Phase portrait: speed against angle
plot-dyn-energy = Energy residual against time
plot-dyn-reactions = Joint reactions |R| against time
plot-dyn-mechanism = The mechanism at a sample, over the paths of its joints
plot-dyn-mechanism-spatial = The mechanism at a sample, with its joint reactions to scale
plot-dyn-path = Path of joint { $joint }
plot-dyn-phase-line = ω against φ
plot-dyn-residual = energy residual (W − ΔT)/max(|W|, |ΔT|, T₀, T, T_peak)
plot-dyn-residual-line = integrated power W against the kinetic energy T
plot-dyn-residual-note = at the end { $value }: how far the integration's energy balance drifts
plot-dyn-input-at = { $symbol }(t) at joint { $joint }
plot-dyn-turn = turn { $n }
plot-dyn-slip = slip { $joint }
plot-dyn-roll = roll { $joint }
plot-dyn-end = end
plot-dyn-note =
    { $turns ->
        [one] 1 turn
       *[other] { $turns } turns
    }; energy residual { $residual }; estimated error of the angle { $error } rad
plot-dyn-note-few =
    { $turns ->
        [one] 1 turn
       *[other] { $turns } turns
    }; energy residual { $residual }; estimated error of the angle { $error } rad; only { $samples } samples, joined by straight lines (ask for more: samples)
plot-dyn-at-start = { $joint } at t = 0
plot-dyn-at-end = { $joint } at the end
plot-dyn-path-line = path of joint { $joint }
plot-dyn-sample = sample { $step } of 0 to { $last }: t = { $t } s; dashed: the joints' paths
plot-dyn-sample-spatial = sample { $step } of 0 to { $last }: t = { $t } s
plot-isometric = isometric view, { $up } up; dashed: the joints' axes; arrows: the reactions to scale
plot-cam-svaj = Lift, velocity, acceleration and jerk against the cam angle (each over its peak)
plot-cam-profile = The cam's profile, pitch curve and base circle, the follower at the largest pressure angle
plot-cam-pressure = Pressure angle and radius of curvature against the cam angle
plot-cam-forces = Contact force and cam torque against the cam angle
plot-cam-angle = cam angle θ
plot-cam-pressure-title = Pressure angle and radius of curvature
plot-cam-pressure-line = pressure angle φ (°)
plot-cam-curvature-line = profile's radius of curvature ρ (mm)
plot-cam-forces-title = Contact force and cam torque
plot-cam-contact-force = contact force (N)
plot-cam-torque = cam torque (N·m)
plot-cam-svaj-title = SVAJ diagram
plot-cam-over-peak = each over its peak
plot-cam-law-ends = { $law } ends
cam-law-dwell = dwell
cam-law-harmonic = harmonic
cam-law-cycloidal = cycloidal
cam-law-polynomial-345 = polynomial 3-4-5
cam-law-polynomial-4567 = polynomial 4-5-6-7
cam-law-modified-sine = modified sine
cam-law-modified-trapezoid = modified trapezoid
plot-cam-profile-title = Cam profile (cam's frame, x: the follower's direction at θ = 0)
plot-cam-profile-title-pivot = Cam profile (cam's frame, x: towards the follower's pivot)
plot-cam-profile-line = profile
plot-cam-base = base circle R_b = { $value } mm
plot-cam-pitch = pitch curve
plot-cam-follower-worst = follower at the largest pressure angle
plot-cam-worst-at = φ = { $phi }° at θ = { $theta }°
plot-rotor-bearings = Bearing reactions over the states, in fixed axes
plot-rotor-frame-angle = angle of the frame
plot-rotor-force = force on the body
plot-rotor-bearing = bearing { $name }
plot-rotor-note = total (static and dynamic) reaction of each bearing; components that stay zero are left out
plot-balancing-vectors = Unbalance and corrections (m·r, seen along the axis)
plot-balancing-unbalance = static unbalance U
plot-balancing-correction = correction at z = { $z } m
plot-balancing-note = vectors m·r from the axis, to one scale; each correction in its plane
plot-gear-tooth = The involute teeth, from the computed geometry
plot-gear-profile = tooth profile
plot-gear-pitch = pitch circle r = { $value } mm
plot-gear-base = base circle r_b = { $value } mm
plot-gear-tip = tip r_a = { $tip } mm, root r_f = { $root } mm
plot-gear-thickness = s = { $value } mm on the pitch circle
plot-gear-note = z = { $z }, pressure angle { $alpha }° at the pitch circle; below the base circle the flank is drawn radial
plot-gear-note-pointed = z = { $z }, pressure angle { $alpha }° at the pitch circle; below the base circle the flank is drawn radial; the flanks meet before the tip circle (a pointed tooth)

## The kinds of job, named for people

kind-flywheel = flywheel
kind-kinetostatics = kinetostatics
kind-dynamics = direct dynamics
kind-cams = cam design
kind-rotor = rotor
kind-balancing = balancing
kind-gears = gears
kind-gear-train = gear train
kind-equivalent = equivalent masses
kind-mobility = mobility
kind-check = check

## The flywheel's request

flywheel-speeds = give exactly one of: mean_speed + irregularity, mean_speed + min_speed, min_speed + max_speed
flywheel-torques-count = must hold 1 to { $max } items (or give a machine)
flywheel-one-balance = at most one item may have "balance": true
flywheel-value-or-balance = give either "value" or "balance": true
flywheel-disk-density = a disk sized by its thickness needs its density
flywheel-disk = give exactly one of rim_speed, radius or thickness

## A check's request, a class's CSV, a study

field-finite-not-negative = must be a finite number ≥ 0
field-whole-not-negative = must be a whole number ≥ 0
query-true-false = must be true or false
query-values-none = give the values to answer, e.g. ?values=inertia_exact,energy_fluctuation
csv-not-utf8 = the CSV is not UTF-8 text
csv-header = the CSV's header: { $why }
csv-unreadable = the CSV: { $why }
csv-too-many-rows = more than { $max } rows in one request
template-not-drawable = template { $id } has no parameter with choices or with min, max and step: every variant would be its defaults
template-seed-range = variants are numbered 0 to 2^63 − 1: seed + count − 1 must not exceed it
check-reference-none = name the reference: template (with parameters or variant), kind with request, or job
check-reference-more = give one reference only: template, kind with request, or job
check-kind-alone = kind needs the request
check-request-alone = request needs its kind
check-parameters-alone = parameters belong to a template
check-variant-alone = a variant belongs to a template
check-variant-range = variants are numbered 0 to 2^63 − 1
check-parameters-and-variant = give parameters or a variant, not both
check-answers-none = at least one answer: {"{"}"POINTER": value{"}"}
check-answers-too-many = at most { $max } answers (has { $count })
check-answered-twice = { $pointer } is answered twice
check-required-too-many = at most { $max } pointers
check-tolerance-unanswered = no answer has this pointer
check-sigfigs = must be 1 to 15
check-kind-unknown = '{ $name }' is not a kind of job to check against (one of { $known })
check-template-unknown = no template '{ $id }' (GET /v1/templates lists them)
check-job-offline = a stored job needs the service's store
class-student-column = the CSV needs a `student` column
class-answers-none = no answer columns: name each by its pointer into the result, e.g. inertia_exact
class-reserved = a reserved name, not a pointer into the result
class-variant-and-parameters = give a variant or the student's parameters, not both
class-variant-none = no variant (and no parameters) for this student
class-variant-number = '{ $text }' is not a variant number (0 to 2^63 − 1)
class-row-no-student = row { $row } has no student
class-student-twice = student { $student } appears twice
check-no-value = the { $kind } result has no value at { $pointer }
check-not-graded = { $pointer } is not a number ({ $value }): only numbers are graded

## A template as a client writes it

template-kind-unknown = unknown kind '{ $kind }' (known: { $known })
template-request-object = must be a request object of that kind
template-name-slug = '{ $name }' is not a slug: lower-case letters, digits and -, at most 64
template-parameters-too-many = at most { $max } parameters
template-no-parameter = no parameter { $name } in this template
template-parameter-name = '{ $name }' is not a name: letters, digits and _, not starting with a digit
template-parameter-reserved = '{ $name }' is reserved in a template's URL ({ $reserved })
template-pointer-scalar = must point at a number or a text of the request
template-pointer-missing = { $pointer } is not in the request
template-min-above-max = min { $min } is above max { $max }
template-no-statement = the template has no statement quantity { $name }
template-statement-too-many = at most { $max } quantities of the statement
template-statement-pointer = "of" is a JSON pointer into the result, such as "/balance_torque"
template-statement-sign = "sign" is 1 or -1
template-derived-too-many = at most { $max } derived values
template-derived-expression = the derived value's expression does not read: { $why }
template-derived-finite = the derived value comes out as { $value }, not a finite number

## Headers, labels, lists

field-one-of = must be one of { $known }
field-integer-between = must be an integer from { $min } to { $max }
header-ascii = must be visible ASCII
header-characters = must be 1 to { $max } characters
header-key-reused = this key was sent before with another request (method, path, query or body); use a new key for a new request
label-control = must not hold control characters or bidirectional overrides (it holds { $code })
label-empty = must not be empty

## A part of a result in another unit

unit-part-not-number = the part at { $pointer } is not a number: it has no unit to convert
unit-part-no-unit = the part at { $pointer } has no unit to convert
unit-part-no-single-unit = the part at { $pointer } is in { $unit }, which has no single unit to convert from
unit-target = '{ $target }': { $why }
unit-part-in = '{ $target }' is a unit of { $found }; the part at { $pointer } is in { $unit }
unit-part-in-of = '{ $target }' is a unit of { $found }; the part at { $pointer } is in { $unit }, a unit of { $expected }
query-whole-number = '{ $text }': must be a whole number from 0
query-step = '{ $text }': must be a whole number from 0 to { $last }
parameter-pointer-missing = points at { $pointer }, not in the request

## A result too large

size-would-be = the result would be { $size } ({ $bytes } bytes), over the limit of { $limit } on a result (MECHDYN_MAX_RESULT_BYTES)
size-would-be-about = the result would be about { $size } ({ $bytes } bytes), over the limit of { $limit } on a result (MECHDYN_MAX_RESULT_BYTES)
size-would-be-at-least = the result would be at least { $size } ({ $bytes } bytes), over the limit of { $limit } on a result (MECHDYN_MAX_RESULT_BYTES)
size-too-large = { $size }; { $advice }
size-advice = at { $each } each, { $name } ≤ { $fit } would fit{ $also }
size-advice-at-most = at { $each } or more each, no more than { $fit } { $name } could fit{ $also }
size-also-events = { " " }(events: one per turn, fewer with a shorter run)
size-also-table = { " " }(0 for no table)
size-also-outputs = ; or ask for fewer "outputs" (every body's kinematics is the largest)

## A plot's step

plot-no-steps = { $step }: this job draws no mechanism, so it has no steps to choose
plot-singular-step = { $step }: the mechanism is at a singular position at this step, where no force is solved; choose a step beside it
plot-steps = { $step }: the job has { $count ->
        [one] 1 step (0)
       *[other] { $count } steps (0 to { $last })
    }

## Conflicts, budgets, slow bodies

template-builtin = '{ $id }' is a built-in template
template-exists = a template named '{ $id }' exists
detail-over-budget = the compute budget of { $seconds } s ran out ({ $progress }); ask for fewer steps, samples or bodies, or a looser tolerance
progress-flywheel-sampling = stopped while sampling M* and I*
progress-flywheel-work = stopped while integrating the work of each torque
progress-flywheel-crossings = stopped while locating the crossings and lobes of M*
progress-flywheel-exact = stopped while finding the exact inertia
progress-flywheel-time-check = stopped while checking by time integration
progress-flywheel-table = stopped while sampling the table
progress-late = the solution was complete but late
progress-assembling-machine = while assembling the machine
progress-assembled = the mechanism was assembled at { $step } of { $of } positions
progress-candidates = the inputs were sought as far as joint { $joint } of { $of }
progress-cam-size = { $tried } base radii had been tried in the search for the smallest
rows-budget-spent = not computed: this request's compute budget of { $seconds } s went on the rows before; ask again for the rest (the rows done are stored and found again at once) or send fewer rows
progress-friction = the joints' friction was being iterated at position { $step }
progress-approach = the mechanism had moved { $step } of { $of } steps from its drawing towards the first position
progress-cam-lift = the lift had been evaluated at { $angle } of { $of } angles
progress-reading = while the request was being read: its sketch assembled, its contacts placed, its inputs laid out
progress-stopped = it did not stop by itself, and was stopped from outside
detail-request-timeout = the request's body did not arrive in time: { $read } bytes in { $seconds } s; this service needs a body to keep arriving at { $rate } bytes/s once { $grace } s have passed

## The worked solution (free bodies)

page-solution-title = Worked solution, step { $step }
page-solution-input = Input:
page-solution-job = The job
page-solution-previous = Previous step
page-solution-next = Next step
page-solution-numbering = The bodies, numbered
page-solution-order = The order of the solution
page-solution-order-why = Each group's equations give its unknowns once the groups before it are solved: from the last group of the mechanism to its input.
page-solution-group = { $bodies }: its equations give { $unknowns }
page-solution-diagram = Free-body diagram of { $body }, its forces to one scale
page-solution-action = Action
page-solution-from = From
page-solution-at = Point (m)
page-solution-reaction = reaction
page-solution-inertia = inertia
page-solution-weight = weight
page-solution-driving = driving
page-solution-load = load
page-solution-power = Virtual power
page-solution-power-why = The power of every action at this step: by the principle of virtual power they add up to zero (a joint's two sides cancel but for its friction).
page-solution-reactions = reactions (their friction)
page-solution-total = total
page-solution-link = Worked solution (free bodies)
page-solution-at-step = Solve step
page-solution-solve = Solve
