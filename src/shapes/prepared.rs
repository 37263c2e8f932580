//! A ray with what every intersection test would otherwise recompute for each
//! primitive, computed once per ray: 1/d for the slab test, and the axis permutation
//! and shear of the watertight triangle test.
//!
//! A ray meets many primitives (six in lesson 08's list, dozens in a BVH's leaves);
//! the per-ray work is done here once, and each test then does only the work that
//! depends on its primitive (pbrt-v4 does the same: `Ray` with its `invDir`, and
//! `TriangleIntersection` with the shear hoisted in Embree-style renderers).

use glam::Vec3;

use crate::bvh::BoxRay;
use crate::ray::Ray;

/// A [`Ray`] with its per-ray numbers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PreparedRay {
    ray: Ray,
    /// 1 / d, per axis (infinite where d has a zero component).
    pub(crate) inv_d: Vec3,
    /// The watertight test's axes: `kz` the largest |d| component, `kx`, `ky` the
    /// next two cyclically (which keeps the handedness).
    pub(crate) axes: [usize; 3],
    /// The shear that takes the permuted d to (0, 0, 1):
    /// (-d_kx / d_kz, -d_ky / d_kz, 1 / d_kz).
    pub(crate) shear: Vec3,
}

impl PreparedRay {
    // ANCHOR: prepare
    /// Computes 1/d, the permutation and the shear of `ray`, once.
    pub fn new(ray: &Ray) -> PreparedRay {
        PreparedRay::with_inv_d(ray, ray.direction().recip())
    }

    /// [`PreparedRay::new`] for a ray whose 1/d, `inv_d`, is known already (a
    /// [`BoxRay`]'s): it must be `ray.direction().recip()`.
    #[inline(always)]
    pub fn with_inv_d(ray: &Ray, inv_d: Vec3) -> PreparedRay {
        let d = ray.direction();
        let kz = d.abs().max_position();
        let next = |k: usize| if k == 2 { 0 } else { k + 1 }; // (k + 1) mod 3
        let (kx, ky) = (next(kz), next(next(kz)));
        let inv_kz = inv_d[kz]; // 1 / d_kz, the same division
        PreparedRay {
            ray: *ray,
            inv_d,
            axes: [kx, ky, kz],
            shear: Vec3::new(-d[kx] / d[kz], -d[ky] / d[kz], inv_kz),
        }
    }
    // ANCHOR_END: prepare

    /// The ray itself.
    pub fn ray(&self) -> &Ray {
        &self.ray
    }

    /// The ray as a tree's boxes see it, with the same 1/d.
    #[inline(always)]
    pub fn box_ray(&self) -> BoxRay {
        BoxRay::with_inv_d(self.ray.origin(), self.inv_d)
    }
}

impl From<&Ray> for PreparedRay {
    fn from(ray: &Ray) -> PreparedRay {
        PreparedRay::new(ray)
    }
}
