//! Spatial mechanisms: rigid bodies in three dimensions joined by lower
//! pairs, beside the planar engine (which a planar problem keeps).
//!
//! Symbols (each used in the files below without being explained again):
//! - body b ≥ 1 has its centre of mass G at r_b and its orientation p_b, a
//!   unit quaternion turning the body as drawn into the body now; R_b = R(p_b).
//!   The ground, body 0, has r = 0 and R = I. As drawn, r_b = G_b and R_b = I.
//! - a point P of body b is r_b + R_b·s′ with s′ = P_drawn − G_drawn (s = R_b·s′
//!   the same arm now); a vector u of body b is R_b·u′, u′ as drawn.
//! - velocities v_b = (ṙ_b, ω_b), ω_b in ground axes; accelerations
//!   (r̈_b, α_b); increments δ_b = (δr_b, δθ_b), applied as r ← r + δr and
//!   p ← exp(δθ)·p: six columns a body.
//! - J_b = R_b·J′_b·R_bᵀ, J′_b the inertia about G in the drawn (ground) axes.
//! - Φ(q, t) = 0 the joints' rows and the inputs' (drivers'), Φ_q its
//!   Jacobian on the increments, so that Φ_q·v = −Φ_t and Φ_q·a = γ.
//!
//! Why unit quaternions for the orientation, and rotation increments for
//! the Jacobian: a quaternion is 4 numbers held unit by one division (a
//! rotation matrix is 9, held orthogonal by a factorization), has no
//! orientation where it fails (Euler angles have gimbal lock), and two
//! compose in 16 products. The Jacobian is taken on the increments δθ, not
//! on the quaternion's 4 components, so no normalization row enters Φ_q:
//! its rank is the mechanism's own, which is what mobility reads, and a
//! body's mass matrix is diag(m·I, J_b) in the velocities the equations of
//! motion are written in (Newton–Euler about G, ground axes).

mod constraints;
pub mod dynamics;
mod energy;
pub mod free_body;
mod kinematics;
mod kinetostatics;
pub mod machine;
mod mobility;
mod model;
mod range;
mod setup;
#[cfg(test)]
mod tests;

pub use constraints::{Rows, coordinate, evaluate};
pub use energy::{energy, kinetic};
pub use kinematics::{Motion, Scaled, assemble, motion, sweep};
pub use kinetostatics::{Actions, Reaction, Wrench, inverse_dynamics};
pub use mobility::{Mobility, candidate_inputs, mobility};
pub use model::{Body, BodyId, Coordinate, Input, Joint, JointKind, Load, LoadLaw, Mechanism, Pose, perpendiculars};
