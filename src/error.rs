//! The renderer's errors, grouped by what failed: a value handed in, a file, or
//! the machine. Every error names what was at fault: a value or a request names its
//! parameter, a file its path. How an error reads as a lesson's flag is the course's
//! business (`course::lesson::errors`), not the renderer's.

use std::fmt;

use glam::Vec3;

/// What failed, and with which parameter or file.
#[derive(Clone, Debug, PartialEq)]
pub enum Error {
    /// A value handed to a constructor or a writer is not one it can use.
    Value {
        /// The parameter, as the caller spelled it.
        param: &'static str,
        /// What is wrong with its value.
        problem: Problem,
    },
    /// A file could not be read, written or understood; `line` (1-based) when known.
    File {
        /// The file, as the caller named it.
        path: String,
        /// The line at fault, from 1, when known.
        line: Option<usize>,
        /// What went wrong.
        message: String,
    },
    /// A value asks for more than the machine can give.
    Machine {
        /// The parameter that asks for too much.
        param: &'static str,
        /// What the machine cannot give.
        shortfall: Shortfall,
    },
}

/// What is wrong with a value. Each reads after the parameter's name: "radius"
/// + "must be greater than 0 (got -1)".
#[derive(Clone, Debug, PartialEq)]
pub enum Problem {
    /// NaN or infinite.
    NotFinite,
    /// A direction (or other vector that must have a length) was zero.
    ZeroLength,
    /// Must be strictly positive.
    NotPositive {
        /// The value given.
        value: f32,
    },
    /// Must be 0 or more.
    Negative {
        /// The value given.
        value: f32,
    },
    /// The up vector is parallel to the view direction, so no camera frame exists
    /// (STABILITY S10).
    UpParallelToDirection,
    /// An image resolution was 0 or larger than `max` (for images,
    /// `limits::MAX_RESOLUTION`).
    Resolution {
        /// The resolution given.
        value: u32,
        /// The largest allowed.
        max: u32,
    },
    /// A range such as `x_min..x_max` was empty or inverted.
    EmptyRange {
        /// The range's lower end.
        min: f32,
        /// The range's upper end.
        max: f32,
    },
    /// Three vectors that should form an orthonormal basis do not.
    NotOrthonormal {
        /// The largest departure of a dot product from 0 or 1.
        error: f32,
    },
    /// A matrix that must be symmetric is not (relative asymmetry `error`).
    NotSymmetric {
        /// The relative asymmetry.
        error: f32,
    },
    /// A matrix has no inverse.
    Singular,
    /// A count such as a sphere's number of segments was below its minimum.
    TooFew {
        /// The count given.
        value: u32,
        /// The smallest allowed.
        min: u32,
    },
    /// Outside what the parameter may be; `reason` says what is allowed.
    Invalid {
        /// What is allowed, as a phrase after "must".
        reason: &'static str,
    },
    /// A pixel holds NaN or infinity and must not be written to an image.
    NonFinitePixel {
        /// The pixel's column.
        x: u32,
        /// The pixel's row.
        y: u32,
    },
    /// Triangle number `triangle` (0-based) refers to vertex `index`, but the mesh
    /// has only `vertices` vertices.
    VertexIndex {
        /// The triangle, from 0.
        triangle: usize,
        /// The vertex it names.
        index: u32,
        /// How many vertices the mesh has.
        vertices: usize,
    },
}

/// What the machine cannot give.
#[derive(Clone, Debug, PartialEq)]
pub enum Shortfall {
    /// `needed` units where `limit` are allowed (`unit` is "bytes", "threads", ...).
    TooMuch {
        /// What the value asks for.
        needed: u64,
        /// What is allowed.
        limit: u64,
        /// The unit of both: "bytes", "threads", ...
        unit: &'static str,
    },
    /// The operating system would not start a pool of `threads` worker threads.
    ThreadPool {
        /// The worker threads asked for.
        threads: usize,
        /// The operating system's answer.
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
            Error::Value { param, .. } | Error::Machine { param, .. } => param,
            Error::File { path, .. } => path,
        }
    }

    /// What is wrong, without the parameter's name: the error reads
    /// "{param} {what}" ("radius must be greater than 0 (got -1)"), so a lesson
    /// can put its own name for the parameter, its flag, in front.
    pub fn what(&self) -> String {
        match self {
            Error::Value { problem, .. } => problem.to_string(),
            Error::Machine { shortfall, .. } => shortfall.to_string(),
            Error::File {
                line: Some(line),
                message,
                ..
            } => format!("line {line}: {message}"),
            Error::File { message, .. } => message.clone(),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Value { param, problem } => write!(f, "{param} {problem}"),
            Error::Machine { param, shortfall } => write!(f, "{param} {shortfall}"),
            Error::File {
                path,
                line: Some(line),
                message,
            } => write!(f, "{path}, line {line}: {message}"),
            Error::File {
                path,
                line: None,
                message,
            } => write!(f, "{path}: {message}"),
        }
    }
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Problem::NotFinite => write!(f, "must be a finite number"),
            Problem::ZeroLength => write!(f, "must not have zero length"),
            Problem::NotPositive { value } => {
                write!(f, "must be greater than 0 (got {value})")
            }
            Problem::Negative { value } => write!(f, "must be 0 or more (got {value})"),
            Problem::UpParallelToDirection => write!(
                f,
                "must not be parallel to direction: no camera frame can be built"
            ),
            Problem::Resolution { value, max } => {
                write!(f, "must be between 1 and {max} pixels (got {value})")
            }
            Problem::EmptyRange { min, max } => {
                write!(f, "must have min < max (got {min} .. {max})")
            }
            Problem::NotOrthonormal { error } => {
                write!(f, "is not orthonormal (error {error:e})")
            }
            Problem::NotSymmetric { error } => {
                write!(f, "must be symmetric (relative asymmetry {error:e})")
            }
            Problem::Singular => write!(f, "is singular: it has no inverse"),
            Problem::TooFew { value, min } => {
                write!(f, "must be at least {min} (got {value})")
            }
            Problem::Invalid { reason } => write!(f, "{reason}"),
            Problem::NonFinitePixel { x, y } => {
                write!(f, "({x}, {y}) is NaN or infinite; refusing to write it")
            }
            Problem::VertexIndex {
                triangle,
                index,
                vertices,
            } => write!(
                f,
                "{triangle} refers to vertex {index}, but the mesh has {vertices} vertices"
            ),
        }
    }
}

impl fmt::Display for Shortfall {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Shortfall::TooMuch {
                needed,
                limit,
                unit: "bytes",
            } => write!(
                f,
                "would need {} of memory, more than the {} this machine allows",
                bytes(*needed),
                bytes(*limit)
            ),
            Shortfall::TooMuch {
                needed,
                limit,
                unit,
            } => write!(
                f,
                "asks for {needed} {unit}, more than the limit of {limit}"
            ),
            Shortfall::ThreadPool { threads, message } => write!(
                f,
                "asks for {threads} worker threads, which the system would not start ({message})"
            ),
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

/// `value` itself if it is finite, else a `Problem::NotFinite` error naming `param`.
pub fn finite(param: &'static str, value: f32) -> Result<f32> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::Value {
            param,
            problem: Problem::NotFinite,
        })
    }
}

/// Every corner of every triangle names one of `vertices` vertices, else a
/// `Problem::VertexIndex` error naming the first triangle that does not.
pub fn vertex_indices(triangles: &[[u32; 3]], vertices: usize) -> Result<()> {
    for (triangle, t) in triangles.iter().enumerate() {
        if let Some(&index) = t.iter().find(|&&i| i as usize >= vertices) {
            return Err(Error::Value {
                param: "triangle",
                problem: Problem::VertexIndex {
                    triangle,
                    index,
                    vertices,
                },
            });
        }
    }
    Ok(())
}

/// `v` itself if all three components are finite.
pub fn finite3(param: &'static str, v: Vec3) -> Result<Vec3> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(Error::Value {
            param,
            problem: Problem::NotFinite,
        })
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
    unit_and_length(v).map(|(n, _)| n).ok_or(Error::Value {
        param,
        problem: Problem::ZeroLength,
    })
}

/// `v / |v|` and `|v|`, from one square root, for a finite non-zero `v`; `None` for
/// any other. What [`unit`] computes, for a vector the renderer makes itself (a
/// shadow ray's gap between two points), which needs its length too and no error
/// message.
#[inline]
pub(crate) fn unit_and_length(v: Vec3) -> Option<(Vec3, f32)> {
    let length2 = v.length_squared();
    if (f32::MIN_POSITIVE..=f32::MAX).contains(&length2) {
        return Some(v.normalize_and_length());
    }
    // |v|^2 overflows past about 1.8e19 per component, and below about 1e-19 it is
    // subnormal or 0: with a few significant bits left, |v| and so v / |v| come out
    // wrong by up to a few parts in a thousand. Dividing by the largest component
    // first, whose scaled length is then between 1 and sqrt(3), avoids both.
    let largest = v.abs().max_element();
    if !v.is_finite() || largest == 0.0 {
        return None;
    }
    let (n, length) = (v / largest).normalize_and_length();
    Some((n, length * largest))
}

/// `value` if it is finite and strictly positive.
pub fn positive(param: &'static str, value: f32) -> Result<f32> {
    if finite(param, value)? > 0.0 {
        Ok(value)
    } else {
        Err(Error::Value {
            param,
            problem: Problem::NotPositive { value },
        })
    }
}

/// `value` if it is finite and 0 or more, else an error naming `param`.
pub fn non_negative(param: &'static str, value: f32) -> Result<f32> {
    if finite(param, value)? >= 0.0 {
        Ok(value)
    } else {
        Err(Error::Value {
            param,
            problem: Problem::Negative { value },
        })
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
                // The length too (a shadow ray's): right to 1e-6 wherever it is a
                // normal f32 (at 1e-45 it is itself a subnormal, with one bit).
                let (m, length) = unit_and_length(w).unwrap();
                let exact = w.as_dvec3().length();
                assert_eq!(m, n, "{w}");
                if exact >= f64::from(f32::MIN_POSITIVE) {
                    assert!(
                        (f64::from(length) / exact - 1.0).abs() < 1e-6,
                        "{w}: {length} against {exact}"
                    );
                }
            }
        }
        for v in [
            Vec3::ZERO,
            Vec3::new(f32::NAN, 1.0, 0.0),
            Vec3::Y * f32::INFINITY,
        ] {
            assert_eq!(unit_and_length(v), None, "{v}");
        }
        assert_eq!(
            unit("v", Vec3::ZERO),
            Err(Error::Value {
                param: "v",
                problem: Problem::ZeroLength
            })
        );
    }
}
