//! The harness of the coding exercises' checks (`src/course/exercises/harness.rs`),
//! checked: a `todo!()` is "not started", a panic and an endless loop fail their case
//! with the place or the time limit, the reports and the summary say so, and every
//! exercise is listed once, with its file. Run by the default test suite.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use glam::{Mat4, Vec3};
use render_lessons::course::exercises::check::*;

use crate::common::panicked;

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
        check_pixel_to_plane(|_, _, _| todo!("Coding exercise 3.5")),
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

/// One exercise as the book labels it: its page, its number ("7.16", "W.2"), and the
/// text from its label to the next label or heading.
struct BookExercise {
    page: String,
    number: String,
    text: String,
}

/// Every exercise of the book's pages, in the order `SUMMARY.md` lists them: the
/// labels `**Exercise N.k.**`, `**Exercises N.a and N.b.**` and `## Exercise N.k: ...`.
fn book_exercises() -> Vec<BookExercise> {
    let summary = std::fs::read_to_string("chapters/SUMMARY.md").unwrap();
    let pages = summary
        .split("](")
        .skip(1)
        .filter_map(|rest| rest.split(')').next());
    let mut found = Vec::new();
    for page in pages {
        let text = std::fs::read_to_string(format!("chapters/{page}")).unwrap();
        let mut open: Vec<usize> = Vec::new();
        for line in text.lines() {
            let label = line
                .strip_prefix("**Exercises ")
                .or_else(|| line.strip_prefix("**Exercise "))
                .and_then(|rest| rest.split_once(".**"))
                .map(|(numbers, _)| numbers)
                .or_else(|| {
                    let rest = line.strip_prefix("## Exercise ")?;
                    Some(rest.split_once(':')?.0)
                });
            if let Some(numbers) = label {
                open.clear();
                for number in numbers.split(" and ") {
                    open.push(found.len());
                    found.push(BookExercise {
                        page: page.to_string(),
                        number: number.to_string(),
                        text: String::new(),
                    });
                }
            } else if line.starts_with('#') {
                open.clear();
            }
            for &i in &open {
                let exercise: &mut BookExercise = &mut found[i];
                exercise.text.push_str(line);
                exercise.text.push('\n');
            }
        }
    }
    found
}

#[test]
fn every_exercise_is_numbered_n_k_in_book_order_across_its_lessons_pages() {
    // One scheme for the whole book: lesson N's exercises, written and coding alike,
    // are N.1, N.2, ... in the order of its pages, and the pages of "Where methods
    // fail" number theirs W.1, W.2, ...
    let exercises = book_exercises();
    let mut next: std::collections::BTreeMap<String, u32> = Default::default();
    for e in &exercises {
        let lesson = match e.page.split_once('_') {
            Some((n, _)) if n.len() == 2 && n.chars().all(|c| c.is_ascii_digit()) => {
                n.trim_start_matches('0').to_string()
            }
            _ if e.page.starts_with("where_methods_fail") => "W".to_string(),
            _ => panic!("{}: an exercise outside the lessons: {}", e.page, e.number),
        };
        let k = next.entry(lesson.clone()).or_insert(0);
        *k += 1;
        assert_eq!(e.number, format!("{lesson}.{k}"), "{}", e.page);
    }
    assert!(next.len() >= 12, "{next:?}");
}

#[test]
fn every_coding_exercise_has_the_books_number_in_its_check_stub_and_test() {
    let exercises = book_exercises();
    let students = std::fs::read_to_string("tests/exercises.rs").unwrap();
    for e in ALL {
        // The book: one exercise with the check's number, on the lesson's pages, and
        // its text asks for the function.
        let mut holding = exercises.iter().filter(|b| b.number == e.number);
        let book = holding
            .next()
            .unwrap_or_else(|| panic!("{} not in the book", e.number));
        assert!(holding.next().is_none(), "{} twice in the book", e.number);
        assert!(
            book.page.starts_with(e.chapter),
            "{} on {}",
            e.number,
            book.page
        );
        assert!(
            book.text.contains(&format!("`{}(", e.function)),
            "exercise {} of {} does not ask for `{}`:\n{}",
            e.number,
            book.page,
            e.function,
            book.text
        );
        // The stub's doc comment and the student's test, named after the number.
        let stub = std::fs::read_to_string(e.file).unwrap();
        let number = format!("Coding exercise {}:", e.number);
        assert!(stub.contains(&number), "{number} not in {}", e.file);
        let test = format!("exercise_{}_{}:", e.number.replace('.', "_"), e.function);
        let module = format!("ch{} {{", e.chapter);
        let in_module = students
            .split_once(&module)
            .is_some_and(|(_, rest)| rest.split('}').next().unwrap().contains(&test));
        assert!(in_module, "no test {test} in module ch{}", e.chapter);
    }
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
