//! The calculation kinds, one folder each with everything about it: the
//! request and result types, their conversion with a pointer for every
//! error, the computation, the table, the units of the result's fields, the
//! plots as chart data, the OpenAPI examples. [`mechanism`] is the
//! mechanism's wire form the mechanism kinds share. Each kind is written
//! against the contract ([`crate::kind`]) only.

pub mod dynamics;
pub mod equivalent;
pub mod flywheel;
pub mod gear_train;
pub mod gears;
pub mod kinetostatics;
pub mod mechanism;
pub mod rotor;
