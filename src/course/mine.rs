//! `--mine`: a lesson's picture drawn a second time, with the student's own code.
//!
//! Each `my_*` function gives the student's function of one coding exercise (from
//! `src/course/exercises/chNN.rs`) once its check passes. Otherwise it is an error
//! whose message says what to do: the check's report, which for a function still
//! `todo!()` names the file to write it in and the command that tests it, and
//! otherwise gives the case, expected, got and hint. The examples' `--mine` flags
//! call these; the pictures themselves are the examples' own, drawn with the
//! function given.

use glam::{Mat4, Vec2, Vec3};

use crate::camera::{Film, Frame};
use crate::course::exercises as ch;
use crate::course::exercises::check::{self, Exercise};
use crate::course::failure::{Failure, LessonResult};
use crate::error::Result;
use crate::framebuffer::Framebuffer;
use crate::lighting::AMBIENT;
use crate::ray::{Interval, Ray};
use crate::scene::{PointLight, Scene, SceneHit};
use crate::shapes::Shape;
use crate::spawn::{Offset, Start};
use crate::transform::Transform;

/// The signature of coding exercise 1.6, `compose(first, second)`.
pub type Compose = fn(&Transform, &Transform) -> Mat4;

/// The signature of coding exercise 3.5, `pixel_to_plane(film, px, py)`.
pub type PixelToPlane = fn(&Film, u32, u32) -> Vec2;

/// The signature of coding exercise 6.3, `pinhole_ray(film, s, frame, px, py)`.
pub type PinholeRay = fn(&Film, f32, &Frame, u32, u32) -> (Vec3, Vec3);

/// The signature of coding exercise 8.3, `closest(ray, shapes, range)`.
pub type Closest = fn(&Ray, &[Shape], Interval) -> Option<SceneHit>;

/// The signature of coding exercise 8.7, `lambert(p, n, albedo, light, visible)`.
pub type Lambert = fn(Vec3, Vec3, Vec3, &PointLight, bool) -> Vec3;

/// The student's `compose` for lesson 01's `--mine` (coding exercise 1.6).
pub fn my_compose() -> LessonResult<Compose> {
    passing(
        check::COMPOSE,
        check::check_compose(ch::ch01::compose),
        ch::ch01::compose,
    )
}

/// The student's `pixel_to_plane` for lesson 03's `--mine` (coding exercise 3.5).
pub fn my_pixel_to_plane() -> LessonResult<PixelToPlane> {
    passing(
        check::PIXEL_TO_PLANE,
        check::check_pixel_to_plane(ch::ch03::pixel_to_plane),
        ch::ch03::pixel_to_plane,
    )
}

/// The student's `pinhole_ray` for lesson 06's `--mine` (coding exercise 6.3).
pub fn my_pinhole_ray() -> LessonResult<PinholeRay> {
    passing(
        check::PINHOLE_RAY,
        check::check_pinhole_ray(ch::ch06::pinhole_ray),
        ch::ch06::pinhole_ray,
    )
}

/// The student's `closest` for lesson 08's `--mine` (coding exercise 8.3).
pub fn my_closest() -> LessonResult<Closest> {
    passing(
        check::CLOSEST,
        check::check_closest(ch::ch08::closest),
        ch::ch08::closest,
    )
}

/// The student's `lambert` for lesson 08's `--mine` (coding exercise 8.7).
pub fn my_lambert() -> LessonResult<Lambert> {
    passing(
        check::LAMBERT,
        check::check_lambert(ch::ch08::lambert),
        ch::ch08::lambert,
    )
}

/// For a lesson whose `--mine` draws several pictures, one per exercise: `Some` of
/// the student's function when its exercise passes; `None` when it does not, after
/// printing the check's report on stderr, so that the pictures of the exercises that
/// pass are still drawn.
pub fn if_passing<F>(mine: LessonResult<F>) -> LessonResult<Option<F>> {
    match mine {
        Ok(f) => Ok(Some(f)),
        Err(Failure::Exercise { report }) => {
            eprintln!("{report}\n(its --mine picture is not drawn)\n");
            Ok(None)
        }
        Err(e) => Err(e),
    }
}

/// Lesson 08's lit colour along `ray` (`raycast::lit` with the scaled offset), with
/// the Lambert formula `lambert` in place of the crate's: the closest hit, a shadow
/// ray to the scene's point light, then `lambert` at the hit.
pub fn lit_with(scene: &Scene, ray: &Ray, lambert: Lambert) -> Vec3 {
    let Some(found) = scene.closest(ray, Interval::AHEAD) else {
        return scene.background();
    };
    let (hit, colour) = (found.hit, scene.object(&found).colour());
    let Some(light) = scene.point_light() else {
        return colour * AMBIENT;
    };
    let from = Offset::Scaled.start(hit.point, hit.error, hit.facing());
    let visible = from
        .ray_to(Start::at(light.position))
        .is_some_and(|shadow| !scene.occluded(&shadow.ray, shadow.range));
    lambert(hit.point, hit.facing(), colour, &light, visible)
}

/// The student's function `f` of `exercise` if its check's `outcome` is a pass;
/// otherwise the check's report as the error.
fn passing<F>(exercise: Exercise, outcome: check::Outcome, f: F) -> LessonResult<F> {
    match outcome {
        check::Outcome::Pass => Ok(f),
        outcome => Err(Failure::Exercise {
            report: exercise.report(&outcome),
        }),
    }
}

/// A `--mine` picture of a lesson that renders images: its file name, the lesson's
/// picture it should equal, and how it is drawn at the lesson's image size with the
/// student's function (which `draw` holds).
/// [`crate::course::lesson::ImageFlags::run_with_mine`] draws and saves it after the
/// lesson's own images, and says how it compares with the lesson's ([`compared`]).
pub struct Picture {
    /// The file name, `NN_..._mine.png`.
    pub file: &'static str,
    /// The file name of the lesson's own picture, which a right answer redraws.
    pub like: &'static str,
    /// Draws the picture at `(width, height)` pixels.
    pub draw: Box<dyn Fn((u32, u32)) -> Result<Framebuffer> + Send + Sync>,
}

impl Picture {
    /// The picture `file`, drawn by `draw`, to be compared with the lesson's `like`.
    pub fn new(
        file: &'static str,
        like: &'static str,
        draw: impl Fn((u32, u32)) -> Result<Framebuffer> + Send + Sync + 'static,
    ) -> Picture {
        Picture {
            file,
            like,
            draw: Box::new(draw),
        }
    }
}

/// How a `--mine` picture differs from the lesson's: pixels compared as the 8-bit
/// RGBA bytes the PNG files hold.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Comparison {
    /// The pixels of the picture.
    pub pixels: usize,
    /// The pixels that differ in any channel.
    pub differing: usize,
    /// The largest difference of one channel, in levels of 255.
    pub levels: u8,
}

impl Comparison {
    /// The comparison of two pictures' RGBA bytes (of the same size).
    pub fn of(mine: &[u8], lesson: &[u8]) -> Comparison {
        let mut comparison = Comparison {
            pixels: mine.len() / 4,
            differing: 0,
            levels: 0,
        };
        for (a, b) in mine.chunks(4).zip(lesson.chunks(4)) {
            let levels = a.iter().zip(b).map(|(x, y)| x.abs_diff(*y)).max();
            if let Some(levels @ 1..) = levels {
                comparison.differing += 1;
                comparison.levels = comparison.levels.max(levels);
            }
        }
        comparison
    }

    /// One line for the student: the same picture; or the same but for rounding (one
    /// level of 255, in at most one pixel in a thousand: a right formula that does
    /// its arithmetic in another order than the crate's, which a byte-for-byte
    /// comparison such as `cmp` reports as different); or another picture.
    pub fn verdict(&self, mine: &str, lesson: &str) -> String {
        let Comparison {
            pixels,
            differing,
            levels,
        } = *self;
        let (pixel_s, differ) = if differing == 1 {
            ("pixel", "differs")
        } else {
            ("pixels", "differ")
        };
        if differing == 0 {
            format!("{mine} is {lesson}, byte for byte")
        } else if levels <= 1 && differing * 1000 <= pixels {
            format!(
                "{mine} is {lesson} but for rounding: {differing} {pixel_s} of {pixels} {differ} \
                 by 1 level of 255, as a right formula that rounds in another order than the \
                 crate's may give (`cmp` calls the files different; this comparison is the one \
                 to trust)"
            )
        } else {
            format!(
                "{mine} is not {lesson}: {differing} {pixel_s} of {pixels} {differ}, by up to \
                 {levels} levels of 255"
            )
        }
    }
}

/// How the picture `mine` compares with the lesson's PNG file `lesson` (written by
/// the same run): [`Comparison::verdict`]'s line, or `None` if that file cannot be
/// read or has another size.
pub fn compared(
    mine: &Framebuffer,
    name: &str,
    lesson: &std::path::Path,
) -> Option<String> {
    let (width, height, theirs) = crate::files::read_png_rgba(lesson).ok()?;
    if (width, height) != (mine.width(), mine.height()) {
        return None;
    }
    let ours = mine.to_srgb8().ok()?;
    let like = lesson.file_name()?.to_string_lossy();
    Some(Comparison::of(&ours, &theirs).verdict(name, &like))
}

#[cfg(test)]
mod tests {
    use super::*;
    use check::*;

    /// `--mine` on a function still `todo!()` (as every exercise file begins) says
    /// what to do: write the function, in its file, and test it with the command
    /// that runs that lesson's exercises. The functions here are `todo!()`s of the
    /// test's own, so that the test does not change when a student writes theirs.
    #[test]
    fn mine_on_an_unwritten_exercise_says_where_to_write_it_and_how_to_test_it() {
        let unwritten = [
            (COMPOSE, check_compose(|_, _| todo!())),
            (PIXEL_TO_PLANE, check_pixel_to_plane(|_, _, _| todo!())),
            (PINHOLE_RAY, check_pinhole_ray(|_, _, _, _, _| todo!())),
            (CLOSEST, check_closest(|_, _, _| todo!())),
            (LAMBERT, check_lambert(|_, _, _, _, _| todo!())),
        ];
        for (exercise, outcome) in unwritten {
            let Err(Failure::Exercise { report }) = passing(exercise, outcome, ())
            else {
                panic!("{}: a todo!() must not be drawn", exercise.number);
            };
            for says in [
                "NOT STARTED",
                exercise.function,
                exercise.file,
                &format!("cargo test --test exercises ch{}", exercise.chapter),
            ] {
                assert!(report.contains(says), "{report}\nsays nothing of {says:?}");
            }
            let failure = Failure::Exercise { report };
            assert!(matches!(if_passing(Err::<(), _>(failure)), Ok(None)));
        }
        // A passing exercise's function is handed on, to draw its picture.
        assert!(matches!(if_passing(Ok::<u8, Failure>(7)), Ok(Some(7))));
    }
}
