//! The lessons' claims, one module per lesson topic: each lesson's numbers (insta
//! snapshots the chapters include), the invariants of its algorithms (random cases), the
//! STABILITY cases it meets, and its example's flags. Run one lesson with
//! `cargo test --test lessons lesson_07`.
//!
//! Facts about a single function live beside it in `src/` as unit tests; the lesson
//! 11 charts, the BVH, the ported tests and the crate's architecture are in
//! `tests/course/`; the checks of the book's text in `tests/book/`.

#[path = "../common/mod.rs"]
mod common;
mod examples;

mod figures;
mod lesson_01_transforms;
mod lesson_02_ray_model;
mod lesson_03_ortho_camera;
mod lesson_04_basis_change;
mod lesson_05_arbitrary_ortho_camera;
mod lesson_06_pinhole_camera;
mod lesson_07_box;
mod lesson_07_cylinder;
mod lesson_07_instances;
mod lesson_07_intersections;
mod lesson_07_plane;
mod lesson_07_quadrics;
mod lesson_07_sphere;
mod lesson_07_triangle;
mod lesson_08_ray_casting;
mod lesson_08_spawned_rays;
mod lesson_09_coverage;
mod lesson_09_meshes;
mod lesson_09_obj_textures;
mod lesson_09_placement;
mod lesson_09_rasterization;
mod lesson_09_real_models;
mod lesson_09_shading;
mod lesson_09_teapot;
mod lesson_09_textures;
mod lesson_10_densities;
mod lesson_10_estimators;
mod lesson_10_figures;
mod lesson_10_lights;
mod lesson_10_monte_carlo;
mod lesson_10_no_nan;
mod lesson_10_pages;
mod lesson_10_path_tracing;
mod lesson_10_pfm;
mod lesson_10_point_light;
mod lesson_10_thin_lens;
