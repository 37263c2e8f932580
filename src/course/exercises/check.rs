//! The checks of the coding exercises, all in one place: every chapter's check
//! (`chNN_check.rs`, beside the student's `chNN.rs`), the harness they run on
//! (`harness.rs`), and the list of exercises in book order.

pub use super::ch01_check::*;
pub use super::ch02_check::*;
pub use super::ch03_check::*;
pub use super::ch04_check::*;
pub use super::ch05_check::*;
pub use super::ch06_check::*;
pub use super::ch07_check::*;
pub use super::ch08_check::*;
pub use super::ch09_check::*;
pub use super::ch10_check::*;
pub use super::ch11_check::*;
pub use super::ch11_sah_check::*;
pub use super::harness::*;

/// Every coding exercise, in book order.
pub const ALL: [Exercise; 23] = [
    ROTATION_Y,
    COMPOSE,
    POINT_AT,
    T_CLOSEST,
    PIXEL_TO_PLANE,
    PLANE_TO_PIXEL,
    TO_WORLD,
    TO_LOCAL,
    CAMERA_BASIS,
    ORTHO_RAY,
    PINHOLE_RAY,
    PROJECT,
    RAY_PLANE_T,
    RAY_SPHERE_ROOTS,
    MOLLER_TRUMBORE,
    CLOSEST,
    LAMBERT,
    COVERS,
    PERSPECTIVE_WEIGHTS,
    COSINE_SAMPLE,
    BOUNCE_WEIGHT,
    SLAB,
    SAH_COST,
];
