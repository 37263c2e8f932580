//! Lesson 10's cross-check figures: the per-pixel z of the crate's image minus
//! Mitsuba 3's, one map per configuration, from the numbers `scripts/cross-check
//! --update` measured and committed (`chapters/figures/10_9_cross_check_z.csv`), and
//! the error against time of both renderers on one thread, from `scripts/cross-check
//! --time --update` (`chapters/figures/10_9_error_time.csv`). No render happens here:
//! the figures show those runs' numbers, as the page's tables do.

use std::path::Path;

use glam::Vec2;
use render_lessons::course::chart::{Chart, Scale};
use render_lessons::course::diagram::{Diagram, Place, palette};
use render_lessons::course::lesson::Output;
use render_lessons::files::write_atomically;
use render_lessons::{Error, Result};

/// The committed z-maps, beside the book's figures.
const DATA: &str = "chapters/figures/10_9_cross_check_z.csv";
/// The committed error-against-time measurements.
const TIME_DATA: &str = "chapters/figures/10_9_error_time.csv";

/// Each map's pixels are drawn this many screen pixels wide.
const ZOOM: u32 = 4;
/// |z| at which the colour saturates.
const Z_FULL: f32 = 4.0;
/// Caption size in pixels, and the gap between panels.
const TEXT: f32 = 15.0;
const GAP: u32 = 24;

/// Writes `10_9_zmap.png` and `10_9_error_time.svg`.
pub fn figures(out: &Output) -> Result<()> {
    out.diagram("10_9_zmap.png", &zmap_figure(&committed(DATA)?)?)?;
    let svg = error_time_chart(&committed(TIME_DATA)?)?.svg()?;
    write_atomically(&out.file("10_9_error_time.svg"), svg.as_bytes())
}

/// A file `scripts/cross-check` wrote, relative to the repository's root.
fn committed(name: &str) -> Result<String> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(name);
    std::fs::read_to_string(&path).map_err(|e| Error::File {
        path: name.to_string(),
        line: None,
        message: e.to_string(),
    })
}

/// RMS error against seconds on one thread, one line per renderer, from the rows
/// `renderer,spp,seconds,rms_error` (a comment line first).
pub fn error_time_chart(text: &str) -> Result<Chart> {
    let mut chart = Chart::new(
        "Lesson 10's Cornell box: error against time, one thread",
        ("seconds on one thread", Scale::Log),
        ("RMS error against the reference", Scale::Log),
    );
    for (k, line) in text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.starts_with('#'))
    {
        let bad = |message: &str| Error::File {
            path: TIME_DATA.to_string(),
            line: Some(k + 1),
            message: message.to_string(),
        };
        let fields: Vec<&str> = line.split(',').collect();
        let [renderer, _spp, seconds, error] = fields[..] else {
            return Err(bad("not four fields"));
        };
        let number = |v: &str| v.parse::<f64>().map_err(|_| bad("not a number"));
        let point = (number(seconds)?, number(error)?);
        match chart.series.iter_mut().find(|s| s.name == renderer) {
            Some(series) => series.points.push(point),
            None => chart = chart.with(renderer, vec![point]),
        }
    }
    Ok(chart)
}

/// One configuration's map: its label and the z of each pixel, rows from the top.
type Map = (String, Vec<f32>);

/// The size ("W x H" in the header line) and the maps.
fn parse(text: &str) -> Result<((u32, u32), Vec<Map>)> {
    let bad = |message: &str| Error::File {
        path: DATA.to_string(),
        line: None,
        message: message.to_string(),
    };
    let mut lines = text.lines();
    let header = lines.next().ok_or_else(|| bad("empty"))?;
    let size = header
        .split(", ")
        .find_map(|part| {
            let (w, rest) = part.split_once(" x ")?;
            let h = rest.split_whitespace().next()?;
            Some((w.trim().parse().ok()?, h.parse().ok()?))
        })
        .ok_or_else(|| bad("no size in the header"))?;
    let mut maps = Vec::new();
    for line in lines {
        let (label, values) = line.split_once(';').ok_or_else(|| bad("no ';'"))?;
        let z: Vec<f32> = values
            .split(',')
            .map(|v| v.parse().map_err(|_| bad("a z that is not a number")))
            .collect::<Result<_>>()?;
        if z.len() != (size.0 * size.1) as usize {
            return Err(bad("a map of the wrong size"));
        }
        maps.push((label.to_string(), z));
    }
    Ok((size, maps))
}

/// Blue for negative z, white for 0, red for positive, full at |z| = Z_FULL.
fn colour(z: f32) -> [u8; 4] {
    let t = (z.abs() / Z_FULL).min(1.0);
    let fade = |full: u8| (255.0 + (f32::from(full) - 255.0) * t).round() as u8;
    let (r, g, b) = if z >= 0.0 {
        (fade(200), fade(30), fade(30))
    } else {
        (fade(30), fade(80), fade(200))
    };
    [r, g, b, 255]
}

/// The maps two to a row, each under its caption, and a colour bar under them.
pub fn zmap_figure(text: &str) -> Result<Diagram> {
    let ((w, h), maps) = parse(text)?;
    let (pw, ph) = (w * ZOOM, h * ZOOM);
    let band = (TEXT * 1.8) as u32;
    let columns = 2;
    let rows = (maps.len() as u32).div_ceil(columns);
    let legend = 70;
    let width = columns * pw + (columns + 1) * GAP;
    let height = rows * (band + ph) + GAP + legend;
    let mut d = Diagram::new(width, height, (0.0, width as f32), (0.0, height as f32))?;
    for (k, (label, z)) in maps.iter().enumerate() {
        let (col, row) = (k as u32 % columns, k as u32 / columns);
        let left = GAP + col * (pw + GAP);
        let top = row * (band + ph) + band;
        let mut rgba = Vec::with_capacity((pw * ph * 4) as usize);
        for y in 0..ph {
            for x in 0..pw {
                rgba.extend(colour(z[((y / ZOOM) * w + x / ZOOM) as usize]));
            }
        }
        d.image_px(left, top, pw, &rgba);
        let centre = Vec2::new((left + pw / 2) as f32, (top - band / 2) as f32);
        d.text_px(centre, label, TEXT, palette::INK, Place::Centre);
    }
    // The colour bar: z from -Z_FULL to Z_FULL.
    let (bar_w, bar_h) = (width - 4 * GAP, 14);
    let bar_top = height - legend + 10;
    let mut rgba = Vec::new();
    for _ in 0..bar_h {
        for x in 0..bar_w {
            let z = (x as f32 / (bar_w - 1) as f32 * 2.0 - 1.0) * Z_FULL;
            rgba.extend(colour(z));
        }
    }
    d.image_px(2 * GAP, bar_top, bar_w, &rgba);
    for tick in [-4, -2, 0, 2, 4] {
        let x =
            2 * GAP + ((tick as f32 / Z_FULL + 1.0) / 2.0 * (bar_w - 1) as f32) as u32;
        let at = Vec2::new(x as f32, (bar_top + bar_h + 4) as f32);
        let label = if tick > 0 {
            format!("+{tick}")
        } else {
            tick.to_string()
        };
        d.text_px(at, &label, TEXT, palette::INK, Place::Below);
    }
    Ok(d)
}
