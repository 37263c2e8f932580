//! A path recorded as the estimator traces it, for figures and tests.

use glam::{Vec2, Vec3};

use crate::camera::Camera;
use crate::pathtrace::estimator::{At, Path};
use crate::pathtrace::progressive::{PixelSampling, pixel_ray};
use crate::pathtrace::settings::Settings;
use crate::rng::Rng;
use crate::scene::Intersect;

/// One vertex of a recorded path: where it is, which object it is on, and, at a
/// diffuse vertex with next event estimation, the point aimed at on a light and
/// whether the shadow ray reached it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PathVertex {
    /// The hit point.
    pub point: Vec3,
    /// The index of the object hit.
    pub object: usize,
    /// The light sample of next event estimation: (point, unoccluded).
    pub light_sample: Option<(Vec3, bool)>,
}

/// A path as the estimator traced it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RecordedPath {
    /// Where the camera ray starts.
    pub eye: Vec3,
    /// The surfaces the path met, in order.
    pub vertices: Vec<PathVertex>,
    /// The direction of the last ray if it left the scene.
    pub escaped: Option<Vec3>,
    /// The path's radiance sample, as the estimator returned it.
    pub radiance: Vec3,
}

// ANCHOR: recorder
/// The first sample of pixel (`x`, `y`) of a render with independent pixel samples
/// and streams seeded from `seed` ([`Accumulator`](crate::pathtrace::Accumulator)),
/// traced by the estimator itself ([`Path`], the vertices that
/// [`radiance`](crate::pathtrace::radiance) sums) and recorded.
pub fn record_path(
    scene: &impl Intersect,
    camera: &Camera,
    settings: &Settings,
    seed: u64,
    (x, y): (u32, u32),
) -> RecordedPath {
    let mut rng = Rng::for_pixel(seed, x, y);
    let pixel = Vec2::new(x as f32, y as f32);
    let ray = pixel_ray(camera, pixel, PixelSampling::Independent, 1, 0, &mut rng);
    let mut path = RecordedPath {
        eye: ray.origin(),
        ..RecordedPath::default()
    };
    // The estimator's own path, and its light summed as `radiance` sums it.
    for vertex in Path::new(scene, ray, &mut rng, settings) {
        path.radiance += vertex.emitted;
        path.radiance += vertex.direct;
        match vertex.at {
            At::Surface { point, object } => path.vertices.push(PathVertex {
                point,
                object,
                light_sample: vertex.light_sample,
            }),
            At::Escaped { direction } => path.escaped = Some(direction),
        }
    }
    path
}
// ANCHOR_END: recorder
