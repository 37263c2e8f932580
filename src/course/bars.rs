//! Bar charts for lesson 11: a few named values side by side (the C anchor, the
//! plain and the robust caster), drawn as SVG with plotters, with the data as CSV
//! beside it, as [`crate::course::chart`] does for line charts.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use plotters::prelude::*;

use crate::course::chart::{HEIGHT, LABEL_SIZE, WIDTH, save_svg_and_csv, titled};
use crate::error::{Error, Problem, Result};

/// Horizontal bars, one per name, the first at the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Bars {
    /// The caption.
    pub title: String,
    /// What the bars' length measures, with its unit, e.g. "ns per ray".
    pub unit: String,
    /// The bars: a name and a value (0 or more).
    pub bars: Vec<(String, f64)>,
}

/// The bars' colours, in order.
const COLOURS: [RGBColor; 3] = [
    RGBColor(90, 90, 90),
    RGBColor(30, 100, 200),
    RGBColor(210, 50, 40),
];

impl Bars {
    /// No bars yet.
    pub fn new(title: &str, unit: &str) -> Bars {
        Bars {
            title: title.to_string(),
            unit: unit.to_string(),
            bars: Vec::new(),
        }
    }

    /// The chart with one more bar, below the others.
    pub fn with(mut self, name: &str, value: f64) -> Bars {
        self.bars.push((name.to_string(), value));
        self
    }

    /// The data as CSV: the unit in a comment line, then `bar,value` rows.
    pub fn csv(&self) -> String {
        let mut out = format!("# value: {}\nbar,value\n", self.unit);
        for (name, value) in &self.bars {
            let _ = writeln!(out, "\"{}\",{value:e}", name.replace('"', "'"));
        }
        out
    }

    /// The chart as an SVG document, [`WIDTH`] x [`HEIGHT`]; an error if a value
    /// is negative or not finite, or there is no bar.
    pub fn svg(&self) -> Result<String> {
        let longest = self.bars.iter().map(|b| b.1).fold(0.0, f64::max);
        if self.bars.is_empty()
            || self.bars.iter().any(|b| !(b.1 >= 0.0 && b.1.is_finite()))
        {
            return Err(Error::Value {
                param: "bars",
                problem: Problem::Invalid {
                    reason: "must be at least one, each finite and 0 or more",
                },
            });
        }
        let mut svg = String::new();
        self.draw(&mut svg, longest.max(f64::MIN_POSITIVE))
            .map_err(|e| Error::File {
                path: format!("chart \"{}\"", self.title),
                line: None,
                message: e.to_string(),
            })?;
        Ok(svg)
    }

    fn draw(
        &self,
        svg: &mut String,
        longest: f64,
    ) -> std::result::Result<(), Box<dyn std::error::Error>> {
        let n = self.bars.len();
        // Bar k (from the top) is centred on y = n - 1 - k.
        let name_at = |y: f64| {
            let k = n as f64 - 1.0 - y.round();
            let near = (y - y.round()).abs() < 1e-6 && k >= 0.0 && k < n as f64;
            near.then(|| self.bars[k as usize].0.clone())
        };
        let root = SVGBackend::with_string(svg, (WIDTH, HEIGHT)).into_drawing_area();
        root.fill(&WHITE)?;
        let mut chart = titled(&root, &self.title, 230)
            .build_cartesian_2d(0.0..longest * 1.2, -0.5..n as f64 - 0.5)?;
        chart
            .configure_mesh()
            .disable_y_mesh()
            .y_labels(n)
            .x_desc(self.unit.as_str())
            .label_style(("sans-serif", LABEL_SIZE))
            .axis_desc_style(("sans-serif", LABEL_SIZE))
            .y_label_formatter(&|y| name_at(*y).unwrap_or_default())
            .draw()?;
        for (k, (_, value)) in self.bars.iter().enumerate() {
            let y = (n - 1 - k) as f64;
            let colour = COLOURS[k % COLOURS.len()];
            chart.draw_series([Rectangle::new(
                [(0.0, y - 0.3), (*value, y + 0.3)],
                colour.filled(),
            )])?;
            chart.draw_series([Text::new(
                format!(" {value:.1}"),
                (*value, y + 0.1),
                ("sans-serif", LABEL_SIZE),
            )])?;
        }
        root.present()?;
        Ok(())
    }

    /// Writes `stem.svg` and `stem.csv` into `dir`, each atomically.
    pub fn save(&self, dir: &Path, stem: &str) -> Result<[PathBuf; 2]> {
        save_svg_and_csv(dir, stem, &self.svg()?, &self.csv())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bars_draw_with_their_names_and_refuse_bad_values() {
        let bars = Bars::new("speed", "ns per ray")
            .with("plain C", 25.0)
            .with("robust Rust", 45.0);
        let svg = bars.svg().unwrap();
        assert!(
            svg.contains("plain C") && svg.contains("robust Rust"),
            "{svg}"
        );
        assert!(bars.csv().ends_with("\"robust Rust\",4.5e1\n"));
        assert!(Bars::new("x", "y").svg().is_err());
        assert!(Bars::new("x", "y").with("a", f64::NAN).svg().is_err());
    }
}
