//! Label placement: every label is kept (text, kind, ink box) and set on top of the
//! shapes when the diagram is saved; a label that would cover something moves to
//! the nearest place that covers least, a tick value that would cover another label
//! is left out, and what still collides can be listed for a test.

use glam::Vec2;

use super::place::{GAP, Place, PxBox, ink_box, offset};
use super::{Diagram, Rgb, Segment, palette};

/// What a label is, which decides what gives way when two collide.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LabelKind {
    /// A figure's own label.
    Text,
    /// An axis tick's value: left out when it would cover another label.
    Tick,
    /// An axis's name.
    AxisName,
    /// The title at the top.
    Title,
}

/// A label as drawn: its text, kind and the box its ink covers.
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    /// The text.
    pub text: String,
    /// What the label is.
    pub kind: LabelKind,
    /// Where its ink lies, in pixels.
    pub bounds: PxBox,
    pub(super) at: Vec2,
    pub(super) size: f32,
    pub(super) color: Rgb,
}

/// Two things a reader cannot tell apart: found by [`Diagram::label_collisions`].
#[derive(Clone, Debug, PartialEq)]
pub enum Collision {
    /// Two labels whose ink boxes overlap.
    Labels(String, String),
    /// A label over an axis line or a tick mark.
    Axis(String),
}

impl std::fmt::Display for Collision {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Collision::Labels(a, b) => write!(f, "label {a:?} overlaps label {b:?}"),
            Collision::Axis(a) => {
                write!(f, "label {a:?} lies on an axis or a tick mark")
            }
        }
    }
}

/// Font size of labels, in pixels.
pub const LABEL_SIZE: f32 = 15.0;

/// The room a placed label keeps from everything else, in pixels.
const PAD: f32 = 2.0;

impl Diagram {
    /// A label next to the diagram point `p`, placed as `place` says; if the label
    /// would lie on an axis, a tick mark or another label there, it moves to the
    /// nearest place around `p` that covers nothing drawn so far (Right tries
    /// AboveRight and BelowRight first, Left last), or else to the nearest that at
    /// least leaves the axes and labels clear.
    pub fn text(&mut self, p: Vec2, s: &str, color: Rgb, place: Place) {
        let at = self.to_px(p);
        let readable = ink_box(at, s, LABEL_SIZE, place).is_none_or(|b| {
            let on_label =
                |l: &Label| l.kind != LabelKind::Tick && l.bounds.overlaps(&b);
            let on_axis = |g: &Segment| g.axis && b.touches(g.a, g.b, g.half_width);
            !self.labels.iter().any(on_label) && !self.segments.iter().any(on_axis)
        });
        if readable {
            self.text_px(at, s, LABEL_SIZE, color, place);
        } else {
            self.text_clear(p, s, color, &place.nearest_first());
        }
    }

    /// A label next to `p` at the first of `places` where it covers no other label,
    /// line or dot drawn so far (draw the lines first); where none is clear, at the
    /// one that covers least (labels and axes weigh most, then tick values, then each
    /// line or dot). Returns the place taken.
    pub fn text_clear(
        &mut self,
        p: Vec2,
        s: &str,
        color: Rgb,
        places: &[Place],
    ) -> Place {
        let at = self.to_px(p);
        let cost = |place: &Place| {
            ink_box(at, s, LABEL_SIZE, *place).map_or(0, |b| self.cost(&b))
        };
        let mut best = (u64::MAX, places.first().copied().unwrap_or(Place::Right));
        for place in places {
            let c = cost(place);
            if c < best.0 {
                best = (c, *place);
            }
            if c == 0 {
                break;
            }
        }
        self.text_px(at, s, LABEL_SIZE, color, best.1);
        best.1
    }

    /// How much a label with ink box `b` would cover, 2 px around it included: 0
    /// when nothing. Each pixel already inked (darker than a light fill) counts one;
    /// a tick value 100, another label or an axis 10 000.
    fn cost(&self, b: &PxBox) -> u64 {
        let b = &PxBox {
            min: b.min - PAD,
            max: b.max + PAD,
        };
        let labels: u64 = self
            .labels
            .iter()
            .filter(|l| l.bounds.overlaps(b))
            .map(|l| {
                if l.kind == LabelKind::Tick {
                    100
                } else {
                    10_000
                }
            })
            .sum();
        let axes = self
            .segments
            .iter()
            .filter(|g| g.axis && b.touches(g.a, g.b, g.half_width))
            .count() as u64;
        let (w, h) = (self.pixmap.width() as i64, self.pixmap.height() as i64);
        let (x0, y0) = (
            b.min.x.floor().max(0.0) as i64,
            b.min.y.floor().max(0.0) as i64,
        );
        let (x1, y1) = (
            b.max.x.ceil().min(w as f32) as i64,
            b.max.y.ceil().min(h as f32) as i64,
        );
        let pixels = self.pixmap.pixels();
        let mut inked = 0;
        for y in y0..y1 {
            for x in x0..x1 {
                let p = pixels[(y * w + x) as usize];
                let deficit =
                    3 * 255 - p.red() as u32 - p.green() as u32 - p.blue() as u32;
                if deficit > 90 {
                    inked += 1;
                }
            }
        }
        // Off the canvas counts as covered: a label there is cut.
        let area = ((b.max.x - b.min.x) * (b.max.y - b.min.y)).max(0.0) as i64;
        let cut = (area - (x1 - x0).max(0) * (y1 - y0).max(0)).max(0) as u64;
        labels + 10_000 * axes + inked + cut
    }

    /// A title centred at the top of the canvas.
    pub fn title(&mut self, s: &str) {
        let top = Vec2::new(self.pixmap.width() as f32 * 0.5, 8.0);
        let size = LABEL_SIZE * 1.2;
        self.label(top, s, size, palette::INK, Place::Below, LabelKind::Title);
    }

    /// Text at pixel position `at`, `size` pixels high, placed as `place` says.
    pub fn text_px(&mut self, at: Vec2, s: &str, size: f32, color: Rgb, place: Place) {
        self.label(at, s, size, color, place, LabelKind::Text);
    }

    pub(super) fn label(
        &mut self,
        at: Vec2,
        s: &str,
        size: f32,
        color: Rgb,
        place: Place,
        kind: LabelKind,
    ) {
        let Some(bounds) = ink_box(at, s, size, place) else {
            return;
        };
        let at = at + offset(s, size, place);
        self.labels.push(Label {
            text: s.to_string(),
            kind,
            bounds,
            at,
            size,
            color,
        });
    }

    /// Every label the saved diagram shows, in the order drawn: tick values that
    /// would cover another label or a dot are left out.
    pub fn labels(&self) -> Vec<&Label> {
        let mut shown: Vec<&Label> = Vec::new();
        let others: Vec<&Label> = self
            .labels
            .iter()
            .filter(|l| l.kind != LabelKind::Tick)
            .collect();
        // A marker dot (a hit, an origin: 3 px or more; not the small dots that
        // trace a surface) hides a tick value within a gap of it, as a label does.
        let on_dot = |l: &Label| {
            self.segments.iter().any(|g| {
                g.a == g.b
                    && g.half_width >= 3.0
                    && l.bounds.touches(g.a, g.b, g.half_width + GAP)
            })
        };
        for l in &self.labels {
            let hides = |o: &&Label| o.bounds.overlaps(&l.bounds);
            let covered =
                others.iter().any(hides) || shown.iter().any(hides) || on_dot(l);
            if l.kind == LabelKind::Tick && covered {
                continue;
            }
            shown.push(l);
        }
        shown
    }

    /// What still collides in the figure: pairs of shown labels whose ink boxes
    /// overlap, and labels over an axis line or a tick mark. A legible figure has none.
    pub fn label_collisions(&self) -> Vec<Collision> {
        let shown = self.labels();
        let mut found = Vec::new();
        for (i, a) in shown.iter().enumerate() {
            for b in &shown[i + 1..] {
                if a.bounds.overlaps(&b.bounds) {
                    found.push(Collision::Labels(a.text.clone(), b.text.clone()));
                }
            }
            let on_axis = self
                .segments
                .iter()
                .filter(|g| g.axis)
                .any(|g| a.bounds.touches(g.a, g.b, g.half_width));
            if on_axis {
                found.push(Collision::Axis(a.text.clone()));
            }
        }
        found
    }
}
