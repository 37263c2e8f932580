//! The cross-section of one ray and one shape (lesson 07's figures): the surface
//! traced by the same intersection code, the ray, every crossing and the normal at
//! the nearest hit.

use glam::{Vec2, Vec3};

use super::{Diagram, Place, palette};
use crate::course::report::num;
use crate::error::Result;
use crate::ray::{Interval, Ray};
use crate::shapes::Shape;

/// The cross-section through `ray` of `shape` (called `name` in the title): the
/// surface, the ray, every crossing, and the normal at the nearest hit.
pub fn cross_section(name: &str, shape: &Shape, ray: &Ray) -> Result<Diagram> {
    // The figure's plane: spanned by x and y, or by x and z for a ray in y = 0.
    let in_xy = ray.origin().z == 0.0 && ray.direction().z == 0.0;
    let up = if in_xy { Vec3::Y } else { Vec3::Z };
    let view = |p: Vec3| Vec2::new(p.x, p.dot(up));
    let (lo, hi) = (Vec2::new(-3.2, -2.0), Vec2::new(3.2, 3.2));
    let mut d = Diagram::new(600, 460, (lo.x, hi.x), (lo.y, 3.3))?;
    d.title(&format!(
        "Ray and {}: crossings, and the normal at the nearest hit",
        name
    ));
    let names = ("x", if in_xy { "y" } else { "z" });
    d.axes((lo.x, hi.x), (lo.y, hi.y), 1.0, names);
    // The surface's trace in the plane, found by the same `Shape::crossings`: a dot
    // wherever a grid of rays along x and along the plane's second axis crosses it.
    for i in -400..=400 {
        let s = i as f32 / 100.0;
        for (o, dir) in [(up * s, Vec3::X), (Vec3::X * s, up)] {
            let probe = Ray::new(o, dir)?;
            for &t in shape.crossings(&probe).iter() {
                let q = view(probe.at(t));
                if q.clamp(lo, hi) == q {
                    d.dot(q, 1.5, palette::PLANE);
                }
            }
        }
    }
    let ts = shape.crossings(ray);
    let far = ts.iter().copied().fold(1.0f32, f32::max) + 1.5;
    d.arrow(view(ray.origin()), view(ray.at(far)), palette::RAY, 2.0);
    d.dot(view(ray.origin()), 4.0, palette::RAY);
    d.text(view(ray.origin()), "o", palette::RAY, Place::Left);
    for t in ts.iter() {
        d.dot(view(ray.at(*t)), 5.0, palette::HIT);
    }
    let normal = shape.hit(ray, Interval::AHEAD).map(|hit| {
        let (p, tip) = (view(hit.point), view(hit.point) + view(hit.normal) * 0.8);
        d.arrow(p, tip, palette::NORMAL, 2.5);
        tip
    });
    // The labels once everything is drawn, each where it covers nothing.
    for (i, t) in ts.iter().enumerate() {
        let place = if i == 0 { Place::Below } else { Place::Right };
        let label = format!("t = {}", num(*t as f64, 3));
        d.text_clear(
            view(ray.at(*t)),
            &label,
            palette::HIT,
            &place.nearest_first(),
        );
    }
    if let Some(tip) = normal {
        d.text_clear(tip, "n", palette::NORMAL, &Place::Right.nearest_first());
    }
    Ok(d)
}
