//! One error type for the whole crate: every constructor that can be handed bad
//! input returns it, and every variant names the parameter at fault.

use std::fmt;

use glam::Vec3;

/// What went wrong, and with which parameter.
#[derive(Clone, Debug, PartialEq)]
pub enum Error {
    /// A number was NaN or infinite.
    NotFinite { param: &'static str },
    /// A direction (or other vector that must have a length) was zero.
    ZeroLength { param: &'static str },
    /// A value that must be strictly positive was not.
    NotPositive { param: &'static str, value: f32 },
    /// A value that must be 0 or more was negative.
    Negative { param: &'static str, value: f32 },
    /// The up vector is parallel to the view direction, so no camera frame exists
    /// (STABILITY S10).
    UpParallelToDirection { param: &'static str },
    /// An image resolution was 0 or larger than `max` (for images, `limits::MAX_RESOLUTION`).
    Resolution {
        param: &'static str,
        value: u32,
        max: u32,
    },
    /// A range such as `x_min..x_max` was empty or inverted.
    EmptyRange {
        param: &'static str,
        min: f32,
        max: f32,
    },
    /// Three vectors that should form an orthonormal basis do not.
    NotOrthonormal { param: &'static str, error: f32 },
    /// A matrix that must be symmetric is not (relative asymmetry `error`).
    NotSymmetric { param: &'static str, error: f32 },
    /// A matrix has no inverse.
    Singular { param: &'static str },
    /// The operating system would not start a pool of `threads` worker threads.
    ThreadPool {
        param: &'static str,
        threads: usize,
        message: String,
    },
    /// A pixel holds NaN or infinity and must not be written to an image.
    NonFinitePixel { x: u32, y: u32 },
    /// Reading or writing a file failed.
    Io { path: String, message: String },
    /// Triangle number `triangle` (0-based) refers to vertex `index`, but the mesh
    /// has only `vertices` vertices.
    VertexIndex {
        triangle: usize,
        index: u32,
        vertices: usize,
    },
    /// A count such as a sphere's number of segments was below its minimum.
    TooFew {
        param: &'static str,
        value: u32,
        min: u32,
    },
    /// A parameter's value is outside what it may be; `reason` says what is allowed.
    Invalid {
        param: &'static str,
        reason: &'static str,
    },
    /// A parameter asks for more than the machine can give: `needed` units where
    /// `limit` are allowed (`unit` is "bytes", "threads", ...).
    TooMuch {
        param: &'static str,
        needed: u64,
        limit: u64,
        unit: &'static str,
    },
    /// A PFM image could not be read: `path` names the file (or the bytes), `message`
    /// says what is wrong with it.
    Pfm { path: String, message: String },
    /// An OBJ file could not be turned into a mesh; `line` (1-based) when known.
    Obj {
        path: String,
        line: Option<usize>,
        message: String,
    },
}

/// The crate's result type.
pub type Result<T> = std::result::Result<T, Error>;

impl Error {
    /// The name of the parameter at fault, as the caller spelled it (for a file, its
    /// path).
    pub fn param(&self) -> &str {
        match self {
            Error::NonFinitePixel { .. } => "pixel",
            Error::Io { path, .. } | Error::Obj { path, .. } | Error::Pfm { path, .. } => path,
            Error::VertexIndex { .. } => "triangle",
            named => named.clone().param_field().map_or("", |param| *param),
        }
    }

    /// The `param` field of the variants that have one, to read or to rewrite: the
    /// course puts the flag the user typed in it (`course::lesson::as_typed`).
    pub fn param_field(&mut self) -> Option<&mut &'static str> {
        match self {
            Error::NotFinite { param }
            | Error::ZeroLength { param }
            | Error::NotPositive { param, .. }
            | Error::Negative { param, .. }
            | Error::Resolution { param, .. }
            | Error::EmptyRange { param, .. }
            | Error::NotOrthonormal { param, .. }
            | Error::NotSymmetric { param, .. }
            | Error::Singular { param }
            | Error::TooFew { param, .. }
            | Error::Invalid { param, .. }
            | Error::TooMuch { param, .. }
            | Error::UpParallelToDirection { param }
            | Error::ThreadPool { param, .. } => Some(param),
            Error::NonFinitePixel { .. }
            | Error::Io { .. }
            | Error::Obj { .. }
            | Error::Pfm { .. }
            | Error::VertexIndex { .. } => None,
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::NotFinite { param } => write!(f, "{param} must be a finite number"),
            Error::ZeroLength { param } => write!(f, "{param} must not have zero length"),
            Error::NotPositive { param, value } => {
                write!(f, "{param} must be greater than 0 (got {value})")
            }
            Error::Negative { param, value } => {
                write!(f, "{param} must be 0 or more (got {value})")
            }
            Error::UpParallelToDirection { param } => write!(
                f,
                "{param} must not be parallel to direction: no camera frame can be built"
            ),
            Error::Resolution { param, value, max } => write!(
                f,
                "{param} must be between 1 and {max} pixels (got {value})"
            ),
            Error::EmptyRange { param, min, max } => {
                write!(f, "{param} must have min < max (got {min} .. {max})")
            }
            Error::NotOrthonormal { param, error } => {
                write!(f, "{param} is not orthonormal (error {error:e})")
            }
            Error::NotSymmetric { param, error } => {
                write!(
                    f,
                    "{param} must be symmetric (relative asymmetry {error:e})"
                )
            }
            Error::Singular { param } => write!(f, "{param} is singular: it has no inverse"),
            Error::NonFinitePixel { x, y } => {
                write!(
                    f,
                    "pixel ({x}, {y}) is NaN or infinite; refusing to write it"
                )
            }
            Error::ThreadPool {
                param,
                threads,
                message,
            } => {
                write!(
                    f,
                    "{param}: could not start {threads} worker threads ({message})"
                )
            }
            Error::Io { path, message } | Error::Pfm { path, message } => {
                write!(f, "{path}: {message}")
            }
            Error::TooFew { param, value, min } => {
                write!(f, "{param} must be at least {min} (got {value})")
            }
            Error::Invalid { param, reason } => write!(f, "{param} {reason}"),
            Error::TooMuch {
                param,
                needed,
                limit,
                unit: "bytes",
            } => write!(
                f,
                "{param} would need {} of memory, more than the {} this machine allows",
                bytes(*needed),
                bytes(*limit)
            ),
            Error::TooMuch {
                param,
                needed,
                limit,
                unit,
            } => write!(
                f,
                "{param} asks for {needed} {unit}, more than the limit of {limit}"
            ),
            Error::VertexIndex {
                triangle,
                index,
                vertices,
            } => write!(
                f,
                "triangle {triangle} refers to vertex {index}, but the mesh has {vertices} vertices"
            ),
            Error::Obj {
                path,
                line: Some(line),
                message,
            } => write!(f, "{path}, line {line}: {message}"),
            Error::Obj {
                path,
                line: None,
                message,
            } => write!(f, "{path}: {message}"),
        }
    }
}

impl std::error::Error for Error {}

/// A byte count in the unit a person reads: "3.2 GiB", "512 MiB".
fn bytes(n: u64) -> String {
    const MIB: f64 = 1024.0 * 1024.0;
    let n = n as f64;
    if n >= 1024.0 * MIB {
        format!("{:.1} GiB", n / (1024.0 * MIB))
    } else {
        format!("{:.0} MiB", (n / MIB).ceil())
    }
}

/// `value` itself if it is finite, else [`Error::NotFinite`] naming `param`.
pub fn finite(param: &'static str, value: f32) -> Result<f32> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NotFinite { param })
    }
}

/// `v` itself if all three components are finite.
pub fn finite3(param: &'static str, v: Vec3) -> Result<Vec3> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(Error::NotFinite { param })
    }
}

/// `v / |v|` if `v` is finite and not zero.
///
/// A vector too long or too short to normalise directly in f32 (|v|^2 beyond
/// f32::MAX, or below f32::MIN_POSITIVE, the smallest normal float) is scaled first,
/// so every finite non-zero vector comes out unit, and only a zero vector is
/// rejected as having zero length.
pub fn unit(param: &'static str, v: Vec3) -> Result<Vec3> {
    let v = finite3(param, v)?;
    // |v|^2 overflows past about 1.8e19 per component, and below about 1e-19 it is
    // subnormal or 0: with a few significant bits left, |v| and so v / |v| come out
    // wrong by up to a few parts in a thousand. Dividing by the largest component
    // first changes nothing for a vector of sane length, which skips it.
    let length2 = v.length_squared();
    let n = if (f32::MIN_POSITIVE..=f32::MAX).contains(&length2) {
        v.normalize_or_zero()
    } else {
        (v / v.abs().max_element()).normalize_or_zero()
    };
    if n == Vec3::ZERO {
        Err(Error::ZeroLength { param })
    } else {
        Ok(n)
    }
}

/// `value` if it is finite and strictly positive.
pub fn positive(param: &'static str, value: f32) -> Result<f32> {
    if finite(param, value)? > 0.0 {
        Ok(value)
    } else {
        Err(Error::NotPositive { param, value })
    }
}

/// `value` if it is finite and 0 or more, else an error naming `param`.
pub fn non_negative(param: &'static str, value: f32) -> Result<f32> {
    if finite(param, value)? >= 0.0 {
        Ok(value)
    } else {
        Err(Error::Negative { param, value })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every finite non-zero vector comes out unit, however short or long: from
    /// components of 1e-45 (the smallest subnormal) through the range where |v|^2 is
    /// subnormal (3e-22: |v| - 1 was +1.8e-3 before the rescaling) to 1e38.
    #[test]
    fn unit_is_unit_for_tiny_subnormal_and_huge_vectors() {
        for scale in [1e-45f32, 1e-40, 3e-22, 4e-23, 1e-19, 1e-10, 1.0, 1e19, 1e38] {
            for v in [Vec3::new(1.0, 1.0, 0.0), Vec3::new(0.3, -1.0, 0.7), Vec3::X] {
                // The input as f32 holds it (at 1e-45 the small parts round away),
                // and its direction in f64.
                let w = v * scale;
                let Ok(n) = unit("v", w) else {
                    panic!("{w} was rejected");
                };
                let exact = w.as_dvec3().normalize();
                assert!((n.length() - 1.0).abs() < 1e-6, "{w}: |n| = {}", n.length());
                assert!(
                    (n.as_dvec3() - exact).length() < 1e-6,
                    "{w}: {n} against {exact}"
                );
            }
        }
        assert_eq!(unit("v", Vec3::ZERO), Err(Error::ZeroLength { param: "v" }));
    }
}
