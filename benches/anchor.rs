//! The plain C anchor: lesson 08's scene and pinhole camera cast with the textbook
//! tests in C (`anchors/plain_caster.c`, -O2, scalar f32, one thread), compiled by
//! `build.rs` when a C compiler is there. It computes the image of
//! `course::measure::plain` bit for bit, so the two can be timed against each other.

use glam::Vec3;

/// The C compiler's version and the flags the anchor was built with, or `None`
/// when there was no C compiler and the anchor is missing.
pub const COMPILER: Option<&str> = option_env!("C_ANCHOR_COMPILER");

/// The line a bench prints instead of the anchor's figures when it is missing.
pub const MISSING: &str = "C anchor skipped: it was not compiled (no C compiler when the \
     benches were built, or RENDER_BENCHES_NO_C_ANCHOR set; see benches/build.rs)";

/// `true` when the anchor was compiled in.
pub fn available() -> bool {
    cfg!(c_anchor)
}

/// One frame of lesson 08 cast by the C anchor into `rgb` (one colour per pixel,
/// row 0 at the top), on this thread; `None` without the anchor.
pub fn frame(width: u32, height: u32, rgb: &mut [Vec3]) -> Option<()> {
    check(width, height, rgb);
    ffi::frame(width, height, rgb)
}

/// The C camera alone: every pixel's ray direction into `xyz`; `None` without the
/// anchor.
pub fn camera(width: u32, height: u32, xyz: &mut [Vec3]) -> Option<()> {
    check(width, height, xyz);
    ffi::camera(width, height, xyz)
}

/// The C code writes 3 width height floats: one `Vec3` (three `f32`, `#[repr(C)]`)
/// per pixel.
fn check(width: u32, height: u32, pixels: &[Vec3]) {
    assert_eq!(
        pixels.len(),
        width as usize * height as usize,
        "one Vec3 per pixel"
    );
}

#[cfg(c_anchor)]
mod ffi {
    use glam::Vec3;

    unsafe extern "C" {
        fn plain_caster_frame(width: u32, height: u32, rgb: *mut f32);
        fn plain_camera_frame(width: u32, height: u32, xyz: *mut f32);
    }

    pub fn frame(width: u32, height: u32, rgb: &mut [Vec3]) -> Option<()> {
        // SAFETY: `rgb` holds width x height Vec3s (checked by the caller), each
        // three contiguous f32 (glam's Vec3 is #[repr(C)]), and the C code writes
        // exactly 3 width height floats.
        unsafe { plain_caster_frame(width, height, rgb.as_mut_ptr().cast()) };
        Some(())
    }

    pub fn camera(width: u32, height: u32, xyz: &mut [Vec3]) -> Option<()> {
        // SAFETY: as in `frame`.
        unsafe { plain_camera_frame(width, height, xyz.as_mut_ptr().cast()) };
        Some(())
    }
}

#[cfg(not(c_anchor))]
mod ffi {
    use glam::Vec3;

    pub fn frame(_: u32, _: u32, _: &mut [Vec3]) -> Option<()> {
        None
    }

    pub fn camera(_: u32, _: u32, _: &mut [Vec3]) -> Option<()> {
        None
    }
}
