//! What the benches share (`cargo bench -p render-benches`, BENCHMARKS.md): the plain
//! C anchor of the ray-casting bench, and the frame loop that times a caster without
//! the set-up a renderer does once, the BVH bench's view of a big mesh and its
//! Embree anchor, and the path-tracing bench's Mitsuba anchor.

pub mod anchor;
pub mod args;
pub mod clock;
pub mod embree;
pub mod frame;
pub mod mesh_view;
pub mod mitsuba;
