//! The Embree anchor of the BVH bench: Embree 3's `rtcIntersect1` on the bench's
//! mesh and rays, through the C shim `anchors/embree_caster.c`, compiled by
//! `build.rs` when Embree 3 is installed (Debian: `libembree-dev`). One build
//! thread, build quality medium, Embree's default (not watertight) triangle test.

use std::fmt;

use glam::Vec3;
use render_lessons::mesh::Mesh;
use render_lessons::ray::{Interval, Ray};
use render_lessons::scene::BvhScene;
use render_lessons::scene::Intersect;

/// The line the bench prints in place of Embree's figures when it is missing.
pub const MISSING: &str = "Embree anchor skipped: Embree 3 was not found when the \
     benches were built (no /usr/include/embree3/rtcore.h, no pkg-config embree3, or \
     RENDER_BENCHES_NO_EMBREE set). Install it (Debian/Ubuntu: apt-get install \
     libembree-dev) and run the bench again";

/// `true` when the shim was compiled and linked in.
pub fn available() -> bool {
    cfg!(embree_anchor)
}

/// Embree's version ("3.13.5"), or `None` without the anchor.
pub fn version() -> Option<String> {
    ffi::version()
}

#[cfg_attr(not(embree_anchor), allow(dead_code))]
/// A mesh as Embree reads it in place: three floats per vertex (and one more, as
/// Embree loads 16 bytes at a time), three indices per triangle.
pub struct EmbreeMesh {
    vertices: Vec<f32>,
    indices: Vec<u32>,
}

impl EmbreeMesh {
    /// `mesh`'s vertex and triangle lists, copied into Embree's layout (before any
    /// clock starts). Triangle i of the mesh is Embree's primitive i.
    pub fn new(mesh: &Mesh) -> EmbreeMesh {
        let mut vertices: Vec<f32> =
            mesh.positions.iter().flat_map(|p| p.to_array()).collect();
        vertices.push(0.0);
        let indices = mesh.triangles.iter().flatten().copied().collect();
        EmbreeMesh { vertices, indices }
    }

    /// Embree's tree over the mesh (`rtcCommitScene`, one thread): `None` without
    /// the anchor, an error when Embree refuses.
    pub fn build(&self) -> Option<Result<EmbreeScene<'_>, String>> {
        ffi::build(self)
    }
}

/// A built Embree scene, which reads the [`EmbreeMesh`] it was built from.
pub struct EmbreeScene<'a> {
    scene: ffi::Handle,
    _mesh: &'a EmbreeMesh,
}

/// Rays as the shim takes them: origin and direction, six floats a ray.
pub fn flat_rays(rays: &[Ray]) -> Vec<f32> {
    let six = |r: &Ray| {
        let (o, d): (Vec3, Vec3) = (r.origin(), r.direction());
        [o.x, o.y, o.z, d.x, d.y, d.z]
    };
    rays.iter().flat_map(six).collect()
}

impl EmbreeScene<'_> {
    /// How many of the rays (from [`flat_rays`]) hit the mesh: one `rtcIntersect1`
    /// each, t from 0 to infinity.
    pub fn count_hits(&self, rays: &[f32]) -> usize {
        ffi::trace(&self.scene, rays, None)
    }

    /// Each ray's closest hit: its distance and the triangle's index, `None` on a
    /// miss.
    pub fn closest(&self, rays: &[f32]) -> Vec<Option<(f32, usize)>> {
        let n = rays.len() / 6;
        let (mut t, mut prim) = (vec![0.0; n], vec![0; n]);
        ffi::trace(&self.scene, rays, Some((&mut t, &mut prim)));
        t.iter()
            .zip(&prim)
            .map(|(&t, &p)| (p != u32::MAX).then_some((t, p as usize)))
            .collect()
    }
}

/// Whether Embree finds, for every ray, what the crate's tree finds: a hit or a
/// miss, and for a hit the same triangle at the same distance up to a relative
/// 1e-4 (Embree's Möller-Trumbore test and the crate's watertight one round
/// differently, and a ray that grazes the sphere's outline meets it at so small an
/// angle that t is ill-conditioned: up to 4e-5 apart on the bench's mesh). A ray
/// through the edge two triangles share may be given to either by two correct
/// tests, and Embree's test, not watertight, may let it through both: such
/// disagreements are allowed on at most one ray in 10 000 (on the bench's frames
/// Embree misses the front of the sphere on one ray in about 130 000 to 2 million). A bench that timed
/// different work would compare nothing, so it leaves Embree out when they do not
/// agree.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Agreement {
    /// Rays on which Embree hits another triangle at the same distance.
    pub other_triangle: usize,
    /// Rays on which one misses where the other hits, or they hit at different
    /// distances.
    pub other_hit: usize,
    /// The most rays that may differ: one in 10 000.
    pub allowed: usize,
}

impl Agreement {
    /// `rays` traced by both, compared ray by ray.
    pub fn of(ours: &BvhScene, embree: &EmbreeScene, rays: &[Ray]) -> Agreement {
        let theirs = embree.closest(&flat_rays(rays));
        let (mut other_triangle, mut other_hit) = (0, 0);
        for (ray, theirs) in rays.iter().zip(theirs) {
            let ours = ours.closest(ray, Interval::AHEAD);
            match (ours.map(|h| (h.hit.t, h.object)), theirs) {
                (None, None) => {}
                (Some((t, i)), Some((u, j))) if (t - u).abs() <= 1e-4 * t => {
                    other_triangle += usize::from(i != j);
                }
                _ => other_hit += 1,
            }
        }
        let allowed = rays.len() / 10_000;
        Agreement {
            other_triangle,
            other_hit,
            allowed,
        }
    }

    /// How many rays differ.
    pub fn differ(&self) -> usize {
        self.other_triangle + self.other_hit
    }

    /// True when at most `allowed` rays differ.
    pub fn holds(&self) -> bool {
        self.differ() <= self.allowed
    }
}

impl fmt::Display for Agreement {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        write!(
            f,
            "Embree against ours: {} ray(s) hit another triangle at the same distance, \
             {} a miss or a hit at another distance; at most {} allowed in all{}",
            self.other_triangle,
            self.other_hit,
            self.allowed,
            if self.holds() {
                ""
            } else {
                ": not the same work, Embree left out"
            }
        )
    }
}

#[cfg(embree_anchor)]
mod ffi {
    use super::{EmbreeMesh, EmbreeScene};
    use std::ffi::{CStr, c_char, c_int, c_void};

    unsafe extern "C" {
        fn embree_anchor_version() -> *const c_char;
        fn embree_anchor_build(
            vertices: *const f32,
            vertex_count: usize,
            indices: *const u32,
            triangle_count: usize,
        ) -> *mut c_void;
        fn embree_anchor_release(scene: *mut c_void);
        fn embree_anchor_error() -> c_int;
        fn embree_anchor_trace(
            scene: *mut c_void,
            rays: *const f32,
            ray_count: usize,
            t: *mut f32,
            prim: *mut u32,
        ) -> usize;
    }

    /// An `RTCScene`, released when dropped.
    pub struct Handle(*mut c_void);

    impl Drop for Handle {
        fn drop(&mut self) {
            // SAFETY: the handle came from embree_anchor_build and is released once.
            unsafe { embree_anchor_release(self.0) }
        }
    }

    pub fn version() -> Option<String> {
        // SAFETY: the shim returns a static NUL-terminated string.
        let s = unsafe { CStr::from_ptr(embree_anchor_version()) };
        Some(s.to_string_lossy().into_owned())
    }

    pub fn build(mesh: &EmbreeMesh) -> Option<Result<EmbreeScene<'_>, String>> {
        let (vertices, indices) = (&mesh.vertices, &mesh.indices);
        // SAFETY: `vertices` holds 3 floats per vertex and one more (Embree's 16-byte
        // loads stay inside it), `indices` 3 per triangle, and both outlive the
        // scene (EmbreeScene borrows the mesh).
        let scene = unsafe {
            embree_anchor_build(
                vertices.as_ptr(),
                (vertices.len() - 1) / 3,
                indices.as_ptr(),
                indices.len() / 3,
            )
        };
        Some(if scene.is_null() {
            // SAFETY: a plain call into the shim.
            let code = unsafe { embree_anchor_error() };
            Err(format!("Embree refused the mesh (RTCError {code})"))
        } else {
            Ok(EmbreeScene {
                scene: Handle(scene),
                _mesh: mesh,
            })
        })
    }

    pub fn trace(
        scene: &Handle,
        rays: &[f32],
        out: Option<(&mut [f32], &mut [u32])>,
    ) -> usize {
        let n = rays.len() / 6;
        let (t, prim) = match out {
            Some((t, prim)) => {
                assert!(
                    t.len() == n && prim.len() == n,
                    "one t and one index per ray"
                );
                (t.as_mut_ptr(), prim.as_mut_ptr())
            }
            None => (std::ptr::null_mut(), std::ptr::null_mut()),
        };
        // SAFETY: `rays` holds 6 floats per ray; `t` and `prim` are null or hold one
        // entry per ray; the scene is alive (a Handle).
        unsafe { embree_anchor_trace(scene.0, rays.as_ptr(), n, t, prim) }
    }
}

#[cfg(not(embree_anchor))]
mod ffi {
    use super::{EmbreeMesh, EmbreeScene};

    /// Never made: without Embree there is no scene.
    pub enum Handle {}

    pub fn version() -> Option<String> {
        None
    }

    pub fn build(_: &EmbreeMesh) -> Option<Result<EmbreeScene<'_>, String>> {
        None
    }

    pub fn trace(
        scene: &Handle,
        _: &[f32],
        _: Option<(&mut [f32], &mut [u32])>,
    ) -> usize {
        match *scene {}
    }
}
