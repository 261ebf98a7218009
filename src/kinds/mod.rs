//! The calculation kinds, one folder each with everything about it: the
//! request and result types, their conversion with a pointer for every
//! error, the computation, the table, the units of the result's fields, the
//! plots as chart data, the OpenAPI examples. [`mechanism`] is the
//! mechanism's wire form the mechanism kinds share. Each kind is written
//! against the contract ([`crate::kind`]) only; [`register`] lists them.

pub mod balancing;
pub mod cams;
pub mod dynamics;
pub mod equivalent;
pub mod flywheel;
pub mod gear_train;
pub mod gears;
pub mod kinetostatics;
pub mod mechanism;
pub mod mobility;
pub mod rotor;

use crate::kind::Register;

/// Every kind, in the order of the documentation: a new kind is its folder
/// and one line here.
pub fn register(r: &mut impl Register) {
    r.kind::<flywheel::Flywheel>();
    r.kind::<kinetostatics::Kinetostatics>();
    r.kind::<dynamics::Dynamics>();
    r.kind::<gears::Gears>();
    r.kind::<gear_train::GearTrain>();
    r.kind::<equivalent::EquivalentMasses>();
    r.kind::<rotor::RigidRotor>();
    r.kind::<balancing::Balancing>();
    r.kind::<mobility::Mobility>();
    r.kind::<cams::Cams>();
}
