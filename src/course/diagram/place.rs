//! Where a label goes: the nine places around its point, the offset of the text's
//! layout box for each, and the pixel box its ink then covers, which label
//! placement and the collision checks compare.

use glam::Vec2;

use super::glyphs::{glyphs, layout_size};

/// Where a label goes relative to its point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    /// To the right, vertically centred.
    Right,
    /// To the left, vertically centred.
    Left,
    /// Above, horizontally centred.
    Above,
    /// Below, horizontally centred.
    Below,
    /// Centred on the point.
    Centre,
    /// Above and to the right: the label's lower-left corner near the point.
    AboveRight,
    /// Above and to the left.
    AboveLeft,
    /// Below and to the right.
    BelowRight,
    /// Below and to the left.
    BelowLeft,
}

impl Place {
    /// Every place but the centre, nearest to this one first (its two neighbours,
    /// then theirs, the opposite place last); the centre alone for the centre.
    pub fn nearest_first(self) -> Vec<Place> {
        use Place::*;
        let ring = [
            Right, AboveRight, Above, AboveLeft, Left, BelowLeft, Below, BelowRight,
        ];
        let Some(i) = ring.iter().position(|p| *p == self) else {
            return vec![self];
        };
        let mut order = vec![self];
        for k in 1..=4 {
            order.push(ring[(i + k) % 8]);
            if k < 4 {
                order.push(ring[(i + 8 - k) % 8]);
            }
        }
        order
    }
}

/// A rectangle of the canvas in pixels (y down): where a label's ink lies.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PxBox {
    /// The top-left corner.
    pub min: Vec2,
    /// The bottom-right corner.
    pub max: Vec2,
}

impl PxBox {
    /// `true` if the two boxes share more than a touching edge.
    pub fn overlaps(&self, other: &PxBox) -> bool {
        self.min.x < other.max.x
            && other.min.x < self.max.x
            && self.min.y < other.max.y
            && other.min.y < self.max.y
    }

    /// `true` if a stroke from `a` to `b`, `half_width` pixels either side of its
    /// centre line, touches the box.
    pub(super) fn touches(&self, a: Vec2, b: Vec2, half_width: f32) -> bool {
        // The box grown by the half width against the segment, clipped (Liang-Barsky).
        let (lo, hi) = (self.min - half_width, self.max + half_width);
        let d = b - a;
        let (mut t0, mut t1) = (0.0f32, 1.0f32);
        for (p, q) in [
            (-d.x, a.x - lo.x),
            (d.x, hi.x - a.x),
            (-d.y, a.y - lo.y),
            (d.y, hi.y - a.y),
        ] {
            if p == 0.0 {
                if q < 0.0 {
                    return false;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    t0 = t0.max(r);
                } else {
                    t1 = t1.min(r);
                }
            }
        }
        t0 <= t1
    }
}

/// The gap between a point and its label, in pixels.
pub(super) const GAP: f32 = 6.0;

/// Where the text's layout box starts (top-left) relative to its point.
pub(super) fn offset(s: &str, size: f32, place: Place) -> Vec2 {
    let Some((width, height)) = layout_size(s, size) else {
        return Vec2::ZERO;
    };
    let (dx, dy) = match place {
        Place::Right => (GAP, -height * 0.5),
        Place::Left => (-GAP - width, -height * 0.5),
        Place::Above => (-width * 0.5, -GAP - height),
        Place::Below => (-width * 0.5, GAP),
        Place::Centre => (-width * 0.5, -height * 0.5),
        Place::AboveRight => (GAP, -GAP - height),
        Place::AboveLeft => (-GAP - width, -GAP - height),
        Place::BelowRight => (GAP, GAP),
        Place::BelowLeft => (-GAP - width, GAP),
    };
    Vec2::new(dx, dy)
}

/// The box the ink of `s` covers when placed at `at` as `place` says; `None` for
/// text with no ink.
pub(super) fn ink_box(at: Vec2, s: &str, size: f32, place: Place) -> Option<PxBox> {
    let mut b: Option<PxBox> = None;
    glyphs(at + offset(s, size, place), s, size, |g| {
        let r = g.px_bounds();
        let (min, max) = (Vec2::new(r.min.x, r.min.y), Vec2::new(r.max.x, r.max.y));
        b = Some(match b {
            None => PxBox { min, max },
            Some(b) => PxBox {
                min: b.min.min(min),
                max: b.max.max(max),
            },
        });
    });
    b
}
