//! Lesson 10's floating-point image file: what `pfm_bytes` writes, `read_pfm`
//! reads back bit for bit, and every malformed file is refused with an error that
//! names the file and what is wrong.

use crate::common::bits;
use glam::Vec3;
use render_lessons::error::Error;
use render_lessons::framebuffer::Framebuffer;
use render_lessons::framebuffer::pfm::{load_pfm, pfm_bytes, read_pfm, save_pfm};

/// Values that a lossy reader would change: signed zero, a subnormal, the largest
/// and smallest normal floats, values with every mantissa bit set.
fn awkward(x: u32, y: u32) -> Vec3 {
    let pick = [
        -0.0,
        f32::from_bits(1),
        f32::MAX,
        f32::MIN_POSITIVE,
        1.0 - f32::EPSILON / 2.0,
        -123.456,
        std::f32::consts::PI,
    ];
    let i = (x * 3 + y * 5) as usize;
    Vec3::new(pick[i % 7], pick[(i + 1) % 7], pick[(i + 3) % 7])
}

#[test]
fn round_trip_keeps_every_bit_and_the_row_order() {
    let image = Framebuffer::from_fn(7, 5, awkward).unwrap();
    let back = read_pfm(&pfm_bytes(&image).unwrap()).unwrap();
    assert_eq!((back.width(), back.height()), (7, 5));
    assert_eq!(bits(&back), bits(&image));
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("awkward.pfm");
    save_pfm(&path, &image).unwrap();
    assert_eq!(bits(&load_pfm(&path).unwrap()), bits(&image));
}

/// A PFM written by hand: `tag`, the size, `scale`, then `values` as they are, in
/// the byte order the scale's sign says.
fn hand_made(tag: &str, w: u32, h: u32, scale: &str, values: &[f32]) -> Vec<u8> {
    let mut bytes = format!("{tag}\n{w} {h}\n{scale}\n").into_bytes();
    let little = scale.starts_with('-');
    for v in values {
        bytes.extend(if little {
            v.to_le_bytes()
        } else {
            v.to_be_bytes()
        });
    }
    bytes
}

#[test]
fn big_endian_grey_and_scaled_files_are_read_as_other_programs_write_them() {
    // Big-endian (positive scale), two pixels, the bottom row first in the file.
    let big = hand_made("PF", 1, 2, "1.0", &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    let image = read_pfm(&big).unwrap();
    assert_eq!(image.get(0, 1), Some(Vec3::new(1.0, 2.0, 3.0)));
    assert_eq!(image.get(0, 0), Some(Vec3::new(4.0, 5.0, 6.0)));
    // Grey: one channel, read as three equal ones.
    let grey = hand_made("Pf", 2, 1, "-1.0", &[0.25, 0.75]);
    let image = read_pfm(&grey).unwrap();
    assert_eq!(image.get(1, 0), Some(Vec3::splat(0.75)));
    // A scale of magnitude 2 doubles every value (pbrt-v3's reader does the same).
    let scaled = hand_made("PF", 1, 1, "-2.0", &[1.0, 0.5, 0.25]);
    assert_eq!(
        read_pfm(&scaled).unwrap().get(0, 0),
        Some(Vec3::new(2.0, 1.0, 0.5))
    );
}

/// The message of `read_pfm(bytes)`'s error, which must be an `Error::File`.
fn message(bytes: &[u8]) -> String {
    match read_pfm(bytes) {
        Err(Error::File {
            path,
            line: None,
            message,
        }) => {
            assert_eq!(path, "PFM data");
            message
        }
        other => panic!("expected a PFM error, got {other:?}"),
    }
}

#[test]
fn malformed_files_are_refused_saying_what_is_wrong() {
    let cases: [(&str, Vec<u8>, &str); 9] = [
        ("empty", Vec::new(), "bad header: empty"),
        ("a PNM", b"P6\n1 1\n255\n...".to_vec(), "not PF or Pf"),
        ("no size", b"PF\n".to_vec(), "bad header: no width"),
        (
            "size not a number",
            b"PF\n2 x\n-1.0\n".to_vec(),
            "height \"x\"",
        ),
        ("scale 0", b"PF\n1 1\n0\n".to_vec(), "scale \"0\""),
        ("scale NaN", b"PF\n1 1\nnan\n".to_vec(), "scale \"nan\""),
        (
            "one value short",
            hand_made("PF", 1, 1, "-1.0", &[1.0, 2.0]),
            "need 12 bytes, found 8",
        ),
        (
            "one value too many",
            hand_made("PF", 1, 1, "-1.0", &[1.0, 2.0, 3.0, 4.0]),
            "need 12 bytes, found 16",
        ),
        (
            "zero width",
            hand_made("PF", 0, 1, "-1.0", &[]),
            "wrong size: 0 x 1",
        ),
    ];
    for (what, bytes, expected) in cases {
        let got = message(&bytes);
        assert!(got.contains(expected), "{what}: {got:?}");
    }
    let nan = hand_made("PF", 2, 1, "-1.0", &[0.0, 0.0, 0.0, 1.0, f32::NAN, 1.0]);
    assert_eq!(message(&nan), "pixel (1, 0) is NaN or infinite");
    let inf = hand_made("Pf", 1, 2, "-1.0", &[f32::INFINITY, 0.0]);
    assert_eq!(message(&inf), "pixel (0, 1) is NaN or infinite");
}

#[test]
fn a_file_s_errors_name_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("short.pfm");
    std::fs::write(&path, hand_made("PF", 2, 2, "-1.0", &[1.0])).unwrap();
    let err = load_pfm(&path).unwrap_err();
    assert_eq!(err.param(), path.display().to_string());
    assert!(
        err.to_string()
            .starts_with(&format!("{}: wrong size", path.display())),
        "{err}"
    );
    let missing = dir.path().join("missing.pfm");
    let err = load_pfm(&missing).unwrap_err();
    assert!(matches!(err, Error::File { .. }), "{err:?}");
    assert_eq!(err.param(), missing.display().to_string());
}

#[test]
fn pfm_has_its_header_and_rows_from_the_bottom() {
    let img = render_lessons::framebuffer::Framebuffer::from_fn(2, 2, |x, y| {
        Vec3::new(x as f32, y as f32, 0.5)
    })
    .unwrap();
    let bytes = render_lessons::framebuffer::pfm::pfm_bytes(&img).unwrap();
    let header = b"PF\n2 2\n-1.0\n";
    assert_eq!(&bytes[..header.len()], header);
    assert_eq!(bytes.len(), header.len() + 2 * 2 * 12);
    let first = f32::from_le_bytes(
        bytes[header.len() + 4..header.len() + 8]
            .try_into()
            .unwrap(),
    );
    assert_eq!(first, 1.0, "the first row written is the bottom row, y = 1");
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("x.pfm");
    render_lessons::framebuffer::pfm::save_pfm(&path, &img).unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), bytes);
    let nan = render_lessons::framebuffer::Framebuffer::from_fn(1, 1, |_, _| Vec3::NAN)
        .unwrap();
    assert!(render_lessons::framebuffer::pfm::pfm_bytes(&nan).is_err());
}
