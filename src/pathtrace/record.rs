//! A path recorded as the estimator traces it, for figures and tests.

use glam::{Vec2, Vec3};

use crate::camera::Camera;
use crate::pathtrace::estimator::radiance_observed;
use crate::pathtrace::observer::PathObserver;
use crate::pathtrace::progressive::{PixelSampling, pixel_ray};
use crate::pathtrace::rng::Rng;
use crate::pathtrace::settings::Settings;
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
impl PathObserver for RecordedPath {
    fn vertex(&mut self, point: Vec3, object: usize) {
        let light_sample = None;
        self.vertices.push(PathVertex {
            point,
            object,
            light_sample,
        });
    }

    fn light_sample(&mut self, point: Vec3, unoccluded: bool) {
        if let Some(last) = self.vertices.last_mut() {
            last.light_sample = Some((point, unoccluded));
        }
    }

    fn escaped(&mut self, direction: Vec3) {
        self.escaped = Some(direction);
    }
}

/// The first sample of pixel (`x`, `y`) of a render with independent pixel samples
/// and streams seeded from `seed` ([`Accumulator`](crate::pathtrace::Accumulator)),
/// traced by the estimator itself and recorded.
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
    path.radiance = radiance_observed(scene, ray, &mut rng, settings, &mut path);
    path
}
// ANCHOR_END: recorder
