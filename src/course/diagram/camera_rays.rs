//! Camera drawings: a camera and its rays seen from the side or from above, the
//! projection plane edge-on ([`CameraRays`]), every ray asked of the camera itself.

use glam::{Vec2, Vec3};

use super::place::Place;
use super::{Diagram, palette};
use crate::camera::{Camera, Film};
use crate::ray::Ray;

/// Which world plane a diagram shows, and how a world point lands on the page.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    /// Seen from the side (from +x): z to the right, y up.
    Side,
    /// Seen from above (from +y): x to the right, -z up.
    Top,
}

impl View {
    /// Where the world point `p` lands on the page.
    pub fn project(self, p: Vec3) -> Vec2 {
        match self {
            View::Side => Vec2::new(p.z, p.y),
            View::Top => Vec2::new(p.x, -p.z),
        }
    }

    /// The names of the page's horizontal and vertical axes, for [`Diagram::axes`].
    pub fn axis_names(self) -> (&'static str, &'static str) {
        match self {
            View::Side => ("z", "y"),
            View::Top => ("x", "-z"),
        }
    }
}

/// The most rays a [`CameraRays`] figure draws: beyond that a figure is a smear.
const MAX_RAYS: u32 = 32;

/// `0..n`, or [`MAX_RAYS`] indices spread evenly over it, first and last included.
fn spread(n: u32) -> impl Iterator<Item = u32> {
    let shown = n.min(MAX_RAYS);
    (0..shown).map(move |i| {
        if shown == n {
            i
        } else {
            (u64::from(i) * u64::from(n - 1) / u64::from(shown - 1)) as u32
        }
    })
}

/// The standard picture of a camera and its rays, drawn by [`CameraRays::draw`]:
/// the projection plane edge-on, one arrow per chosen pixel from the ray's origin to
/// `reach` units in front of the camera, a dot where each ray crosses the plane (the
/// pixel centre, or the pinhole's screen point), and optionally labels, the camera's
/// basis and its eye. Everything comes from the camera's own `ray`, so the picture
/// cannot disagree with the renderer.
#[derive(Clone, Debug)]
pub struct CameraRays {
    camera: Camera,
    view: View,
    reach: f32,
    pixels: Vec<(u32, u32)>,
    plane: String,
    labels: Option<fn(u32, u32) -> String>,
    eye: Option<(String, Place)>,
    basis: Option<f32>,
    ray_width: f32,
    dot: f32,
}

impl CameraRays {
    /// The camera seen from the side; the rays of the middle column.
    pub fn side(camera: impl Into<Camera>, reach: f32) -> CameraRays {
        CameraRays::new(camera.into(), View::Side, reach)
    }

    /// The camera seen from above; the rays of the middle row.
    pub fn top(camera: impl Into<Camera>, reach: f32) -> CameraRays {
        CameraRays::new(camera.into(), View::Top, reach)
    }

    fn new(camera: Camera, view: View, reach: f32) -> CameraRays {
        let film = camera.film();
        let (w, h) = (film.width(), film.height());
        let pixels = match view {
            View::Side => spread(h).map(|y| (w / 2, y)).collect(),
            View::Top => spread(w).map(|x| (x, h / 2)).collect(),
        };
        CameraRays {
            camera,
            view,
            reach,
            pixels,
            plane: "projection plane".into(),
            labels: None,
            eye: None,
            basis: None,
            ray_width: 2.0,
            dot: 4.0,
        }
    }

    /// Draws the rays of every pixel of image column `x` instead.
    pub fn column(mut self, x: u32) -> CameraRays {
        self.pixels = spread(self.camera.film().height())
            .map(|y| (x, y))
            .collect();
        self
    }

    /// Draws the rays of every pixel of image row `y` instead.
    pub fn row(mut self, y: u32) -> CameraRays {
        self.pixels = spread(self.camera.film().width()).map(|x| (x, y)).collect();
        self
    }

    /// The projection plane's label, under its lower or left end.
    pub fn plane(mut self, label: impl Into<String>) -> CameraRays {
        self.plane = label.into();
        self
    }

    /// Labels each ray's dot on the plane with `label(x, y)` of its pixel.
    pub fn labels(mut self, label: fn(u32, u32) -> String) -> CameraRays {
        self.labels = Some(label);
        self
    }

    /// Marks the camera's position (the eye) with a dot and `name`, placed as `place`.
    pub fn eye(mut self, name: impl Into<String>, place: Place) -> CameraRays {
        self.eye = Some((name.into(), place));
        self
    }

    /// Draws the two camera basis vectors that lie in the page (u and w from above,
    /// v and w from the side) as arrows `length` units long from the camera position.
    pub fn basis(mut self, length: f32) -> CameraRays {
        self.basis = Some(length);
        self
    }

    /// Ray width and dot radius in pixels (2 and 4 unless set).
    pub fn sizes(mut self, ray_width: f32, dot: f32) -> CameraRays {
        (self.ray_width, self.dot) = (ray_width, dot);
        self
    }

    /// Each chosen pixel's ray, with the point where it crosses the projection plane
    /// and the parameter t where its arrow ends, in world space.
    pub fn rays(&self) -> Vec<(Ray, Vec3, f32)> {
        let w = self.camera.frame().basis().w();
        let pixel = |&(x, y): &(u32, u32)| {
            let ray = self.camera.ray(x, y);
            match self.camera.pinhole() {
                None => (ray, ray.origin(), self.reach),
                Some(c) => {
                    let s = c.screen_point(Film::pixel_centre(x, y));
                    let s = c.frame().point_to_world(s);
                    (ray, s, self.reach / ray.direction().dot(-w))
                }
            }
        };
        self.pixels.iter().map(pixel).collect()
    }

    /// Every point the rays are drawn between, and the camera position, on the page:
    /// what a figure's extent must hold.
    pub fn points(&self) -> Vec<Vec2> {
        let mut points = vec![self.view.project(self.camera.frame().position())];
        for (ray, _, t) in self.rays() {
            points.extend([ray.origin(), ray.at(t)].map(|p| self.view.project(p)));
        }
        points
    }

    /// Draws the picture on `d`: plane, rays, dots and labels, basis, eye.
    pub fn draw(&self, d: &mut Diagram) {
        let page = |p: Vec3| self.view.project(p);
        let frame = self.camera.frame();
        let film = self.camera.film();
        let depth = match self.camera.pinhole() {
            None => 0.0,
            Some(c) => -c.screen_distance(),
        };
        // The plane edge-on: its midline along v from the side, along u from above.
        let (edge, on_plane) = match self.view {
            View::Side => (film.y_extent(), Vec3::new(0.0, 1.0, 0.0)),
            View::Top => (film.x_extent(), Vec3::new(1.0, 0.0, 0.0)),
        };
        let edge = [edge.0, edge.1].map(|a| {
            let local = on_plane * a + Vec3::new(0.0, 0.0, depth);
            page(frame.point_to_world(local))
        });
        d.line(edge[0], edge[1], palette::PLANE, 4.0);
        let rays = self.rays();
        for (ray, on_plane, t) in &rays {
            d.arrow(
                page(ray.origin()),
                page(ray.at(*t)),
                palette::RAY,
                self.ray_width,
            );
            d.dot(page(*on_plane), self.dot, palette::HIT);
        }
        let p = page(frame.position());
        let mut tips = Vec::new();
        if let Some(length) = self.basis {
            let b = frame.basis();
            let first = match self.view {
                View::Side => (b.v(), "v", palette::Y_AXIS),
                View::Top => (b.u(), "u", palette::X_AXIS),
            };
            for (v, name, color) in [first, (b.w(), "w", palette::Z_AXIS)] {
                let tip = p + page(v) * length;
                d.arrow(p, tip, color, 3.5);
                tips.push((tip, name, color));
            }
        }
        if self.eye.is_some() {
            d.dot(p, 6.0, palette::CAMERA);
        }
        // The labels last, each where the lines and dots leave it room.
        let beside = [
            Place::Right,
            Place::AboveRight,
            Place::BelowRight,
            Place::Left,
            Place::AboveLeft,
            Place::BelowLeft,
        ];
        if let Some(label) = self.labels {
            for ((x, y), (_, on_plane, _)) in self.pixels.iter().zip(&rays) {
                d.text_clear(page(*on_plane), &label(*x, *y), palette::INK, &beside);
            }
        }
        for (tip, name, color) in tips {
            d.text_clear(tip, name, color, &beside);
        }
        if let Some((name, place)) = &self.eye {
            d.text_clear(p, name, palette::CAMERA, &place.nearest_first());
        }
        let under = [
            Place::Below,
            Place::BelowLeft,
            Place::BelowRight,
            Place::Left,
            Place::Right,
        ];
        d.text_clear(edge[0], &self.plane, palette::PLANE, &under);
    }
}

/// The smallest ranges (x, y) that hold every point, widened by `margin` on all sides.
pub fn extent(points: &[Vec2], margin: f32) -> ((f32, f32), (f32, f32)) {
    let lo = points
        .iter()
        .copied()
        .fold(Vec2::splat(f32::MAX), Vec2::min)
        - margin;
    let hi = points
        .iter()
        .copied()
        .fold(Vec2::splat(f32::MIN), Vec2::max)
        + margin;
    ((lo.x, hi.x), (lo.y, hi.y))
}
