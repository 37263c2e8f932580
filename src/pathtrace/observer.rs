//! Watching the estimator: a hook that sees every vertex of a path as
//! [`radiance_observed`](crate::pathtrace::estimator::radiance_observed) traces it,
//! so that a figure can draw the real paths (see [`crate::pathtrace::record`]).

use glam::Vec3;

// ANCHOR: observer
/// What a path tracer can be watched doing, one call per event of a path; every
/// method does nothing unless implemented. `()` watches nothing: it is what
/// [`radiance`](crate::pathtrace::estimator::radiance) passes, and the compiler
/// drops its calls, so the renders pay nothing for the hook.
pub trait PathObserver {
    /// The path met object `index` (of
    /// [`Scene::objects`](crate::scene::Scene::objects)) at `point`.
    fn vertex(&mut self, _point: Vec3, _index: usize) {}
    /// At the last vertex (diffuse), next event estimation aimed at `point` on a
    /// light; `unoccluded`: the point faces the vertex and its shadow ray got through.
    fn light_sample(&mut self, _point: Vec3, _unoccluded: bool) {}
    /// The path left the scene along the unit `direction`.
    fn escaped(&mut self, _direction: Vec3) {}
    /// Light added to the sample: `contribution` (already weighted), and whether it
    /// is a caustic, light that reached a diffuse vertex through mirror or glass
    /// (only the specular bounce can find it; light sampling cannot help).
    fn light(&mut self, _contribution: Vec3, _caustic: bool) {}
}

impl PathObserver for () {}
// ANCHOR_END: observer
