//! mechdyn: a machine-dynamics calculation service.
//!
//! - [`engine`]: pure math (functions of the cycle angle, numerics, flywheels);
//! - [`units`]: `"VALUE UNIT"` quantities to SI with dimension checks;
//! - [`api`]: the HTTP interface (axum + utoipa), request validation, errors;
//! - [`store`]: jobs in SQLite (sqlx);
//! - [`config`]: command line and environment settings.

pub mod api;
pub mod config;
pub mod engine;
pub mod kind;
pub mod kinds;
pub mod offline;
pub mod store;
pub mod units;
