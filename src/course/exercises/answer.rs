//! How the exercises' checks compare an answer with the reference and print it: with
//! a tolerance ([`TOLERANCE`]), and numbers with at most four decimals.

use glam::{Mat4, Vec2, Vec3};

/// Relative (and, near zero, absolute) tolerance of every comparison.
pub const TOLERANCE: f32 = 1e-4;

/// An answer that can be compared with tolerance and printed.
pub trait Answer {
    /// Equal within [`TOLERANCE`].
    fn close(&self, other: &Self) -> bool;
    /// Short, readable form: numbers with at most four decimals.
    fn show(&self) -> String;
}

impl Answer for f32 {
    /// Equal, or both finite and within [`TOLERANCE`]: an infinity is close only to
    /// itself (a relative tolerance scaled by it would accept any number), a NaN to
    /// nothing.
    fn close(&self, other: &f32) -> bool {
        *self == *other
            || (self.is_finite()
                && other.is_finite()
                && (self - other).abs()
                    <= TOLERANCE * 1f32.max(self.abs()).max(other.abs()))
    }
    fn show(&self) -> String {
        if !self.is_finite() {
            return format!("{self}");
        }
        let s = format!("{self:.4}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        if s == "-0" { "0".into() } else { s.into() }
    }
}

impl Answer for bool {
    fn close(&self, other: &bool) -> bool {
        self == other
    }
    fn show(&self) -> String {
        self.to_string()
    }
}

impl Answer for usize {
    fn close(&self, other: &usize) -> bool {
        self == other
    }
    fn show(&self) -> String {
        self.to_string()
    }
}

impl Answer for Vec2 {
    fn close(&self, other: &Vec2) -> bool {
        self.x.close(&other.x) && self.y.close(&other.y)
    }
    fn show(&self) -> String {
        format!("({}, {})", self.x.show(), self.y.show())
    }
}

impl Answer for Vec3 {
    fn close(&self, other: &Vec3) -> bool {
        self.x.close(&other.x) && self.y.close(&other.y) && self.z.close(&other.z)
    }
    fn show(&self) -> String {
        format!("({}, {}, {})", self.x.show(), self.y.show(), self.z.show())
    }
}

impl Answer for Mat4 {
    fn close(&self, other: &Mat4) -> bool {
        let (a, b) = (self.to_cols_array(), other.to_cols_array());
        a.iter().zip(&b).all(|(x, y)| x.close(y))
    }
    fn show(&self) -> String {
        let rows: Vec<String> = (0..4)
            .map(|i| {
                let r = self.row(i);
                format!(
                    "[{}, {}, {}, {}]",
                    r.x.show(),
                    r.y.show(),
                    r.z.show(),
                    r.w.show()
                )
            })
            .collect();
        format!("rows {}", rows.join(" "))
    }
}

impl<T: Answer, const N: usize> Answer for [T; N] {
    fn close(&self, other: &[T; N]) -> bool {
        self.iter().zip(other).all(|(a, b)| a.close(b))
    }
    fn show(&self) -> String {
        let items: Vec<String> = self.iter().map(Answer::show).collect();
        format!("[{}]", items.join(", "))
    }
}

impl<T: Answer> Answer for Option<T> {
    fn close(&self, other: &Option<T>) -> bool {
        match (self, other) {
            (Some(a), Some(b)) => a.close(b),
            (None, None) => true,
            _ => false,
        }
    }
    fn show(&self) -> String {
        match self {
            Some(a) => format!("Some({})", a.show()),
            None => "None".into(),
        }
    }
}

impl<A: Answer, B: Answer> Answer for (A, B) {
    fn close(&self, other: &(A, B)) -> bool {
        self.0.close(&other.0) && self.1.close(&other.1)
    }
    fn show(&self) -> String {
        format!("({}, {})", self.0.show(), self.1.show())
    }
}

impl<A: Answer, B: Answer, C: Answer> Answer for (A, B, C) {
    fn close(&self, other: &(A, B, C)) -> bool {
        self.0.close(&other.0) && self.1.close(&other.1) && self.2.close(&other.2)
    }
    fn show(&self) -> String {
        format!("({}, {}, {})", self.0.show(), self.1.show(), self.2.show())
    }
}
