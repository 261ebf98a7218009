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
pub mod i18n;
pub mod kind;
pub mod kinds;
pub mod offline;
pub mod store;
pub mod units;

/// The service's kinds: every kind of [`kinds`], then the service's own
/// `check` — what `main.rs` hands the service, and the tests too. One per
/// process, so its OpenAPI document is made once.
pub fn registry() -> api::kind::Registry {
    static KINDS: std::sync::OnceLock<api::kind::Registry> = std::sync::OnceLock::new();
    KINDS.get_or_init(|| api::kind::Registry::new(kinds::register, &[&api::check::CHECK])).clone()
}
