//! Instancing: a shape defined in its own object space, placed in the world by a
//! lesson-01 [`Transform`] M (object to world).
//!
//! Rather than transform the shape (a transformed sphere is no longer a sphere), the
//! ray is brought into object space by M^-1, intersected there, and the hit taken
//! back to the world: the point by M, the normal by the inverse transpose M^-T
//! (pbrt-v4, "Applying Transformations": normals). One routine per primitive then
//! serves every placement, scale and shear of it.

use glam::{Mat3, Mat4, Vec3};

use crate::error::{Error, Problem, Result};
use crate::float::gamma;
use crate::ray::{Interval, Ray};
use crate::shapes::{Aabb, Crossings, Hit, Shape};
use crate::transform::Transform;

/// The relative margin around an instance's world box: 16 gamma(3), about 3e-6.
pub const INSTANCE_MARGIN: f32 = 16.0 * gamma(3);

/// A [`Shape`] placed in the world by `to_world`.
#[derive(Clone, Debug, PartialEq)]
pub struct Instance {
    shape: Shape,
    to_world: Transform,
    to_object: Transform,
    /// (M^-1)^T: what [`Transform::normal`] applies, computed once instead of per hit.
    normal_matrix: Mat4,
}

impl Instance {
    /// `shape` placed by the object-to-world transform `to_world`.
    ///
    /// The inverse is computed here, once; a singular `to_world` (e.g. a scale by 0)
    /// has none and is rejected with [`Problem::Singular`] naming `to_world`.
    pub fn new(shape: Shape, to_world: Transform) -> Result<Instance> {
        let to_object = to_world.inverse().map_err(|_| Error::Value {
            param: "to_world",
            problem: Problem::Singular,
        })?;
        Ok(Instance {
            shape,
            to_world,
            to_object,
            normal_matrix: to_object.matrix().transpose(),
        })
    }

    /// The shape, in object space.
    pub fn shape(&self) -> &Shape {
        &self.shape
    }

    /// The object-to-world transform M.
    pub fn to_world(&self) -> Transform {
        self.to_world
    }

    /// The world-to-object transform M^-1.
    pub fn to_object(&self) -> Transform {
        self.to_object
    }

    /// The world-space box around the placed shape: the eight corners of the shape's
    /// own box taken to the world by M, and the box around those (an affine map takes
    /// the box to a parallelepiped, whose corners are the images of the box's).
    /// `None` if the shape has no box (a plane) or a corner overflows.
    ///
    /// The box is moved out by [`INSTANCE_MARGIN`] times its largest coordinate: the
    /// ray is transformed before it is tested, and that rounding must not let a hit
    /// fall just outside. The margin is generous, not a proven bound.
    pub fn bounds(&self) -> Option<Aabb> {
        let b = self.shape.bounds()?;
        let (lo, hi) = (b.min(), b.max());
        let corners = (0..8).map(|i| {
            let pick =
                |bit: u32, axis: usize| if i & bit == 0 { lo[axis] } else { hi[axis] };
            self.to_world
                .point(Vec3::new(pick(1, 0), pick(2, 1), pick(4, 2)))
        });
        let world = Aabb::around(corners)?;
        let size = world.min().abs().max(world.max().abs()).max_element();
        world.padded(INSTANCE_MARGIN * size)
    }

    // ANCHOR: instance_hit
    /// The nearest crossing within `range`, `t` measured along the world ray.
    ///
    /// Object-space ray: origin o' = M^-1 o (a point), direction d' = M^-1 d (a
    /// vector). Because M^-1 is affine, M^-1 (o + t d) = o' + t d': with d' left as it
    /// is, every point has the same `t` in both spaces, and the hit's `t` could be
    /// returned unchanged (pbrt's way; [`Ray::new_unnormalised`] makes that ray). Here
    /// the object ray uses d' / |d'| instead, a unit direction like every other ray
    /// of the course, and object-space distances are world `t` times the stretch
    /// |d'|: the range is searched as (t_min |d'|, t_max |d'|) and the hit's `t`
    /// divided by |d'|. The two round differently (about half of all hits differ in
    /// the last bits of `t`, a rigid placement included), and the course's measured
    /// numbers were taken this way.
    ///
    /// The hit point goes back by M as a point; the normal by the inverse transpose
    /// (M^-1)^T, then is normalised, which keeps it perpendicular to the surface
    /// under non-uniform scale (M n itself is not). Transforming the normal by
    /// (M^-1)^T also keeps the side it points to, so `front_face` is recomputed from
    /// the world ray and agrees with the object-space one.
    pub fn hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let origin = self.to_object.point(ray.origin());
        let direction = self.to_object.vector(ray.direction());
        let stretch = direction.length();
        let unit = direction.normalize_or_zero();
        if !origin.is_finite()
            || unit == Vec3::ZERO
            || !(stretch.is_finite() && stretch > 0.0)
        {
            return None;
        }
        let object_ray = Ray::from_checked(origin, unit);
        let local = self.shape.hit(
            &object_ray,
            Interval::new(range.min * stretch, range.max * stretch),
        )?;
        let t = local.t / stretch;
        let point = self.to_world.point(local.point);
        let error = self.world_error(local.point, local.error, point);
        let normal = self
            .normal_matrix
            .transform_vector3(local.normal)
            .normalize_or_zero();
        if !(t.is_finite() && point.is_finite()) || normal == Vec3::ZERO {
            return None;
        }
        let shading = self
            .normal_matrix
            .transform_vector3(local.shading)
            .normalize_or(normal);
        let hit = Hit::new(ray, t, point, normal, error);
        Some(hit.with_shading(shading, local.uv))
    }
    // ANCHOR_END: instance_hit

    /// The error bound of the world point `world` = M `local`, where `local` is off
    /// its surface by at most `local_error` (pbrt-v4 section 6.8.3, "Transforming
    /// points with error"; |M| is M with every entry made positive, T its
    /// translation):
    /// - M p rounds each coordinate by at most gamma(3) (|M| |p| + |T|);
    /// - the point's own error goes through |M|, grown by 1 + gamma(3);
    /// - and a ray spawned from the world point is taken back to object space by
    ///   M^-1 before it is tested, which rounds its origin by
    ///   gamma(3) (|M^-1| |p_w| + |T^-1|) there, |M| times that in the world.
    fn world_error(&self, local: Vec3, local_error: Vec3, world: Vec3) -> Vec3 {
        let abs = |m: Mat4| (Mat3::from_mat4(m.abs()), m.w_axis.truncate().abs());
        let (m, t) = abs(self.to_world.matrix());
        let (inverse, inverse_t) = abs(self.to_object.matrix());
        let forward =
            gamma(3) * (m * local.abs() + t) + (1.0 + gamma(3)) * (m * local_error);
        let back = m * (gamma(3) * (inverse * world.abs() + inverse_t));
        forward + back
    }

    /// Every crossing of the world ray's line, ascending, `t` measured along the world
    /// ray: the shape's crossings of the object-space ray o' = M^-1 o, d' = M^-1 d / s
    /// (the stretch |M^-1 d|), each divided by it, as in [`Instance::hit`].
    pub fn crossings(&self, ray: &Ray) -> Crossings {
        let origin = self.to_object.point(ray.origin());
        let direction = self.to_object.vector(ray.direction());
        let stretch = direction.length();
        let unit = direction.normalize_or_zero();
        if !origin.is_finite()
            || unit == Vec3::ZERO
            || !(stretch.is_finite() && stretch > 0.0)
        {
            return Crossings::NONE;
        }
        let object_ray = Ray::from_checked(origin, unit);
        self.shape.crossings(&object_ray).map(|t| t / stretch)
    }

    /// The outward unit normal at the world point `p`: the shape's normal at the
    /// object point M^-1 p, taken back by the inverse transpose (M^-1)^T and normalised
    /// (The Ray Tracer Challenge, ch. 6, "Transforming Normals"); the zero vector
    /// where the shape has none.
    pub fn normal_at(&self, p: Vec3) -> Vec3 {
        let local = self.shape.normal_at(self.to_object.point(p));
        self.normal_matrix
            .transform_vector3(local)
            .normalize_or_zero()
    }
}
