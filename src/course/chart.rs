//! Charts for lesson 11: line charts drawn as SVG with plotters, each with its data
//! as CSV beside it, so a student can plot the numbers again with any tool.
//!
//! A chart is a title, two labelled axes (linear or logarithmic) and named series of
//! (x, y) points. On a logarithmic axis a point whose value is 0 or negative has no
//! place: it is left out of the drawing (and kept in the CSV).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::error::{Error, Problem, Result};
use crate::files::write_atomically;

/// How an axis maps values to positions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scale {
    /// Equal steps for equal differences.
    Linear,
    /// Equal steps for equal ratios (decades).
    Log,
}

/// One axis: its label (with the unit) and its scale.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    /// What is measured, and in what unit, e.g. "time per test (ns)".
    pub label: String,
    /// Linear or logarithmic.
    pub scale: Scale,
}

/// One line of a chart.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// The legend's name for it.
    pub name: String,
    /// The points, in drawing order.
    pub points: Vec<(f64, f64)>,
}

/// A line chart.
#[derive(Clone, Debug, PartialEq)]
pub struct Chart {
    /// The caption.
    pub title: String,
    /// The horizontal axis.
    pub x: Axis,
    /// The vertical axis.
    pub y: Axis,
    /// The lines.
    pub series: Vec<Series>,
}

/// The size of a chart's SVG, in pixels: the width of the book's content column
/// (about 750 px) or a little more, so the page shows it at (nearly) full size.
pub const WIDTH: u32 = 800;
/// The height of a chart's SVG, in pixels.
pub const HEIGHT: u32 = 500;

/// The font size of tick labels, axis names and the legend, in plotters' points:
/// plotters writes `font-size` = points / 1.24 into the SVG, 12.9 px for 16, which
/// the page shows at about 12 px (the browser test requires 9 px or more).
pub const LABEL_SIZE: f64 = 16.0;
/// The font size of the title, in plotters' points (19.4 px in the SVG).
pub const TITLE_SIZE: f64 = 24.0;

/// The lines' colours, in order.
const COLOURS: [RGBColor; 8] = [
    RGBColor(30, 100, 200),
    RGBColor(210, 50, 40),
    RGBColor(30, 150, 70),
    RGBColor(230, 140, 20),
    RGBColor(120, 60, 170),
    RGBColor(90, 90, 90),
    RGBColor(0, 160, 170),
    RGBColor(200, 60, 150),
];

impl Chart {
    /// An empty chart.
    pub fn new(title: &str, x: (&str, Scale), y: (&str, Scale)) -> Chart {
        let axis = |(label, scale): (&str, Scale)| Axis {
            label: label.to_string(),
            scale,
        };
        Chart {
            title: title.to_string(),
            x: axis(x),
            y: axis(y),
            series: Vec::new(),
        }
    }

    /// The chart with one more line.
    pub fn with(mut self, name: &str, points: Vec<(f64, f64)>) -> Chart {
        self.series.push(Series {
            name: name.to_string(),
            points,
        });
        self
    }

    /// The series called `name`.
    pub fn get(&self, name: &str) -> Option<&Series> {
        self.series.iter().find(|s| s.name == name)
    }

    /// The data as CSV: a header `series,x,y` (with the axis labels in a comment
    /// line above it), then one row per point.
    pub fn csv(&self) -> String {
        let mut out =
            format!("# x: {}; y: {}\nseries,x,y\n", self.x.label, self.y.label);
        for s in &self.series {
            for (x, y) in &s.points {
                let _ = writeln!(out, "\"{}\",{x:e},{y:e}", s.name.replace('"', "'"));
            }
        }
        out
    }

    /// The points that can be drawn: finite, and positive on a log axis.
    fn drawable(&self, s: &Series) -> Vec<(f64, f64)> {
        let fits = |v: f64, scale| v.is_finite() && (scale == Scale::Linear || v > 0.0);
        s.points
            .iter()
            .copied()
            .filter(|&(x, y)| fits(x, self.x.scale) && fits(y, self.y.scale))
            .collect()
    }

    /// The range an axis must show: the data's, widened a little (to whole decades
    /// on a log axis).
    fn range(
        &self,
        values: impl Iterator<Item = f64>,
        scale: Scale,
    ) -> Result<(f64, f64)> {
        let (lo, hi) = values
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            });
        if !(lo.is_finite() && hi.is_finite()) {
            return Err(Error::Value {
                param: "chart points that can be drawn",
                problem: Problem::TooFew { value: 0, min: 1 },
            });
        }
        Ok(match scale {
            Scale::Log => (
                10f64.powf(lo.log10().floor()),
                10f64.powf(hi.log10().ceil().max(lo.log10().floor() + 1.0)),
            ),
            Scale::Linear => {
                let pad = if hi > lo {
                    0.05 * (hi - lo)
                } else {
                    0.5 * lo.abs().max(1.0)
                };
                (lo - pad, hi + pad)
            }
        })
    }

    /// The chart as an SVG document, [`WIDTH`] x [`HEIGHT`].
    pub fn svg(&self) -> Result<String> {
        let drawn: Vec<_> = self.series.iter().map(|s| self.drawable(s)).collect();
        let xs = self.range(drawn.iter().flatten().map(|p| p.0), self.x.scale)?;
        let ys = self.range(drawn.iter().flatten().map(|p| p.1), self.y.scale)?;
        let mut svg = String::new();
        let result = match (self.x.scale, self.y.scale) {
            (Scale::Linear, Scale::Linear) => {
                self.draw(&mut svg, xs.0..xs.1, ys.0..ys.1, &drawn)
            }
            (Scale::Log, Scale::Linear) => {
                self.draw(&mut svg, (xs.0..xs.1).log_scale(), ys.0..ys.1, &drawn)
            }
            (Scale::Linear, Scale::Log) => {
                self.draw(&mut svg, xs.0..xs.1, (ys.0..ys.1).log_scale(), &drawn)
            }
            (Scale::Log, Scale::Log) => self.draw(
                &mut svg,
                (xs.0..xs.1).log_scale(),
                (ys.0..ys.1).log_scale(),
                &drawn,
            ),
        };
        result.map_err(|e| Error::File {
            path: format!("chart \"{}\"", self.title),
            line: None,
            message: e.to_string(),
        })?;
        Ok(svg)
    }

    fn draw<X, Y>(
        &self,
        svg: &mut String,
        x: X,
        y: Y,
        drawn: &[Vec<(f64, f64)>],
    ) -> std::result::Result<(), Box<dyn std::error::Error>>
    where
        X: plotters::coord::ranged1d::AsRangedCoord<Value = f64>,
        Y: plotters::coord::ranged1d::AsRangedCoord<Value = f64>,
        X::CoordDescType: plotters::coord::ranged1d::ValueFormatter<f64>,
        Y::CoordDescType: plotters::coord::ranged1d::ValueFormatter<f64>,
    {
        let root = SVGBackend::with_string(svg, (WIDTH, HEIGHT)).into_drawing_area();
        root.fill(&WHITE)?;
        let mut chart = titled(&root, &self.title, 85).build_cartesian_2d(x, y)?;
        chart
            .configure_mesh()
            .x_desc(self.x.label.as_str())
            .y_desc(self.y.label.as_str())
            .label_style(("sans-serif", LABEL_SIZE))
            .axis_desc_style(("sans-serif", LABEL_SIZE))
            .x_label_formatter(&|v| tick(*v))
            .y_label_formatter(&|v| tick(*v))
            .draw()?;
        for (i, (series, points)) in self.series.iter().zip(drawn).enumerate() {
            let colour = COLOURS[i % COLOURS.len()];
            chart
                .draw_series(LineSeries::new(
                    points.iter().copied(),
                    colour.stroke_width(2),
                ))?
                .label(series.name.as_str())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], colour)
                });
            if let [point] = points[..] {
                // A series of one point (a method's cost and its error) is a large
                // dot named where it is, not a line the eye has to look for.
                let right_half = chart.backend_coord(&point).0 > WIDTH as i32 / 2;
                let (dx, h) = if right_half {
                    (-10, HPos::Right)
                } else {
                    (10, HPos::Left)
                };
                let style = ("sans-serif", LABEL_SIZE)
                    .into_text_style(&root)
                    .color(&colour)
                    .pos(Pos::new(h, VPos::Bottom));
                let name = series.name.clone();
                chart.draw_series(std::iter::once(
                    EmptyElement::at(point)
                        + Circle::new((0, 0), 6, colour.filled())
                        + Text::new(name, (dx, -6), style),
                ))?;
            } else {
                chart.draw_series(
                    points.iter().map(|&p| Circle::new(p, 3, colour.filled())),
                )?;
            }
        }
        if drawn.iter().all(|points| points.len() == 1) {
            // Every series is named beside its dot: no legend.
            root.present()?;
            return Ok(());
        }
        chart
            .configure_series_labels()
            .label_font(("sans-serif", LABEL_SIZE))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .position(self.legend_corner(drawn))
            .draw()?;
        root.present()?;
        Ok(())
    }

    /// The corner of the plot with the fewest data points near it, for the legend:
    /// points are placed on the axes' own scales (logarithms on a log axis) and
    /// counted in each corner's box, 45% of the width by 40% of the height.
    fn legend_corner(&self, drawn: &[Vec<(f64, f64)>]) -> SeriesLabelPosition {
        let on_scale = |v: f64, scale| if scale == Scale::Log { v.log10() } else { v };
        let points: Vec<(f64, f64)> = drawn
            .iter()
            .flatten()
            .map(|&(x, y)| (on_scale(x, self.x.scale), on_scale(y, self.y.scale)))
            .collect();
        let span = |values: Vec<f64>| {
            let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            (lo, (hi - lo).max(f64::MIN_POSITIVE))
        };
        let (x0, dx) = span(points.iter().map(|p| p.0).collect());
        let (y0, dy) = span(points.iter().map(|p| p.1).collect());
        let crowd = |right: bool, top: bool| {
            points
                .iter()
                .filter(|(x, y)| {
                    let (u, v) = ((x - x0) / dx, (y - y0) / dy);
                    (if right { u > 0.55 } else { u < 0.45 })
                        && (if top { v > 0.6 } else { v < 0.4 })
                })
                .count()
        };
        let corners = [
            (crowd(true, true), SeriesLabelPosition::UpperRight),
            (crowd(false, true), SeriesLabelPosition::UpperLeft),
            (crowd(true, false), SeriesLabelPosition::LowerRight),
            (crowd(false, false), SeriesLabelPosition::LowerLeft),
        ];
        let fewest = corners.iter().map(|c| c.0).min().unwrap_or(0);
        corners
            .into_iter()
            .find(|c| c.0 == fewest)
            .map_or(SeriesLabelPosition::UpperRight, |c| c.1)
    }

    /// Writes `stem.svg` and `stem.csv` into `dir`, each atomically.
    pub fn save(&self, dir: &Path, stem: &str) -> Result<[PathBuf; 2]> {
        save_svg_and_csv(dir, stem, &self.svg()?, &self.csv())
    }
}

/// Writes `svg` to `stem.svg` and `csv` to `stem.csv` in `dir`, each atomically,
/// and returns their paths.
pub(crate) fn save_svg_and_csv(
    dir: &Path,
    stem: &str,
    svg: &str,
    csv: &str,
) -> Result<[PathBuf; 2]> {
    let paths = [
        dir.join(format!("{stem}.svg")),
        dir.join(format!("{stem}.csv")),
    ];
    write_atomically(&paths[0], svg.as_bytes())?;
    write_atomically(&paths[1], csv.as_bytes())?;
    Ok(paths)
}

/// Every course chart's frame on `root`: its title on top, 15 pixels of margin,
/// room for the x axis's ticks and label below and `y_labels` pixels for the y
/// axis's on the left.
pub(crate) fn titled<'a, 'b>(
    root: &'a DrawingArea<SVGBackend<'b>, plotters::coord::Shift>,
    title: &str,
    y_labels: u32,
) -> ChartBuilder<'a, 'b, SVGBackend<'b>> {
    let mut builder = ChartBuilder::on(root);
    builder
        .caption(title, ("sans-serif", TITLE_SIZE))
        .margin(15)
        .x_label_area_size(50)
        .y_label_area_size(y_labels);
    builder
}

/// A tick label: plain decimals from 0.001 to 99 999, powers of ten written as
/// 1e-7 outside that range, so no label carries rounding noise.
fn tick(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 {
        "0".into()
    } else if (1e-3..1e5).contains(&a) {
        let s = format!("{v:.3}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        format!("{v:.0e}")
    }
}

/// The least-squares slope of log10(y) against log10(x), over the points with
/// x, y > 0: the exponent k of y ~ x^k.
pub fn log_log_slope(points: &[(f64, f64)]) -> Option<f64> {
    let logs: Vec<(f64, f64)> = points
        .iter()
        .filter(|(x, y)| *x > 0.0 && *y > 0.0)
        .map(|(x, y)| (x.log10(), y.log10()))
        .collect();
    let n = logs.len() as f64;
    if logs.len() < 2 {
        return None;
    }
    let (mx, my) = logs
        .iter()
        .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / n, b + y / n));
    let sxx: f64 = logs.iter().map(|(x, _)| (x - mx) * (x - mx)).sum();
    let sxy: f64 = logs.iter().map(|(x, y)| (x - mx) * (y - my)).sum();
    (sxx > 0.0).then(|| sxy / sxx)
}
