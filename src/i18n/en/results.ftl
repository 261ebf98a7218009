# What a result says about itself: its warnings and how its accuracy was
# estimated, in English (Spanish in ../es/results.ftl, same ids and
# arguments).

## Any kind

warning-constant-unused = the constant { $name } is not used by any expression of the request
warning-at-field = { $pointer }: { $said }

## A time integration that stopped

warning-ode-step-too-small = the step size fell below round-off at t = { $t } s
warning-ode-too-many-steps = more than { $steps } steps
warning-ode-not-finite = the derivative is not finite at t = { $t } s

## Flywheel

accuracy-flywheel = M* integrated piecewise between its breakpoints: adaptive Gauss-Kronrod 7/15 for expressions, exact (Simpson on each polynomial piece) for tables; sign changes bracketed on 1024 samples per cycle and located by Brent's method; exact inertia from the extrema of (1±eps/2)^2 I*(phi) - F(phi) at piece ends and stationary points (closed form when I* is constant); check by Dormand-Prince 5(4) time integration of the equation of motion
warning-train-assembly = the planet { $planet } cannot assemble with one module: its ring has { $ring } teeth, but the sun ({ $sun }) and the planet need a ring of { $fits } (z_ring = z_sun + 2 z_planet for a simple planet)
warning-flywheel-net-work = the net work over a cycle is { $net } J, within the tolerance; the loads are used as given
warning-flywheel-check = the time-simulation check did not complete: { $why }
warning-flywheel-degenerate = M* is identically zero and I* constant: the speed is constant for any inertia, so no flywheel is needed
warning-flywheel-no-disk = no disk: the flywheel inertia needed is { $inertia } kg*m^2 (the machine's own inertia already keeps the irregularity within the request)

## A mechanism

warning-sketch-larger = the sketch's points are about { $ratio } times as far apart as the dimensions place them: numbers without a unit, in `points` and in a body's `cg`, are read in metres (for millimetres write "40 mm"), and a centre of mass sketched so lies that much farther from its body
warning-sketch-smaller = the sketch's points are about { $ratio } times closer together than the dimensions place them: check the dimensions' units ("100 mm", not "100 m")
warning-dimensions-free = the dimensions leave some points free to move: they stay as near the sketch as the others allow
warning-span = { $from } to { $to }
warning-at-time = t = { $t } s
warning-contact-off-end = contact { $name }: the contact runs off the end of an open curve at { $at }: the results there are not a contact's (extend the curve)
warning-contact-jumped = contact { $name }: the contact jumped at { $at } to a point far from where it was followed to (another lobe): the follower leaves the curve it was on and lands elsewhere, a jump the motion there does not show
warning-contact-cut = contact { $name }: the bodies cut into each other at { $at } (each step's `penetration` says how deep): the contact the equations follow there cannot be, and none outside both bodies was found (a rolling contact cannot jump to another lobe; a cam too hollow for its follower)
warning-contact-slipping = contact { $name } slips from { $at }: μN does not cover the friction rolling would need there, and kinetic friction acts instead (each sample's contact says `state`)
warning-contact-overlap = contact { $name }: the curves overlap around the contact at { $at }: the bodies would touch elsewhere there (the follower jumps to another lobe: a flat face on a concave stretch, a roller in a tighter hollow); the results there follow a contact that cannot be
warning-contact-separates = contact { $name }: the normal force is negative at { $at }: the bodies would separate there (a follower jump, a disk leaving its track) unless something holds them together
warning-contact-slips = contact { $name }: rolling needs more friction than mu = { $mu } gives at { $at } (see mu_required): it would slip there

## Direct dynamics

accuracy-dynamics = { $integrator } with dense output, events located by Brent's method on it; work { $work }{ $repeated }
accuracy-work-quadrature = by adaptive quadrature over the angle
accuracy-work-power = as the integrated power
accuracy-integrator-stiff = { $name } (the explicit pair chosen first found the model stiff at t = { $t } s: its steps were held by stability, not accuracy; the run was made again from the start)
accuracy-repeated = ; the run ended at its angle after more steps than a job keeps ({ $mib } MiB of them) and was made again to the end time it found, for the samples (the steps and evaluations count both runs)
accuracy-dynamics-mechanism = { $integrator } on the index-1 equations of motion [M Φ_qᵀ; Φ_q 0], { $form }; the state projected onto Φ = 0 and Φ_q·q̇ = 0{ $energy } after every step; in LU, rows of Φ_q within 1e-5 of dependence held at singular positions, dependent ones dropped; events by Brent's method on the dense output; work as the integrated power{ $repeated }
accuracy-form-sparse-held = solved by the range-space method (sparse LDLᵀ of Φ_q M⁻¹ Φ_qᵀ; at singular positions the combinations left by rows whose pivot sines fall from 1e-3 to 3e-4 held, by LU within ~1e-8 of dependence)
accuracy-form-sparse = solved by the range-space method (sparse LDLᵀ of Φ_q M⁻¹ Φ_qᵀ) away from singular positions and by LU near them (the steps failed where the sparse form held the folds)
accuracy-form-lu = solved by LU
accuracy-energy-held = { " " }and, the loads having a potential, onto T + V = E₀ ({ $held } of { $steps } steps)
warning-dynamics-not-reached = the angle { $angle } was not reached within { $time }
warning-dynamics-contact-open-at-start = the contact '{ $name }' pulls at the start: its normal force is below 0 there, and a contact only pushes — the bodies part at once (gravity or the loads draw them apart): the run stops at t = 0
warning-dynamics-contact-opens = the contact '{ $name }' opens at { $t }: its normal force falls to 0 and the bodies would separate (what follows is not the motion of these joints): the run stops there
warning-dynamics-unexpected-guard = the run stopped where the model changes nothing (a guard crossed where the model has none)
warning-dynamics-turns-unlisted = the first { $listed } turns are listed as events; { $more } more were crossed after them and are not listed
warning-dynamics-branch-left = the energy balance fails from { $t } (residual { $residual }, over { $bound }), after the motion passed close to a singular position at { $at }: the mechanism may have left its branch there (folded into another assembly), and its motion from then on is not reliable; see machine.near_singular and samples[].energy_residual
warning-dynamics-integrator-replaced = the integrator asked, "{ $asked }", met a singular position at { $t }, where its steps leave the mechanism's branch (it could fold into another assembly): the run was made again from the start with Dormand-Prince 5(4) ("dopri5"), which holds it on its branch; see accuracy.integrator_replaced_at
warning-dynamics-near-singular = the motion passed close to singular positions (the joint Jacobian nearly lost rank) { $count } time(s), the first at { $first }: the mechanism was kept on its branch; see machine.near_singular

## Kinetostatics

accuracy-kinetostatics = body coordinates; { $assembly }; velocities and accelerations from the constraint Jacobian; multipliers of Phi_q^T lambda = Q - M q'' for reactions and driving actions, checked against virtual power
accuracy-assembly-closed-form = positions in closed form (a crank and dyads: circle-circle and circle-line intersections, on the branch drawn), confirmed by Newton-Raphson
accuracy-assembly-newton = Newton-Raphson assembly with continuation of up to third order
warning-redundant-constraints = { $count } redundant constraint(s): the reactions of joints { $joints } are not determined by equilibrium and are reported as null

## Cams

accuracy-cam = the laws in closed form and their derivatives to the jerk; the pitch curve and profile from the follower's position in the cam's frame, their curvature from exact derivatives (a flat face's ρ = R_b + s + s″; an oscillating face's as the envelope of its lines); forces from the follower's equation along its axis (about its pivot, oscillating)
warning-cam-velocity = velocity
warning-cam-acceleration = acceleration
warning-cam-sense = the cam's sense of rotation ("direction") was not given: it turns counter-clockwise ("ccw"); with an offset or an oscillating follower the sense changes the pressure angle and the radius found
warning-cam-fundamental-law = the fundamental law of cam design is broken at { $at }°: the { $what } jumps by { $jump } { $unit }/rad^{ $order }
warning-cam-undercut = undercut: the profile folds on itself near { $at }° (radius of curvature { $rho } m): a larger base circle or a smaller roller
warning-cam-undercut-flat = undercut: the profile folds on itself near { $at }° (radius of curvature { $rho } m): a larger base circle
warning-cam-pressure-translating = the pressure angle reaches { $max }° at { $at }° (over { $limit }° for a translating follower): a larger base circle, or an offset
warning-cam-pressure-oscillating = the pressure angle reaches { $max }° at { $at }° (over { $limit }° for an oscillating follower): a larger base circle, or another pivot
warning-cam-separation = the follower would leave the cam at { $at } (negative contact force)
warning-dynamics-chatter = the contacts changed between rolling and slipping { $count } times by { $t } (they chatter): the run stops there

## Mobility

warning-mobility-grubler = Grübler's count gives { $grubler } but the drawing moves with { $dof }: { $count } constraint(s) repeat what the others impose (a special geometry, such as parallel links), so the count does not see them
mobility-counts-inputs = { $inputs ->
        [one] one input coordinate describes
       *[other] { $inputs } input coordinates describe
    } the motion (with one, any coordinate that moves serves: an angle, a slide); which joints can serve together depends on the geometry, which counts alone cannot tell: send the mechanism's drawing for its candidate inputs

## A check of students' answers

check-no-answer = no answer
check-not-a-number = { $value } is not a number
check-wrong-dimension = '{ $text }' is in { $found }, where the answer is in { $unit }
check-unreadable = '{ $text }' is not a number or a quantity ({ $why })
check-unread = { $name }: { $why }.
check-value = { $value }{ $unit }
check-given = { $text } = { $si }
check-rule-zero-level = ±{ $value } (the zero level)
check-rule-absolute = ±{ $value }
check-rule-relative = { $percent } %
check-rule-sigfigs = { $count } significant figures
check-correct-revealed = { $name }: correct ({ $given }, within { $within } of { $expected }).
check-correct = { $name }: correct (within { $within }).
check-off = , { $percent } % off
check-wrong-revealed = { $name }: { $given } is not within { $within } of the expected { $expected }{ $off }.
check-wrong = { $name }: { $given } is not within { $within } of the expected value.
check-with-slip = { $feedback } { $slip }
check-slip-other-value = It matches { $other } of the result: that value was given for { $name }?
check-slip-reaction-sign = It has the opposite sign: the reaction on the other body of the joint? (The result gives the force on the joint's second body.)
check-slip-sign = It has the opposite sign.
check-slip-degrees = It matches the value in degrees: radians are expected.
check-slip-rpm = It matches the value in rpm: rad/s are expected (1 rpm = 2π/60 rad/s).
check-slip-times-2pi = It is 2π times the expected value.
check-slip-over-2pi = It is the expected value divided by 2π.
check-slip-power-of-ten = It is 10^{ $k } times the expected value: a unit prefix (mm for m, kN for N)?
check-summary = { $passed } of { $total } answers within tolerance (checked by mechdyn { $version }).

## Rotors, gears, gear trains, equivalent masses

accuracy-rotor = Newton F = [dQ/dt]_rel + Ω×Q and Euler M_G = [dK_G/dt]_rel + Ω×K_G in the frame's axes; bearing forces and driving moment from the six equilibrium equations, closed form
accuracy-gear-train = Willis' formula per mesh relative to its carrier; torques from virtual power over a basis of the train's virtual motions (SVD null space)
warning-gear-pointed = the tooth is pointed before { $radius } m: its thickness there would be { $thickness } m
warning-gear-module-metres = a module of { $module } m: a bare number is SI (metres); for { $module } mm write "{ $module } mm" (modules over { $plausible } m are rare)
warning-equivalent-incomplete = no masses at these points match mass, centre of mass and inertia together; the least-squares fit leaves a relative residual of { $residual }
warning-equivalent-not-unique = the points do not determine the masses; the smallest set (minimum norm) is given

## Balancing
accuracy-balancing-static = static balancing in one plane: the correction C₁ = −U cancels the static unbalance U = Σ m·r·e^(iθ); the couple is left; closed form
accuracy-balancing-dynamic = dynamic balancing in two planes: C₁ + C₂ = −U and (z₂ − z₁)·C₂ = −D(z₁), D(z₁) = Σ m·r·(z − z₁)·e^(iθ); closed form
warning-balancing-planes-close = the correction planes are only { $gap } m apart, 1/{ $ratio } of the rotor's length of { $span } m (its masses, bearings and planes): the two corrections grow as 1/(z₂ − z₁), here to { $mass } kg; place the planes farther apart
warning-balancing-couple-left = one correction plane removes the static unbalance only: a dynamic unbalance of { $couple } kg·m² is left (give two planes to remove it)
accuracy-global-made = a bound of the global error: 1.5 times the largest difference of the angle over the samples from the same run at a tolerance a hundred times tighter (global_error), or the summed local error estimates where larger
accuracy-global-none = the summed local error estimates, which ignore how errors grow along the motion (a chaotic or long run can be far more off): no run at a tolerance a hundred times tighter was made, as { $why }
accuracy-global-to-angle = the run ends at an angle, at another instant each time
accuracy-global-floor = the tolerance is already near the limit of double precision
accuracy-global-budget = the run took over a quarter of the compute budget (raise --job-seconds, or shorten the run)
accuracy-global-failed = the tighter run failed or stopped elsewhere
accuracy-kinetostatics-spatial = positions by Newton–Raphson on the joints' rows (quaternions turned by rotation increments) to |Φ| ≤ 1e-12 of the drawing's size, velocities and accelerations from Φ_q·v = −Φ_t and Φ_q·a = γ, reactions and efforts from the Newton–Euler equations with Φ_qᵀ·λ (least-norm where rows repeat); the virtual power of the actions checks them
warning-redundant-constraints-spatial = { $count } redundant constraint(s): equilibrium does not determine the reactions of joints { $joints }; each is given as the share of least norm, marked "determinate": false
accuracy-dynamics-spatial = the Newton–Euler equations of every body about its centre of mass with the joints' rows, [M Φ_qᵀ; Φ_q 0] solved by LU at every evaluation (orientations as unit quaternions, the Jacobian on rotation increments), integrated over the bodies' positions, quaternions and velocities; after every step the quaternions made unit and the state projected onto Φ = 0 and Φ_q·v = 0; events by Brent's method on the dense output; work as the integrated power; reactions from the Newton–Euler equations of the motion found
warning-dynamics-redundant-spatial = { $count ->
        [one] one constraint row repeats others at the start (as in Bricard's linkage) and was
       *[other] { $count } constraint rows repeat others at the start (as in Bricard's linkage) and were
    } left out of the equations of motion; the reactions they share are given as the share of least norm, marked "determinate": false
