//! Everything a program of your own needs, in one `use`:
//!
//! ```no_run
//! use render_lessons::prelude::*;
//! # fn main() -> Result<()> {
//! let ball = Object::diffuse(Sphere::new(Vec3::ZERO, 1.0)?, Vec3::new(0.8, 0.3, 0.2));
//! let scene = Scene::new(vec![ball], Vec3::splat(0.1))?;
//! let camera = Camera::look_at(Vec3::new(0.0, 0.0, 4.0), Vec3::ZERO, Vec3::Y, 40.0, 320, 240)?;
//! ray_cast(&scene, &camera)?.save_png("ball.png")
//! # }
//! ```
//!
//! glam comes with it (`glam`, `Vec3`, ...), the version the crate is built with, so
//! a program needs no glam of its own to disagree with.

pub use glam::{self, Mat4, Vec2, Vec3};

pub use crate::camera::{Camera, Film, Frame, OrthoCamera, PinholeCamera};
pub use crate::error::{Error, Result};
pub use crate::framebuffer::Framebuffer;
pub use crate::material::Material;
pub use crate::mesh::{Mesh, Model};
pub use crate::pathtrace::{Settings, path_trace};
pub use crate::raycast::ray_cast;
pub use crate::render::render;
pub use crate::scene::{BvhScene, ListOrTree};
pub use crate::scene::{Intersect, Object, PointLight, Scene};
pub use crate::scenes::{TEAPOT_OBJ, TORUS_OBJ, asset_path};
pub use crate::shapes::{Aabb, Plane, Quad, Shape, Sphere, Triangle, TriangleMesh};
pub use crate::spawn::Offset;
pub use crate::texture::Texture;
pub use crate::transform::Transform;
