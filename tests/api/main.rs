//! Integration tests through the real router and a real SQLite file.

mod andrews;
mod capacity;
mod cases;
mod cli;
mod constants;
mod crash;
mod dynamics;
mod errors;
mod examples;
mod four_bars;
mod fuzz;
mod gears;
mod group_commit;
mod helpers;
mod jobs;
mod kinetostatics;
mod limits;
mod parts;
mod peers;
mod robot_arm;
mod rotor;
mod security;
mod seed_exams;
mod storage;
mod student;
mod templates;
