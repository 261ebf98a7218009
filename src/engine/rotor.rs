//! A rigid body carried by a frame that turns about a fixed axis x on two
//! bearings D and E (E takes the axial thrust), possibly spinning relative
//! to the frame (seed 003: a disk on a bent arm).
//!
//! Symbols (vectors in the frame's rotating axes x'y'z' unless "fixed"):
//! Ω = Ω₀ + γt the frame's speed about x, φ = φ₀ + Ω₀t + ½γt² its angle;
//! ω_r the body's spin relative to the frame (constant); ω = Ω i + ω_r;
//! r_G the centre of mass from the origin O on the axis; I_G the inertia
//! tensor about G (constant in the frame's axes: the body is symmetric
//! about its spin axis, or does not spin). Then
//!
//! ```text
//! V_G = Ω i × r_G,   Q = m V_G,   K_G = I_G ω,   T = ½ m V_G² + ½ ω·I_G ω
//! F = [dQ/dt]_rel + Ω × Q = m (γ i × r_G + Ω i × V_G)
//! M_G = [dK_G/dt]_rel + Ω × K_G = I_G γ i + Ω i × I_G ω,   M_O = M_G + r_G × F
//! ```
//!
//! The bearings and the driving moment M_x supply the wrench (F, M_O):
//! dynamic parts from the motion, static parts against the weight m·g;
//! the gyroscopic moment is Ω i × I_G ω_r. Fixed axes are the rotating
//! ones turned back by φ about x: y = y' cos φ − z' sin φ, z = y' sin φ + z' cos φ.

use nalgebra::{Matrix3, Vector3};

/// The body, its frame and bearings, in SI.
#[derive(Clone, Debug, PartialEq)]
pub struct Rotor {
    pub mass: f64,
    /// I_G in the frame's axes.
    pub inertia: Matrix3<f64>,
    /// r_G from O, frame axes.
    pub cg: Vector3<f64>,
    /// ω_r, frame axes.
    pub spin: Vector3<f64>,
    /// x of bearing D and of bearing E (the thrust bearing), D ≠ E.
    pub bearings: [f64; 2],
    /// g in the fixed axes.
    pub gravity: Vector3<f64>,
    /// Ω₀, γ and φ₀ of the frame.
    pub speed: f64,
    pub acceleration: f64,
    pub angle: f64,
}

/// Forces on D and E and the driving moment about x that supply a wrench.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Support {
    pub d: Vector3<f64>,
    pub e: Vector3<f64>,
    pub driving_moment: f64,
}

/// Everything at one instant; vectors in the rotating axes, `*_fixed` in the fixed ones.
#[derive(Clone, Debug, PartialEq)]
pub struct RotorState {
    pub t: f64,
    pub angle: f64,
    pub speed: f64,
    pub momentum: Vector3<f64>,
    /// K about G and about O.
    pub angular_momentum_g: Vector3<f64>,
    pub angular_momentum_o: Vector3<f64>,
    pub kinetic_energy: f64,
    pub gyroscopic_moment: Vector3<f64>,
    pub dynamic: Support,
    pub static_: Support,
    pub total: Support,
    /// The total bearing forces in the fixed axes.
    pub total_fixed: [Vector3<f64>; 2],
    pub dynamic_fixed: [Vector3<f64>; 2],
    pub static_fixed: [Vector3<f64>; 2],
}

impl Rotor {
    /// The state at time t.
    pub fn at(&self, t: f64) -> RotorState {
        let omega = self.speed + self.acceleration * t;
        let angle = self.angle + self.speed * t + 0.5 * self.acceleration * t * t;
        let i = Vector3::x();
        let (m, r, ig) = (self.mass, self.cg, self.inertia);
        let w = omega * i + self.spin;
        let v_g = (omega * i).cross(&r);
        let q = m * v_g;
        let k_g = ig * w;
        let force = m * (self.acceleration * i.cross(&r) + (omega * i).cross(&v_g));
        let moment_g = ig * (self.acceleration * i) + (omega * i).cross(&k_g);
        let dynamic = self.support(force, moment_g + r.cross(&force));
        let g = to_rotating(self.gravity, angle) * m;
        let static_ = self.support(-g, -r.cross(&g));
        let total = Support {
            d: dynamic.d + static_.d,
            e: dynamic.e + static_.e,
            driving_moment: dynamic.driving_moment + static_.driving_moment,
        };
        let fixed = |s: &Support| [to_fixed(s.d, angle), to_fixed(s.e, angle)];
        RotorState {
            t,
            angle,
            speed: omega,
            momentum: q,
            angular_momentum_g: k_g,
            angular_momentum_o: k_g + r.cross(&q),
            kinetic_energy: 0.5 * m * v_g.norm_squared() + 0.5 * w.dot(&k_g),
            gyroscopic_moment: (omega * i).cross(&(ig * self.spin)),
            total_fixed: fixed(&total),
            dynamic_fixed: fixed(&dynamic),
            static_fixed: fixed(&static_),
            dynamic,
            static_,
            total,
        }
    }

    /// R_D + R_E = F, x_D i × R_D + x_E i × R_E + M_x i = M_O (R_D·i = 0).
    fn support(&self, f: Vector3<f64>, m_o: Vector3<f64>) -> Support {
        let [xd, xe] = self.bearings;
        let span = xe - xd;
        let ey = (m_o.z - xd * f.y) / span;
        let ez = (-m_o.y - xd * f.z) / span;
        Support { d: Vector3::new(0.0, f.y - ey, f.z - ez), e: Vector3::new(f.x, ey, ez), driving_moment: m_o.x }
    }
}

/// Fixed → rotating axes at angle φ about x.
fn to_rotating(v: Vector3<f64>, phi: f64) -> Vector3<f64> {
    let (s, c) = phi.sin_cos();
    Vector3::new(v.x, c * v.y + s * v.z, -s * v.y + c * v.z)
}

/// Rotating → fixed axes at angle φ about x.
fn to_fixed(v: Vector3<f64>, phi: f64) -> Vector3<f64> {
    let (s, c) = phi.sin_cos();
    Vector3::new(v.x, c * v.y - s * v.z, s * v.y + c * v.z)
}
