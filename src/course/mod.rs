//! The course's own tools, apart from the renderer: figures, tables, measurements.
//!
//! What draws the figures, prints the tables, measures the charts and checks the
//! exercises. The renderer (every module outside `course`) never imports from here;
//! the lessons and the book do.
//!
//! - [`diagram`]: ray diagrams drawn with tiny-skia from the real cameras and shapes;
//! - [`chart`]: SVG + CSV line charts (plotters) for lesson 11;
//! - [`convergence`]: lesson 10's experiment, a ladder of sample counts, every
//!   strategy, and a reference;
//! - [`ladder_figure`]: lesson 10's convergence figure, the ladder's renders captioned;
//! - [`record`]: lesson 10's paths recorded vertex by vertex, for figures;
//! - [`report`]: tables with fixed precision, -0 printed as 0 (the snapshots);
//! - [`image_tables`]: tables about rendered images (pixels per object, differing,
//!   spots);
//! - [`triangle_table`]: a scene as triangles, object by object (lesson 09);
//! - [`compare`]: lesson 09's measurement, a rasterized image against the ray
//!   caster's, away from silhouettes;
//! - [`lesson`]: what every example shares, a file per job: flag parsing, budgets
//!   and the runner of lessons that render images, `--out`, Ctrl-C, one-line errors;
//! - [`failure`]: why a lesson stops, besides the renderer's errors (an exercise
//!   that fails, Ctrl-C, a name that matches nothing);
//! - [`mine`]: `--mine`, a lesson's picture drawn with the student's exercise code;
//! - [`flags`]: the flag values that name core types (`--sampling`, `--scene`);
//! - [`path_flags`]: lesson 10's flags in groups, each making a core value;
//! - [`parsers`]: the value parsers that check a flag's text (finite, in range);
//! - [`measure`]: lesson 11's measurements, one file per chart;
//! - [`exercises`]: the coding exercises and the harness that checks them.

pub mod bars;
pub mod chart;
pub mod compare;
pub mod convergence;
pub mod diagram;
pub mod exercises;
pub mod failure;
pub mod flags;
pub mod image_tables;
pub mod ladder_figure;
pub mod lesson;
pub mod measure;
pub mod mine;
pub mod parsers;
pub mod path_flags;
pub mod record;
pub mod report;
pub mod triangle_table;
