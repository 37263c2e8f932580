//! Comparing results: within a tolerance ([`close`]), or bit for bit ([`bits`]).

use glam::{DVec3, Mat4, Vec2, Vec3, Vec4};
use render_lessons::framebuffer::Framebuffer;
use render_lessons::ray::Ray;
use render_lessons::shapes::Hit;

/// The largest absolute difference between two values, component by component.
pub trait Gap: Copy + std::fmt::Debug {
    fn gap(self, other: Self) -> f64;
}

impl Gap for f32 {
    fn gap(self, other: f32) -> f64 {
        f64::from((self - other).abs())
    }
}

impl Gap for f64 {
    fn gap(self, other: f64) -> f64 {
        (self - other).abs()
    }
}

impl Gap for (f32, f32) {
    fn gap(self, other: (f32, f32)) -> f64 {
        self.0.gap(other.0).max(self.1.gap(other.1))
    }
}

impl Gap for Vec2 {
    fn gap(self, other: Vec2) -> f64 {
        f64::from((self - other).abs().max_element())
    }
}

impl Gap for Vec3 {
    fn gap(self, other: Vec3) -> f64 {
        f64::from((self - other).abs().max_element())
    }
}

impl Gap for Vec4 {
    fn gap(self, other: Vec4) -> f64 {
        f64::from((self - other).abs().max_element())
    }
}

impl Gap for DVec3 {
    fn gap(self, other: DVec3) -> f64 {
        (self - other).abs().max_element()
    }
}

impl Gap for Mat4 {
    fn gap(self, other: Mat4) -> f64 {
        (0..4)
            .map(|i| self.col(i).gap(other.col(i)))
            .fold(0.0, f64::max)
    }
}

/// `a` and `b` differ by at most `tol` in every component (NaN is never close).
pub fn close<T: Gap>(a: T, b: T, tol: impl Into<f64>) -> bool {
    a.gap(b) <= tol.into()
}

/// Panics, naming both values and the tolerance, unless [`close`].
#[track_caller]
pub fn assert_close<T: Gap>(got: T, want: T, tol: impl Into<f64>) {
    let tol = tol.into();
    assert!(
        close(got, want, tol),
        "got {got:?}, want {want:?} (tolerance {tol:e})"
    );
}

/// A value's floats as their bits, in order, so that -0 and 0 (and two NaNs)
/// count as different.
pub trait Bits {
    fn push_bits(&self, out: &mut Vec<u32>);
}

/// Every float of `value` as its bits: two values are the same bit for bit when
/// their `bits` are equal.
pub fn bits<T: Bits + ?Sized>(value: &T) -> Vec<u32> {
    let mut out = Vec::new();
    value.push_bits(&mut out);
    out
}

impl Bits for f32 {
    fn push_bits(&self, out: &mut Vec<u32>) {
        out.push(self.to_bits());
    }
}

impl Bits for Vec2 {
    fn push_bits(&self, out: &mut Vec<u32>) {
        out.extend(self.to_array().map(f32::to_bits));
    }
}

impl Bits for Vec3 {
    fn push_bits(&self, out: &mut Vec<u32>) {
        out.extend(self.to_array().map(f32::to_bits));
    }
}

impl Bits for Ray {
    fn push_bits(&self, out: &mut Vec<u32>) {
        self.origin().push_bits(out);
        self.direction().push_bits(out);
    }
}

/// A hit's `t`, which face, point, normal and error bound.
impl Bits for Hit {
    fn push_bits(&self, out: &mut Vec<u32>) {
        self.t.push_bits(out);
        out.push(u32::from(self.front_face));
        self.point.push_bits(out);
        self.normal.push_bits(out);
        self.error.push_bits(out);
    }
}

/// Every pixel, row by row.
impl Bits for Framebuffer {
    fn push_bits(&self, out: &mut Vec<u32>) {
        for y in 0..self.height() {
            for x in 0..self.width() {
                self.get(x, y).expect("inside").push_bits(out);
            }
        }
    }
}

impl<T: Bits> Bits for [T] {
    fn push_bits(&self, out: &mut Vec<u32>) {
        for v in self {
            v.push_bits(out);
        }
    }
}

impl<T: Bits> Bits for Vec<T> {
    fn push_bits(&self, out: &mut Vec<u32>) {
        self.as_slice().push_bits(out);
    }
}

impl<T: Bits> Bits for Option<T> {
    fn push_bits(&self, out: &mut Vec<u32>) {
        out.push(u32::from(self.is_some()));
        if let Some(v) = self {
            v.push_bits(out);
        }
    }
}
