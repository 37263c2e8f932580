//! Axes and ticks: two axes through the origin with arrowheads and names, tick marks
//! with their values, and a tick step that stays readable whatever the range.

use glam::Vec2;

use super::labels::{LABEL_SIZE, LabelKind};
use super::place::Place;
use super::{Diagram, palette};

impl Diagram {
    /// Horizontal and vertical axes through the origin with ticks every `step`
    /// units, labelled with their values and with the axis names at the ends.
    ///
    /// A tick value that would cover another label is left out when the diagram is
    /// saved (the tick mark stays).
    pub fn axes(
        &mut self,
        x: (f32, f32),
        y: (f32, f32),
        step: f32,
        names: (&str, &str),
    ) {
        self.drawing_axes = true;
        self.arrow(Vec2::new(x.0, 0.0), Vec2::new(x.1, 0.0), palette::INK, 1.5);
        self.arrow(Vec2::new(0.0, y.0), Vec2::new(0.0, y.1), palette::INK, 1.5);
        let (size, kind) = (LABEL_SIZE, LabelKind::AxisName);
        let at = [Vec2::new(x.1, 0.0), Vec2::new(0.0, y.1)].map(|p| self.to_px(p));
        self.label(at[0], names.0, size, palette::INK, Place::Right, kind);
        self.label(at[1], names.1, size, palette::INK, Place::Right, kind);
        let tick = 4.0 / self.scale;
        let ticks = |lo: f32, hi: f32| {
            let step = tick_step(step, lo, hi);
            let first = (lo / step).ceil() as i64;
            let last = (hi / step).floor() as i64;
            (first..=last)
                .filter(|i| *i != 0)
                .map(move |i| i as f32 * step)
                .take(MAX_TICKS)
        };
        for t in ticks(x.0, x.1 - step * 0.5) {
            self.line(Vec2::new(t, -tick), Vec2::new(t, tick), palette::INK, 1.0);
            self.small_text(Vec2::new(t, -tick), &format_tick(t), Place::Below);
        }
        for t in ticks(y.0, y.1 - step * 0.5) {
            self.line(Vec2::new(-tick, t), Vec2::new(tick, t), palette::INK, 1.0);
            self.small_text(Vec2::new(-tick, t), &format_tick(t), Place::Left);
        }
        self.drawing_axes = false;
    }

    /// A tick's value next to `p`, a little smaller than a label (its digits about
    /// 10 px high); left out when the diagram is saved if it would cover another
    /// label or a dot.
    fn small_text(&mut self, p: Vec2, s: &str, place: Place) {
        let px = self.to_px(p);
        let size = LABEL_SIZE * 0.93;
        self.label(px, s, size, palette::INK, place, LabelKind::Tick);
    }
}

/// The most ticks an axis gets before [`tick_step`] widens the step.
const MAX_TICKS: usize = 20;

/// The tick step for an axis over [lo, hi]: `wanted` while that gives between one
/// and [`MAX_TICKS`] ticks, else a "nice" step (1, 2 or 5 times a power of ten) that
/// gives about ten, whatever the range (a range of 1e7 units or of 1e-30).
fn tick_step(wanted: f32, lo: f32, hi: f32) -> f32 {
    let span = hi - lo;
    if !span.is_finite() || span <= 0.0 {
        return f32::INFINITY;
    }
    if wanted > 0.0 && (1.0..=MAX_TICKS as f32).contains(&(span / wanted)) {
        return wanted;
    }
    let rough = span / 10.0;
    let power = 10f32.powf(rough.log10().floor());
    let nice = [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * power)
        .find(|s| *s >= rough)
        .unwrap_or(10.0 * power);
    if nice > 0.0 && nice.is_finite() {
        nice
    } else {
        f32::INFINITY
    }
}

fn format_tick(t: f32) -> String {
    crate::course::report::num(t as f64, if t.fract() == 0.0 { 0 } else { 1 })
}

#[cfg(test)]
mod tests {
    use super::tick_step;

    #[test]
    fn the_asked_step_stays_while_it_gives_few_ticks() {
        assert_eq!(tick_step(1.0, -8.0, 8.0), 1.0);
        assert_eq!(tick_step(0.5, -2.0, 2.0), 0.5);
    }

    #[test]
    fn huge_and_tiny_ranges_get_about_ten_nice_ticks() {
        for (wanted, lo, hi) in [
            (1.0, -1e7, 1e7),
            (1.0, 0.0, 3e38),
            (1.0, 1e-30, 2e-30),
            (0.0, 1e-30, 2e-30),
            (1.0, -5.0, 1e5),
        ] {
            let step = tick_step(wanted, lo, hi);
            let count = (hi - lo) / step;
            assert!((4.0..=20.0).contains(&count), "{lo}..{hi}: step {step}");
            let mantissa = step / 10f32.powf(step.log10().floor());
            assert!(
                [1.0, 2.0, 5.0, 10.0]
                    .iter()
                    .any(|m| (mantissa - m).abs() < 1e-3),
                "{step} is not 1, 2 or 5 times a power of ten"
            );
        }
    }

    #[test]
    fn an_empty_or_broken_range_gets_no_ticks() {
        for (lo, hi) in [
            (1.0, 1.0),
            (2.0, 1.0),
            (0.0, f32::INFINITY),
            (f32::NAN, 1.0),
        ] {
            assert_eq!(tick_step(1.0, lo, hi), f32::INFINITY, "{lo}..{hi}");
        }
    }
}
