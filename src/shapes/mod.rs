//! The primitives: where a ray crosses each kind of surface, and its bounding box.
//!
//! Ray / primitive intersection (Lecture 4): sphere, plane, axis-aligned box and
//! triangle, each in its own file, each with the naive method next to the robust one
//! (STABILITY cases S1, S2, S4 to S8); then the quad, the quadrics, the capped
//! cylinder, and instances of any of them placed by a transform.
//!
//! Every routine takes a [`Ray`] (finite origin, a direction of any non-zero
//! length: `t` is in lengths of it, a distance for a unit direction) and reports the
//! nearest crossing within a `range` (an open [`Interval`], `min < t < max`). For
//! finite input none of them panics or returns NaN: a comparison that meets a NaN
//! always falls on the "miss" side.

use std::sync::Arc;

use glam::{Vec2, Vec3};

use crate::bvh::{Bounded, Crossing};
use crate::float::gamma;
use crate::ray::{Crossings, Interval, Ray};

pub mod aabb;
pub mod by_kind;
pub mod cylinder;
pub mod instance;
pub mod plane;
pub mod prepared;
pub mod quad;
pub mod quadric;
pub mod sphere;
pub mod triangle;
pub mod triangle_mesh;

pub use aabb::{Aabb, FaceHit};
pub use by_kind::ShapesByKind;
pub use cylinder::{Cylinder, CylinderPart, PartHit};
pub use instance::Instance;
pub use plane::Plane;
pub use prepared::PreparedRay;
pub use quad::Quad;
pub use quadric::Quadric;
pub use sphere::Sphere;
pub use triangle::{Barycentric, Triangle};
pub use triangle_mesh::TriangleMesh;

/// Where a ray crosses a surface.
///
/// Two normals, as pbrt keeps them: the geometric `normal`, the surface's own, which
/// decides the side the ray came from and where a spawned ray starts; and the
/// `shading` normal, which lighting uses. They differ only on a mesh with a normal
/// per vertex, whose shading normal is their blend at the point (Phong's smooth
/// shading, lesson 09): the facets are flat, the light on them is not.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// The ray parameter, point = o + t d: the signed distance from the ray's origin
    /// (in lengths of d for a ray made by [`Ray::new_unnormalised`]).
    pub t: f32,
    /// The point on the surface.
    pub point: Vec3,
    /// The unit geometric normal, pointing out of the surface whichever side the ray
    /// came from.
    pub normal: Vec3,
    /// The unit shading normal, on the same side of the surface as `normal`: equal to
    /// it except on a mesh with normals per vertex ([`TriangleMesh`]).
    pub shading: Vec3,
    /// The texture coordinates (u, v) of the point: a textured mesh's, blended from
    /// its vertices' ([`TriangleMesh`]); zero on every other surface.
    pub uv: Vec2,
    /// `true` if the ray arrived from the side the normal points to (d . n < 0).
    pub front_face: bool,
    /// A conservative bound, per coordinate, on how far `point` lies from the true
    /// surface: some surface point lies within `point +- error` (pbrt-v4 section 6.8,
    /// "Managing Rounding Error"). A ray leaving the hit starts just beyond it
    /// ([`crate::spawn::offset_by_error`]).
    pub error: Vec3,
}

impl Hit {
    /// A hit at `t` and `point` with outward unit `normal` and the point's rounding
    /// `error`; `front_face` follows from the sign of d . n.
    pub(crate) fn new(
        ray: &Ray,
        t: f32,
        point: Vec3,
        normal: Vec3,
        error: Vec3,
    ) -> Hit {
        Hit {
            t,
            point,
            normal,
            shading: normal,
            uv: Vec2::ZERO,
            front_face: ray.direction().dot(normal) < 0.0,
            error,
        }
    }

    // ANCHOR: facing
    /// The front-face rule, written once for every renderer: the unit normal on the
    /// side the ray came from, `normal` for a front face and `-normal` for a back
    /// face, so that shading and the offset of the next ray see the lit side.
    pub fn facing(&self) -> Vec3 {
        if self.front_face {
            self.normal
        } else {
            -self.normal
        }
    }
    // ANCHOR_END: facing

    /// The same hit with the unit shading normal `shading` (turned to the side of the
    /// geometric normal if it points the other way) and the texture coordinates `uv`.
    pub(crate) fn with_shading(self, shading: Vec3, uv: Vec2) -> Hit {
        let shading = if shading.dot(self.normal) < 0.0 {
            -shading
        } else {
            shading
        };
        Hit {
            shading,
            uv,
            ..self
        }
    }

    /// The shading normal on the side of the surface the ray came from, by the same
    /// front-face rule ([`Hit::facing`]): what lighting sees. Near a smooth mesh's
    /// outline it can lean away from the ray; it is not turned towards it, which
    /// would light that rim as if it faced the other way (the rasterizer's `shade`
    /// decides the side by the triangle too).
    pub fn shading_facing(&self) -> Vec3 {
        if self.front_face {
            self.shading
        } else {
            -self.shading
        }
    }
}

// ANCHOR: candidate
/// What one primitive's test tells the closest-hit loop: the distance `t` and the
/// little the winner needs later to build its [`Hit`]. The point, the normal and
/// the face are computed once, for the closest hit, not for every closer candidate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Candidate {
    /// The ray parameter of the crossing.
    pub t: f32,
    detail: Detail,
}

/// What a shape needs, besides `t`, to build its hit record.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Detail {
    /// Nothing: the point is o + t d (sphere, plane, quad, quadric).
    OnRay,
    /// A triangle's crossing: the barycentric coordinates (b0, b1, b2) of its point.
    Barycentric(Barycentric),
    /// A box's face: the axis and the sign of its outward normal.
    Face(FaceHit),
    /// A capped cylinder's crossing: the side or a cap.
    Part(PartHit),
    /// An instance: its test is run again, over the same range, for the winner
    /// only (instances are rare; this keeps the candidate small).
    Instance { range: Interval },
    /// A mesh's crossing: which of its triangles, and the barycentric coordinates.
    Mesh { triangle: u32, b: [f32; 3] },
}
// ANCHOR_END: candidate

/// The tree's search ([`crate::bvh::Bvh::closest`]) reads a candidate's `t`.
impl Crossing for Candidate {
    #[inline(always)]
    fn t(&self) -> f32 {
        self.t
    }
}

impl Candidate {
    fn on_ray(t: f32) -> Candidate {
        Candidate {
            t,
            detail: Detail::OnRay,
        }
    }
}

// ANCHOR: kind_candidates
// Which test makes which candidate, once for each kind of shape: the one place the
// closest-hit loops ([`Shape::candidate`], the runs of [`ShapesByKind`], the BVH's
// leaves) learn how a kind is tested.

impl Sphere {
    /// The nearer crossing within `range` as a [`Candidate`]: its `t` alone, the point
    /// being o + t d.
    #[inline(always)]
    pub fn candidate(&self, ray: &PreparedRay, range: Interval) -> Option<Candidate> {
        self.nearest(ray.ray(), range).map(Candidate::on_ray)
    }
}

impl Plane {
    /// The crossing within `range` as a [`Candidate`]: its `t` alone, the point
    /// being o + t d.
    #[inline(always)]
    pub fn candidate(&self, ray: &PreparedRay, range: Interval) -> Option<Candidate> {
        self.nearest(ray.ray(), range).map(Candidate::on_ray)
    }
}

impl Quad {
    /// The crossing within `range` as a [`Candidate`]: its `t` alone, the point
    /// being o + t d.
    #[inline(always)]
    pub fn candidate(&self, ray: &PreparedRay, range: Interval) -> Option<Candidate> {
        self.nearest(ray.ray(), range).map(Candidate::on_ray)
    }
}

impl Quadric {
    /// The nearest crossing within `range` as a [`Candidate`]: its `t` alone, the point
    /// being o + t d.
    #[inline(always)]
    pub fn candidate(&self, ray: &PreparedRay, range: Interval) -> Option<Candidate> {
        self.nearest(ray.ray(), range).map(Candidate::on_ray)
    }
}

impl Triangle {
    /// The watertight crossing within `range` as a [`Candidate`], with its
    /// barycentric coordinates.
    #[inline(always)]
    pub fn candidate(&self, ray: &PreparedRay, range: Interval) -> Option<Candidate> {
        let crossing = self.watertight_prepared(ray, range)?;
        let detail = Detail::Barycentric(crossing);
        Some(Candidate {
            t: crossing.t,
            detail,
        })
    }
}

impl Aabb {
    /// The face the ray enters (or leaves) within `range` as a [`Candidate`].
    #[inline(always)]
    pub fn candidate(&self, ray: &PreparedRay, range: Interval) -> Option<Candidate> {
        let face = self.nearest_face(ray, range)?;
        Some(Candidate {
            t: face.t,
            detail: Detail::Face(face),
        })
    }
}

impl Cylinder {
    /// The nearest crossing of the side or a cap within `range` as a [`Candidate`].
    #[inline(always)]
    pub fn candidate(&self, ray: &PreparedRay, range: Interval) -> Option<Candidate> {
        let part = self.nearest(ray.ray(), range)?;
        Some(Candidate {
            t: part.t,
            detail: Detail::Part(part),
        })
    }
}

impl TriangleMesh {
    /// The nearest crossing within `range` as a [`Candidate`]: its triangle and
    /// barycentric coordinates, found through the mesh's tree.
    #[inline(always)]
    pub fn candidate(&self, ray: &PreparedRay, range: Interval) -> Option<Candidate> {
        let (crossing, triangle) = self.closest(ray, range)?;
        Some(Candidate {
            t: crossing.t,
            detail: Detail::Mesh {
                triangle: triangle as u32,
                b: crossing.b,
            },
        })
    }
}

impl Instance {
    /// The nearest hit within `range` as a [`Candidate`]: its `t`, and the range to
    /// run the test again in for the winner's record.
    #[inline(always)]
    pub fn candidate(&self, ray: &PreparedRay, range: Interval) -> Option<Candidate> {
        let hit = self.hit(ray.ray(), range)?;
        Some(Candidate {
            t: hit.t,
            detail: Detail::Instance { range },
        })
    }
}
// ANCHOR_END: kind_candidates

/// A hit record at `t` from the point on the ray and the shape's `normal_at`: what
/// [`Shape::record`] answers for a candidate it cannot have made, to stay total. The
/// error is [`on_ray_error`] with t taken as exact (nothing here knows t's error).
fn fallback(shape: &Shape, ray: &Ray, t: f32) -> Hit {
    let point = ray.at(t);
    Hit::new(ray, t, point, shape.normal_at(point), on_ray_error(ray, t))
}

/// The rounding of the point o + t d itself, for an exact `t`: each coordinate is a
/// product and a sum, so gamma(2) (|o| + |t d|) (pbrt-v4 section 6.8.4). It does not
/// hold t's own error, which grows with t: the shapes that need a tight bound
/// re-project the point onto the surface instead.
pub(crate) fn on_ray_error(ray: &Ray, t: f32) -> Vec3 {
    gamma(2) * (ray.origin().abs() + (t * ray.direction()).abs())
}

/// One primitive of a scene.
///
/// Not `Copy`: an [`Instance`] owns the shape it places, behind a `Box`. Each kind
/// converts into it with `.into()` (or `Shape::from`), as the cameras do into
/// [`crate::camera::Camera`]:
///
/// ```
/// use glam::Vec3;
/// use render_lessons::shapes::{Plane, Shape, Sphere};
///
/// let ball: Shape = Sphere::new(Vec3::ZERO, 1.0)?.into();
/// let floor = Shape::from(Plane::new(Vec3::ZERO, Vec3::Y)?);
/// assert!(matches!((ball, floor), (Shape::Sphere(_), Shape::Plane(_))));
/// # Ok::<(), render_lessons::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// A sphere (lesson 07).
    Sphere(Sphere),
    /// An infinite plane (lesson 07).
    Plane(Plane),
    /// An axis-aligned box (lesson 07).
    Aabb(Aabb),
    /// A triangle (lesson 07).
    Triangle(Triangle),
    /// A general quadric, the points x = (x, y, z, 1) with x^T Q x = 0 (lesson 07).
    Quadric(Quadric),
    /// A parallelogram (lesson 10's lamp).
    Quad(Quad),
    /// A cylinder closed by two discs (lesson 07).
    Cylinder(Cylinder),
    /// A shape placed by a transform (lesson 07).
    Instance(Box<Instance>),
    /// A triangle mesh, one shape with a tree of its own (lesson 09), shared.
    Mesh(Arc<TriangleMesh>),
}

impl From<Sphere> for Shape {
    fn from(shape: Sphere) -> Shape {
        Shape::Sphere(shape)
    }
}

impl From<Plane> for Shape {
    fn from(shape: Plane) -> Shape {
        Shape::Plane(shape)
    }
}

impl From<Aabb> for Shape {
    fn from(shape: Aabb) -> Shape {
        Shape::Aabb(shape)
    }
}

impl From<Triangle> for Shape {
    fn from(shape: Triangle) -> Shape {
        Shape::Triangle(shape)
    }
}

impl From<Quadric> for Shape {
    fn from(shape: Quadric) -> Shape {
        Shape::Quadric(shape)
    }
}

impl From<Quad> for Shape {
    fn from(shape: Quad) -> Shape {
        Shape::Quad(shape)
    }
}

impl From<Cylinder> for Shape {
    fn from(shape: Cylinder) -> Shape {
        Shape::Cylinder(shape)
    }
}

impl From<TriangleMesh> for Shape {
    fn from(mesh: TriangleMesh) -> Shape {
        Shape::Mesh(Arc::new(mesh))
    }
}

impl From<Instance> for Shape {
    fn from(instance: Instance) -> Shape {
        Shape::Instance(Box::new(instance))
    }
}

impl Shape {
    /// The nearest crossing of `ray` within `range`, if any: the
    /// [`Shape::candidate`] test, then [`Shape::record`].
    pub fn hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let prepared = PreparedRay::new(ray);
        let candidate = self.candidate(&prepared, range)?;
        Some(self.record(&prepared, candidate))
    }

    // ANCHOR: shape_candidate
    /// The nearest crossing within `range` as a [`Candidate`]: `t` and
    /// what the hit record needs, nothing more, from the test of the shape's kind
    /// ([`Sphere::candidate`] and each other kind's). The closest-hit loop
    /// asks every primitive for this, and [`Shape::record`] once, for the winner.
    #[inline(always)]
    pub fn candidate(&self, ray: &PreparedRay, range: Interval) -> Option<Candidate> {
        match self {
            Shape::Sphere(s) => s.candidate(ray, range),
            Shape::Plane(p) => p.candidate(ray, range),
            Shape::Quad(q) => q.candidate(ray, range),
            Shape::Quadric(q) => q.candidate(ray, range),
            Shape::Triangle(tri) => tri.candidate(ray, range),
            Shape::Aabb(b) => b.candidate(ray, range),
            Shape::Cylinder(c) => c.candidate(ray, range),
            Shape::Instance(i) => i.candidate(ray, range),
            Shape::Mesh(m) => m.candidate(ray, range),
        }
    }
    // ANCHOR_END: shape_candidate

    /// The hit record of a `candidate` this shape's [`Shape::candidate`] returned for
    /// `ray`: the point, the outward normal and the side.
    #[inline]
    pub fn record(&self, ray: &PreparedRay, candidate: Candidate) -> Hit {
        let (ray, t) = (ray.ray(), candidate.t);
        match (self, candidate.detail) {
            (Shape::Instance(i), Detail::Instance { range }) => {
                i.hit(ray, range).unwrap_or_else(|| fallback(self, ray, t))
            }
            (Shape::Triangle(tri), Detail::Barycentric(c)) => tri.hit_at(ray, c),
            (Shape::Mesh(m), Detail::Mesh { triangle, b }) => {
                m.hit_at(ray, triangle as usize, Barycentric { t, b })
            }
            (Shape::Aabb(b), Detail::Face(face)) => b.hit_at(ray, face),
            (Shape::Cylinder(c), Detail::Part(crossing)) => c.hit_at(ray, crossing),
            (Shape::Sphere(s), _) => s.hit_at(ray, t),
            (Shape::Plane(p), _) => p.hit_at(ray, t),
            (Shape::Quad(q), _) => q.hit_at(ray, t),
            (Shape::Quadric(q), _) => q.hit_at(ray, t),
            // A candidate that another shape made (the crate never pairs them).
            (shape, _) => fallback(shape, ray, t),
        }
    }

    /// Every crossing of `ray`'s whole line with the surface, ascending (see
    /// [`Crossings`]).
    pub fn crossings(&self, ray: &Ray) -> Crossings {
        match self {
            Shape::Sphere(s) => s.crossings(ray),
            Shape::Plane(p) => p.crossings(ray),
            Shape::Aabb(b) => b.crossings(ray),
            Shape::Triangle(tri) => tri.crossings(ray),
            Shape::Quadric(q) => q.crossings(ray),
            Shape::Quad(q) => q.crossings(ray),
            Shape::Cylinder(c) => c.crossings(ray),
            Shape::Instance(i) => i.crossings(ray),
            Shape::Mesh(m) => m.crossings(ray),
        }
    }

    /// The outward unit normal at the surface point `p`, the normal [`Shape::hit`]
    /// reports there; the zero vector where the surface has none (a cone's apex).
    pub fn normal_at(&self, p: Vec3) -> Vec3 {
        match self {
            Shape::Sphere(s) => s.normal_at(p),
            Shape::Plane(pl) => pl.normal_at(p),
            Shape::Aabb(b) => b.normal_at(p),
            Shape::Triangle(tri) => tri.normal_at(p),
            Shape::Quadric(q) => q.normal_at(p),
            Shape::Quad(q) => q.normal_at(p),
            Shape::Cylinder(c) => c.normal_at(p),
            Shape::Instance(i) => i.normal_at(p),
            Shape::Mesh(m) => m.normal_at(p),
        }
    }

    /// The shape's bounding box, for an acceleration structure ([`crate::bvh`]), or
    /// `None` for a shape without one: a plane, a quadric (most are unbounded; an
    /// ellipsoid is not, but no scene here needs its box), an instance of either, or
    /// a box that overflows f32.
    pub fn bounds(&self) -> Option<Aabb> {
        match self {
            Shape::Sphere(s) => s.bounds(),
            Shape::Plane(_) | Shape::Quadric(_) => None,
            Shape::Aabb(b) => Some(*b),
            Shape::Triangle(tri) => tri.bounds(),
            Shape::Quad(q) => q.bounds(),
            Shape::Cylinder(c) => c.bounds(),
            Shape::Instance(i) => i.bounds(),
            Shape::Mesh(m) => Some(m.bounds()),
        }
    }
}

/// A shape's box for a tree ([`crate::bvh`]): [`Shape::bounds`]'s corners.
impl Bounded for Shape {
    fn corners(&self) -> Option<(Vec3, Vec3)> {
        self.bounds().map(|b| (b.min(), b.max()))
    }
}

/// A triangle's box for a tree: [`Triangle::bounds`]'s corners.
impl Bounded for Triangle {
    fn corners(&self) -> Option<(Vec3, Vec3)> {
        self.bounds().map(|b| (b.min(), b.max()))
    }
}
