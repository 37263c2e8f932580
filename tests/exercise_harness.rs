//! The harness of the coding exercises' checks (`src/course/exercises/harness.rs`),
//! checked: a `todo!()` is "not started", a panic and an endless loop fail their case
//! with the place or the time limit, the reports and the summary say so, and every
//! exercise is listed once, with its file. Run by the default test suite.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use glam::{Mat4, Vec3};
use render_lessons::course::exercises::check::*;

mod exercise_common;
use exercise_common::panicked;

/// A wrong answer that panics on every case, with its line in the message.
fn panics_with_its_line(o: Vec3, _: Vec3, _: f32) -> Vec3 {
    if o.is_finite() {
        panic!("oops on line {}", line!());
    }
    o
}

#[test]
fn a_todo_is_not_started_and_a_panic_fails_with_its_message_and_place() {
    assert_eq!(
        check_pixel_to_plane(|_, _, _| todo!("Coding exercise 3.1")),
        Outcome::NotStarted
    );
    assert_eq!(check_closest(|_, _, _| todo!()), Outcome::NotStarted);
    assert_eq!(check_covers(|_, _, _, _| todo!()), Outcome::NotStarted);
    let outcome = check_point_at(panics_with_its_line);
    let (message, at) = panicked(outcome.clone());
    // The hook's place is the panic's own line, in this file.
    let line = message.trim_start_matches("oops on line ");
    assert_eq!(at, Some(format!("{}:{line}", file!())), "{message}");
    let place = format!("panicked at {}:{line}: oops on line {line}", file!());
    let Outcome::Fail { got, .. } = &outcome else {
        unreachable!()
    };
    assert_eq!(*got, place);
    // The report and the summary's row say where, not a bare FAIL.
    assert!(POINT_AT.report(&outcome).contains(&place));
    let row = POINT_AT.row(&outcome);
    assert!(row.ends_with(&format!("FAIL: {place}")), "{row}");
}

/// Set once the test below has its outcome: the "endless" loop then ends, so that
/// it does not keep a core busy for the rest of the test run.
static STOP_LOOPING: AtomicBool = AtomicBool::new(false);

#[test]
fn an_endless_loop_fails_its_case_within_the_time_limit_and_the_limit_does_not_leak() {
    let before = case_time_limit();
    // 1 s instead of the default 5 s: the test waits for the whole limit.
    let limit = Duration::from_secs(1);
    let start = Instant::now();
    let (outcome, elsewhere) = with_case_time_limit(limit, || {
        // Another thread (another test) keeps its own limit meanwhile.
        let elsewhere = std::thread::spawn(case_time_limit).join().unwrap();
        let outcome = check_point_at(|o, _, _| {
            while !STOP_LOOPING.load(Ordering::Relaxed) {
                std::hint::spin_loop();
            }
            o
        });
        (outcome, elsewhere)
    });
    let waited = start.elapsed();
    STOP_LOOPING.store(true, Ordering::Relaxed);
    assert_eq!(elsewhere, before);
    assert_eq!(case_time_limit(), before, "the 1 s limit leaked");
    assert!(
        waited >= limit && waited < limit + Duration::from_secs(3),
        "{waited:?}"
    );
    match &outcome {
        Outcome::Fail {
            case,
            got,
            hint,
            reason,
            ..
        } => {
            assert!(case.contains("o = (1, 1, 0)"), "{case}");
            assert_eq!(got, "no answer within 1 s");
            assert_eq!(*reason, Reason::TimedOut { seconds: 1 });
            assert!(
                hint.contains(&format!(
                    "case 1 ({case}) did not finish within 1 s: an infinite loop?"
                )),
                "{hint}"
            );
        }
        other => panic!("expected a failure, got {other}"),
    }
    let report = POINT_AT.report(&outcome);
    assert!(
        report.contains("FAIL") && report.contains("infinite loop"),
        "{report}"
    );
    let row = POINT_AT.row(&outcome);
    assert!(row.ends_with("FAIL: no answer within 1 s"), "{row}");
}

#[test]
fn a_slow_right_answer_passes_while_another_check_runs_with_a_short_limit() {
    // The bug a student met: a 1 s limit set by the test above for the whole program
    // failed a right answer taking 1 to 5 s, in the full run only. Here the short
    // limit holds on this thread while a right answer taking 1.5 s is checked on
    // another, which keeps the default.
    with_case_time_limit(Duration::from_secs(1), || {
        let slow = std::thread::spawn(|| {
            check_point_at(|o, d: Vec3, t| {
                if o == Vec3::new(1.0, 1.0, 0.0) && t == 0.0 {
                    std::thread::sleep(Duration::from_millis(1500));
                }
                o + t * (d / d.abs().max_element()).normalize()
            })
        });
        assert_eq!(slow.join().unwrap(), Outcome::Pass);
    });
}

#[test]
fn a_students_failed_test_is_the_report_itself_without_a_backtrace() {
    // The student's tests return `expect_pass`'s error instead of panicking, so that
    // `RUST_BACKTRACE=1` adds no backtrace of the harness to the report.
    assert!(POINT_AT.expect_pass(&Outcome::Pass).is_ok());
    let outcome = check_point_at(|o, _, _| o);
    let error = POINT_AT.expect_pass(&outcome).unwrap_err();
    assert_eq!(
        format!("{error:?}"),
        format!("\n{}\n", POINT_AT.report(&outcome))
    );
}

#[test]
fn every_check_reports_not_started_for_a_todo() {
    let outcomes = [
        check_rotation_y(|_| todo!()),
        check_compose(|_, _| todo!()),
        check_point_at(|_, _, _| todo!()),
        check_t_closest(|_, _| todo!()),
        check_pixel_to_plane(|_, _, _| todo!()),
        check_plane_to_pixel(|_, _| todo!()),
        check_to_world(|_, _, _, _| todo!()),
        check_to_local(|_, _, _, _| todo!()),
        check_camera_basis(|_, _| todo!()),
        check_ortho_ray(|_, _, _, _| todo!()),
        check_pinhole_ray(|_, _, _, _, _| todo!()),
        check_project(|_, _, _, _| todo!()),
        check_ray_plane_t(|_, _, _, _| todo!()),
        check_ray_sphere_roots(|_, _, _, _| todo!()),
        check_moller_trumbore(|_, _, _, _, _| todo!()),
        check_closest(|_, _, _| todo!()),
        check_lambert(|_, _, _, _, _| todo!()),
        check_covers(|_, _, _, _| todo!()),
        check_perspective_weights(|_, _| todo!()),
        check_cosine_sample(|_| todo!()),
        check_bounce_weight(|_, _, _, _| todo!()),
        check_slab(|_, _, _, _, _| todo!()),
        check_sah_cost(|_, _, _, _, _| todo!()),
    ];
    for (exercise, outcome) in ALL.iter().zip(outcomes) {
        assert_eq!(outcome, Outcome::NotStarted, "exercise {}", exercise.number);
    }
}

#[test]
fn an_unwrap_of_none_an_index_out_of_bounds_and_a_panic_in_rayon_fail() {
    let start = Instant::now();
    // A search that finds nothing: the first NaN coordinate of p.
    let (message, at) = panicked(check_t_closest(|_, p: Vec3| {
        p.to_array().into_iter().find(|x| x.is_nan()).unwrap()
    }));
    assert!(
        message.contains("`Option::unwrap()` on a `None`"),
        "{message}"
    );
    // `unwrap` reports its caller's line: the closure's, in this file.
    assert!(at.is_some_and(|at| at.starts_with(file!())));
    let (message, at) = panicked(check_rotation_y(|theta| {
        let angles: Vec<f32> = Vec::new();
        Mat4::from_rotation_y(angles[theta as usize])
    }));
    assert!(message.contains("index out of bounds"), "{message}");
    assert!(at.is_some_and(|at| at.starts_with(file!())));
    // A panic inside a parallel iterator reaches the check through rayon, without
    // its place (rayon's thread printed it).
    let (message, at) = panicked(check_rotation_y(|theta| {
        use rayon::prelude::*;
        let sum: f32 = (0..4)
            .into_par_iter()
            .map(|i| {
                if i == 3 {
                    panic!("in a rayon closure")
                } else {
                    theta
                }
            })
            .sum();
        Mat4::from_rotation_y(sum)
    }));
    assert!(message.contains("in a rayon closure"), "{message}");
    assert_eq!(at, None);
    assert!(start.elapsed() < CASE_TIME_LIMIT, "{:?}", start.elapsed());
}

#[test]
fn every_lesson_has_two_exercises_or_more_numbered_in_book_order() {
    for chapter in 1..=11 {
        let chapter = format!("{chapter:02}");
        let numbers: Vec<&str> = ALL
            .iter()
            .filter(|e| e.chapter == chapter)
            .map(|e| e.number)
            .collect();
        assert!(numbers.len() >= 2, "chapter {chapter}: {numbers:?}");
        let first = chapter.trim_start_matches('0');
        let expected: Vec<String> = (1..=numbers.len())
            .map(|i| format!("{first}.{i}"))
            .collect();
        assert_eq!(numbers, expected, "chapter {chapter}");
    }
    assert!(ALL.len() >= 22);
}

#[test]
fn every_exercise_is_listed_once_with_its_file() {
    for (i, e) in ALL.iter().enumerate() {
        assert!(
            ALL[..i].iter().all(|o| o.number != e.number),
            "{} twice",
            e.number
        );
        assert_eq!(e.file, format!("src/course/exercises/ch{}.rs", e.chapter));
        let stub = std::fs::read_to_string(e.file).unwrap();
        // Only what stays true once the student has written the body: the
        // function's name and the exercise's number in the file.
        let number = format!("Coding exercise {}", e.number);
        assert!(stub.contains(&number), "{number} not in {}", e.file);
        assert!(
            stub.contains(&format!("pub fn {}(", e.function)),
            "{} not in {}",
            e.function,
            e.file
        );
    }
}
