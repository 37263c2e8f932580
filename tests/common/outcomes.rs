//! What a check of a coding exercise answered (`tests/exercise_checks`): a failure
//! with a wrong answer and its hint, a panic, or any failure whose hint says something.

use render_lessons::course::exercises::check::{Outcome, Reason};

/// Asserts a failure with a wrong answer (not a panic, not a time-out) whose hint
/// contains `hint`.
#[track_caller]
pub fn fails_with(outcome: Outcome, hint: &str) {
    match &outcome {
        Outcome::Fail {
            hint: got, reason, ..
        } => {
            assert!(
                got.contains(hint),
                "hint {got:?} does not mention {hint:?}\n{outcome}"
            );
            assert_eq!(*reason, Reason::Wrong, "{outcome}");
        }
        other => panic!("expected a failure with hint {hint:?}, got {other}"),
    }
}

/// Asserts a failure by a panic, and returns the panic's message and place.
#[track_caller]
pub fn panicked(outcome: Outcome) -> (String, Option<String>) {
    match outcome {
        Outcome::Fail {
            hint,
            reason: Reason::Panicked { message, at },
            ..
        } => {
            assert!(hint.contains("must not panic"), "{hint}");
            (message, at)
        }
        other => panic!("expected a panic, got {other}"),
    }
}

/// Asserts a failure of any kind (a wrong answer, a panic or a time-out) whose hint
/// contains `hint`.
#[track_caller]
pub fn fails_hinting(outcome: Outcome, hint: &str) {
    match outcome.hint() {
        Some(got) => assert!(
            got.contains(hint),
            "hint {got:?} does not mention {hint:?}\n{outcome}"
        ),
        None => panic!("expected a failure with hint {hint:?}, got {outcome}"),
    }
}
