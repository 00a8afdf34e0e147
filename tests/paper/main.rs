//! The executable proof of Hoffmann, "Simple Integration Algorithms".
//!
//! One module per section of the paper. Each opens with the section it
//! proves, transcribes what the paper prints, and asserts what is true.
//! Where the paper differs, the test asserts the difference and the claim
//! carries the verdict `errata` or `refined` in `zcheck paper`.

mod app_a_taylor;
mod app_b_source;
mod app_c_three_body;
mod app_d_three_body_euler;
mod app_e_aircraft;
mod common;
mod report;
mod sec04_z_transform;
mod sec05_standard_euler;
mod sec06_damped_euler;
mod sec07_false_euler;
mod sec08_verlet;
mod sec09_standard_heun;
mod sec10_false_heun;
mod sec11_semi_false_heun;
mod sec12_conclusions;
use testkit::snapshot;
mod verdict_policy;
