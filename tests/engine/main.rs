//! Engine-level golden tests against the reference cases in tests/fixtures/cases.

mod actuators;
mod contact;
mod dynamics;
mod elliptic;
mod free_body;
mod kinetostatics;
mod many_turns;
mod mechanism_dynamics;
mod particle;
mod rotor;
mod stiff;
