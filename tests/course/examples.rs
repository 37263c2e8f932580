//! The examples these tests run, compiled once for the whole crate.
#![allow(dead_code)]

#[path = "../../examples/11_speed_vs_accuracy.rs"]
pub mod speed_vs_accuracy;
