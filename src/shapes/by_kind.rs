//! The closest-hit loop's fast path (lesson 11): a list of shapes copied into runs
//! of one kind each, in the list's order, so that the loop over a run calls one test
//! with no `match` on every object.
//!
//! It finds what asking every shape of the list for [`Shape::candidate`] in turn
//! finds, bit for bit: the same tests on the same shapes in the same order, each hit
//! shrinking the range for the next (so on a tie the earlier shape still wins).
//! Lesson 08's scene, a floor, three spheres, a box and a triangle, is four runs;
//! lesson 10's Cornell box, five walls, two balls and the lamp (a quad), is three.
//! Each kind's test is its own `candidate` ([`Sphere::candidate`] and the rest), the
//! one the other loops call too. Shapes without a run of their own (quadrics,
//! cylinders, instances, meshes) make runs that ask [`Shape::candidate`], `match`
//! and all.

use super::{Aabb, Candidate, Plane, PreparedRay, Quad, Shape, Sphere, Triangle};
use crate::ray::Interval;

/// The shapes of a list in runs of one kind, each run knowing the list index of its
/// first shape.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ShapesByKind {
    runs: Vec<Run>,
}

/// Consecutive shapes of the list, all of one kind.
#[derive(Clone, Debug, PartialEq)]
struct Run {
    /// The list index of the run's first shape.
    first: usize,
    shapes: Shapes,
}

#[derive(Clone, Debug, PartialEq)]
enum Shapes {
    Spheres(Vec<Sphere>),
    Planes(Vec<Plane>),
    Boxes(Vec<Aabb>),
    Triangles(Vec<Triangle>),
    Quads(Vec<Quad>),
    Others(Vec<Shape>),
}

impl Shapes {
    /// Adds `shape` to this run if it is of the run's kind; gives it back if not.
    fn push<'a>(&mut self, shape: &'a Shape) -> Option<&'a Shape> {
        match (self, shape) {
            (Shapes::Spheres(v), Shape::Sphere(s)) => v.push(*s),
            (Shapes::Planes(v), Shape::Plane(p)) => v.push(*p),
            (Shapes::Boxes(v), Shape::Aabb(b)) => v.push(*b),
            (Shapes::Triangles(v), Shape::Triangle(t)) => v.push(*t),
            (Shapes::Quads(v), Shape::Quad(q)) => v.push(*q),
            (Shapes::Others(v), shape) if Shapes::of(shape).is_none() => {
                v.push(shape.clone())
            }
            _ => return Some(shape),
        }
        None
    }

    /// A run holding `shape` alone.
    fn start(shape: &Shape) -> Shapes {
        Shapes::of(shape).unwrap_or_else(|| Shapes::Others(vec![shape.clone()]))
    }

    /// The run of `shape`'s kind, if it has a fast test of its own.
    fn of(shape: &Shape) -> Option<Shapes> {
        Some(match shape {
            Shape::Sphere(s) => Shapes::Spheres(vec![*s]),
            Shape::Plane(p) => Shapes::Planes(vec![*p]),
            Shape::Aabb(b) => Shapes::Boxes(vec![*b]),
            Shape::Triangle(t) => Shapes::Triangles(vec![*t]),
            Shape::Quad(q) => Shapes::Quads(vec![*q]),
            _ => return None,
        })
    }
}

impl ShapesByKind {
    /// The runs of `shapes`, in their order.
    pub fn new<'a>(shapes: impl IntoIterator<Item = &'a Shape>) -> ShapesByKind {
        let mut runs: Vec<Run> = Vec::new();
        for (i, shape) in shapes.into_iter().enumerate() {
            let rest = match runs.last_mut() {
                Some(run) => run.shapes.push(shape),
                None => Some(shape),
            };
            if let Some(shape) = rest {
                runs.push(Run {
                    first: i,
                    shapes: Shapes::start(shape),
                });
            }
        }
        ShapesByKind { runs }
    }

    /// The closest candidate within `range` and the list index of its shape; on a
    /// tie, the shape listed first. The same answer as asking every shape of the
    /// list for its [`Shape::candidate`] in turn.
    #[inline]
    pub fn closest(
        &self,
        ray: &PreparedRay,
        range: Interval,
    ) -> Option<(Candidate, usize)> {
        let mut best = None;
        self.search(ray, range, |candidate, i| best = Some((candidate, i)));
        best
    }

    /// The list index of the shape [`ShapesByKind::closest`] finds, without what
    /// its hit record needs (shadowless ray casting asks no more).
    #[inline]
    pub fn closest_index(&self, ray: &PreparedRay, range: Interval) -> Option<usize> {
        let mut best = None;
        self.search(ray, range, |_, i| best = Some(i));
        best
    }

    // ANCHOR: search
    /// Every shape tested in the list's order, each hit shrinking the range: `found`
    /// sees each candidate closer than all before it, with its list index; the last
    /// one is the closest.
    #[inline(always)]
    fn search(
        &self,
        ray: &PreparedRay,
        range: Interval,
        mut found: impl FnMut(Candidate, usize),
    ) {
        let mut range = range;
        for run in &self.runs {
            let (first, found) = (run.first, &mut found);
            match &run.shapes {
                Shapes::Spheres(v) => {
                    closest_in(v, first, &mut range, found, |s, r| s.candidate(ray, r))
                }
                Shapes::Planes(v) => {
                    closest_in(v, first, &mut range, found, |p, r| p.candidate(ray, r))
                }
                Shapes::Boxes(v) => {
                    closest_in(v, first, &mut range, found, |b, r| b.candidate(ray, r))
                }
                Shapes::Triangles(v) => {
                    closest_in(v, first, &mut range, found, |t, r| t.candidate(ray, r))
                }
                Shapes::Quads(v) => {
                    closest_in(v, first, &mut range, found, |q, r| q.candidate(ray, r))
                }
                Shapes::Others(v) => {
                    closest_in(v, first, &mut range, found, |s, r| s.candidate(ray, r))
                }
            }
        }
    }

    // ANCHOR_END: search

    /// True if any shape has a crossing within `range` (a shadow ray's question).
    pub fn any(&self, ray: &PreparedRay, range: Interval) -> bool {
        self.runs.iter().any(|run| match &run.shapes {
            Shapes::Spheres(v) => v.iter().any(|s| s.candidate(ray, range).is_some()),
            Shapes::Planes(v) => v.iter().any(|p| p.candidate(ray, range).is_some()),
            Shapes::Boxes(v) => v.iter().any(|b| b.candidate(ray, range).is_some()),
            Shapes::Triangles(v) => v.iter().any(|t| t.candidate(ray, range).is_some()),
            Shapes::Quads(v) => v.iter().any(|q| q.candidate(ray, range).is_some()),
            Shapes::Others(v) => v.iter().any(|s| s.candidate(ray, range).is_some()),
        })
    }
}

// ANCHOR: closest_in
/// Each of `shapes` asked by `test` in turn: a candidate shrinks `range` and goes to
/// `found` with its list index (`first` + its index in `shapes`).
#[inline(always)]
fn closest_in<T>(
    shapes: &[T],
    first: usize,
    range: &mut Interval,
    found: &mut impl FnMut(Candidate, usize),
    test: impl Fn(&T, Interval) -> Option<Candidate>,
) {
    for (k, shape) in shapes.iter().enumerate() {
        if let Some(candidate) = test(shape, *range) {
            range.max = candidate.t;
            found(candidate, first + k);
        }
    }
}
// ANCHOR_END: closest_in
