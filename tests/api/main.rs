//! Integration tests through the real router and a real SQLite file.

mod cases;
mod cli;
mod errors;
mod helpers;
mod jobs;
mod seed_exams;
