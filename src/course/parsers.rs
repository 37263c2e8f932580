//! The value parsers of the lessons' flags: each turns the text typed after a flag
//! into a checked value, or into a one-line reason that clap prints after the flag's
//! name (`error: invalid value 'nan' for '--angle <ANGLE>': 'nan' is not a finite
//! number`) before any work, with exit code 2.

use glam::Vec3;

use crate::error::{self, Error, Problem};

/// The largest angle a lesson takes, in degrees: a hundred turns. Beyond it f32
/// degrees are too coarse to mean anything (at 1e7 two neighbouring values lie a
/// whole degree apart).
pub const MAX_DEGREES: f32 = 36_000.0;

/// The number typed, `s`, checked by one of the core's validators
/// ([`error::finite`], [`error::positive`], [`error::non_negative`]): the rules are
/// the core's, only the reason is worded for the command line, where clap has named
/// the flag already.
fn checked(
    s: &str,
    check: fn(&'static str, f32) -> crate::Result<f32>,
) -> Result<f32, String> {
    let value = s
        .trim()
        .parse::<f32>()
        .map_err(|_| format!("'{s}' is not a number"))?;
    check("value", value).map_err(|e| match e {
        Error::Value {
            problem: Problem::NotFinite,
            ..
        } => format!("'{s}' is not a finite number"),
        Error::Value {
            problem: Problem::NotPositive { .. },
            ..
        } => format!("'{s}' must be greater than 0"),
        Error::Value {
            problem: Problem::Negative { .. },
            ..
        } => format!("'{s}' is negative: it must be 0 or more"),
        other => other.to_string(),
    })
}

/// A finite number (Rust's own parser also accepts `nan` and `inf`).
pub fn finite(s: &str) -> Result<f32, String> {
    checked(s, error::finite)
}

/// A finite number that is 0 or more.
pub fn non_negative(s: &str) -> Result<f32, String> {
    checked(s, error::non_negative)
}

/// A finite number greater than 0.
pub fn positive(s: &str) -> Result<f32, String> {
    checked(s, error::positive)
}

/// An angle in degrees within ±[`MAX_DEGREES`].
pub fn degrees(s: &str) -> Result<f32, String> {
    match finite(s)? {
        v if v.abs() <= MAX_DEGREES => Ok(v),
        _ => Err(format!(
            "'{s}' must lie within ±36000 degrees (a hundred turns)"
        )),
    }
}

/// A count of pixels from 1 to `max`, for a flag such as `--view-width`.
pub fn pixels(max: u32) -> clap::builder::RangedI64ValueParser<u32> {
    clap::value_parser!(u32).range(1..=i64::from(max))
}

/// `x,y,z` (as typed after a flag such as `--direction 0,0,-1`): three finite numbers.
pub fn vec3(s: &str) -> Result<Vec3, String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    let [x, y, z] = parts.as_slice() else {
        return Err(format!("expected three numbers x,y,z, got '{s}'"));
    };
    let mut v = [0.0f32; 3];
    for (slot, text) in v.iter_mut().zip([x, y, z]) {
        *slot = finite(text)?;
    }
    Ok(Vec3::from_array(v))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hostile_text_is_refused_with_a_reason() {
        for bad in ["nan", "inf", "-inf", "abc", ""] {
            assert!(finite(bad).is_err(), "{bad}");
            assert!(degrees(bad).is_err(), "{bad}");
        }
        assert_eq!(finite(" -1.5 "), Ok(-1.5));
        assert!(non_negative("-1").is_err());
        assert_eq!(non_negative("-0"), Ok(-0.0));
        assert!(positive("0").is_err());
        assert_eq!(degrees("-36000"), Ok(-36000.0));
        assert!(degrees("36000.01").is_err());
        assert_eq!(vec3("1, -2,3"), Ok(Vec3::new(1.0, -2.0, 3.0)));
        for bad in ["1,2", "1,2,3,4", "a,b,c", "nan,0,0", ""] {
            assert!(vec3(bad).is_err(), "{bad}");
        }
    }
}
