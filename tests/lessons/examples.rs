//! The lessons' examples and the book's own figure code, each compiled once for the
//! whole crate: a lesson's modules use `crate::examples::NAME as lesson`.
#![allow(dead_code)]

#[path = "../../examples/01_transforms.rs"]
pub mod transforms;

#[path = "../../examples/02_ray_model.rs"]
pub mod ray_model;

#[path = "../../examples/03_ortho_camera.rs"]
pub mod ortho_camera;

#[path = "../../examples/04_basis_change.rs"]
pub mod basis_change;

#[path = "../../examples/05_arbitrary_ortho_camera.rs"]
pub mod arbitrary_ortho_camera;

#[path = "../../examples/06_pinhole_camera.rs"]
pub mod pinhole_camera;

#[path = "../../examples/07_intersections.rs"]
pub mod intersections;

#[path = "../../examples/08_ray_casting.rs"]
pub mod ray_casting;

#[path = "../../examples/09_rasterization.rs"]
pub mod rasterization;

#[path = "../../examples/10_monte_carlo.rs"]
pub mod monte_carlo;

#[path = "../../examples/10_path_tracing.rs"]
pub mod path_tracing;

#[path = "../../examples/11_speed_vs_accuracy.rs"]
pub mod speed_vs_accuracy;

/// The figures of lesson 09 that only the book draws (`book/figures`).
#[path = "../../book/figures/src/lesson09.rs"]
pub mod book_figures_09;

/// The figures of lesson 10 that only the book draws (`book/figures`).
#[path = "../../book/figures/src/lesson10.rs"]
pub mod book_figures_10;
