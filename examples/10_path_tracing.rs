//! Lesson 10: Monte Carlo path tracing, an estimator of Kajiya's rendering equation
//! (Lecture 2).
//!
//! smallpt's Cornell box rendered progressively at 1, 4, 16 and 64 samples per pixel,
//! each image compared with a reference of many more samples: the error (RMSE)
//! falls as 1/sqrt(N). A second table compares the four ways of sampling at the same
//! sample count.
//!
//!     cargo run --release --example 10_path_tracing
//!     cargo run --release --example 10_path_tracing -- --sampling cosine --spp 256 --jitter
//!     cargo run --release --example 10_path_tracing -- --scene two-lights --aperture 0.2

use std::process::ExitCode;
use std::time::Instant;

use clap::{Parser, ValueEnum};
use indicatif::{ProgressBar, ProgressStyle};
use render_lessons::Result;
use render_lessons::course::lesson::{self, Output, parse_finite};
use render_lessons::course::report::{Table, num};
use render_lessons::error::Error;
use render_lessons::framebuffer::Framebuffer;
use render_lessons::pathtrace::pfm::save_pfm;
use render_lessons::pathtrace::progressive::rmse;
use render_lessons::pathtrace::scenes;
use render_lessons::pathtrace::{
    Accumulator, LensCamera, PixelSampling, Sampling, Settings, SphereSampling,
};

use glam::{Vec2, Vec3};
use render_lessons::basis::Basis;
use render_lessons::course::diagram::{Diagram, Place, Rgb, palette};
use render_lessons::material::{Material, diffuse_brdf};
use render_lessons::scene::Scene;
use render_lessons::pathtrace::roulette::{RR_MAX_SURVIVAL, RR_START};
use render_lessons::pathtrace::{Rng, light};
use render_lessons::ray::Ray;
use render_lessons::sampling::{cosine_hemisphere, uniform_hemisphere};

/// The sampling strategies, as typed after `--sampling`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum SamplingArg {
    /// Uniform directions over the hemisphere.
    Uniform,
    /// Cosine-weighted directions.
    Cosine,
    /// Cosine directions plus one light sample per bounce (next event estimation).
    Nee,
    /// Both, weighted by the power heuristic (multiple importance sampling).
    Mis,
}

impl SamplingArg {
    /// All four, worst first.
    pub const ALL: [SamplingArg; 4] = [
        SamplingArg::Uniform,
        SamplingArg::Cosine,
        SamplingArg::Nee,
        SamplingArg::Mis,
    ];

    fn sampling(self) -> Sampling {
        match self {
            SamplingArg::Uniform => Sampling::UniformHemisphere,
            SamplingArg::Cosine => Sampling::Cosine,
            SamplingArg::Nee => Sampling::NextEvent,
            SamplingArg::Mis => Sampling::Mis,
        }
    }

    fn name(self) -> &'static str {
        match self {
            SamplingArg::Uniform => "uniform hemisphere",
            SamplingArg::Cosine => "cosine",
            SamplingArg::Nee => "next event",
            SamplingArg::Mis => "MIS",
        }
    }
}

/// The scenes, as typed after `--scene`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum SceneArg {
    /// smallpt's Cornell box, walls as planes, a square ceiling light.
    Cornell,
    /// A floor under a small and a large spherical light.
    TwoLights,
    /// Inside a glowing sphere of albedo 0.5 (STABILITY S16).
    Furnace,
    /// A grey sphere in a white environment (STABILITY S17).
    GreyFurnace,
}

/// The lesson's parameters; every one has a default that reproduces the book.
#[derive(Parser, Debug)]
#[command(
    about = "Lesson 10: Monte Carlo path tracing, progressive, with four sampling strategies"
)]
#[command(allow_negative_numbers = true)]
pub struct Args {
    /// Image width in pixels.
    #[arg(long, default_value_t = 160)]
    pub width: u32,
    /// Image height in pixels.
    #[arg(long, default_value_t = 120)]
    pub height: u32,
    /// The largest sample count of the ladder 1, 4, 16, ... (powers of 4 up to it).
    #[arg(long, default_value_t = 64)]
    pub spp: u32,
    /// Samples per pixel of the reference image the errors are measured against.
    #[arg(long, default_value_t = 512)]
    pub reference_spp: u32,
    /// How directions are chosen at diffuse surfaces.
    #[arg(long, value_enum, default_value_t = SamplingArg::Mis)]
    pub sampling: SamplingArg,
    /// The scene.
    #[arg(long, value_enum, default_value_t = SceneArg::Cornell)]
    pub scene: SceneArg,
    /// Seed of the random streams (one per pixel). The images depend on it, not on
    /// the thread count.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Worker threads (default: every core).
    #[arg(long)]
    pub threads: Option<usize>,
    /// The most bounces a path may take.
    #[arg(long, default_value_t = 8)]
    pub max_depth: u32,
    /// Russian roulette on (the default; the last of --rr and --no-rr wins).
    #[arg(long = "rr", overrides_with = "no_rr")]
    pub rr: bool,
    /// Russian roulette off: every path runs to --max-depth unless it escapes.
    #[arg(long = "no-rr", overrides_with = "rr")]
    pub no_rr: bool,
    /// Jittered (stratified) pixel samples instead of independent ones; every
    /// sample count of the ladder is then a square, as it must be.
    #[arg(long)]
    pub jitter: bool,
    /// Lens radius of the thin-lens camera (0: pinhole).
    #[arg(long, default_value = "0", value_parser = parse_finite)]
    pub aperture: f32,
    /// Distance of the plane in focus (only used with an aperture); the default is
    /// about the distance of the Cornell box's glass sphere from the camera.
    #[arg(long, default_value = "220", value_parser = parse_finite)]
    pub focus: f32,
    #[command(flatten)]
    pub output: Output,
}

// ANCHOR: setup
/// The chosen scene and its camera, with the chosen lens.
pub fn scene(args: &Args) -> Result<(Scene, LensCamera)> {
    let (w, h) = (args.width, args.height);
    let (scene, camera) = match args.scene {
        SceneArg::Cornell => scenes::cornell(w, h)?,
        SceneArg::TwoLights => scenes::two_lights(w, h)?,
        SceneArg::Furnace => scenes::interior_furnace(w, h)?,
        SceneArg::GreyFurnace => scenes::grey_furnace(w, h, glam::Vec3::ZERO)?,
    };
    let camera = if args.aperture == 0.0 {
        camera
    } else {
        camera.with_lens(args.aperture, args.focus)?
    };
    Ok((scene, camera))
}

/// The estimator's settings for `sampling` and the flags.
pub fn settings(args: &Args, sampling: SamplingArg) -> Settings {
    Settings {
        sampling: sampling.sampling(),
        sphere_lights: SphereSampling::Cone,
        max_depth: Some(args.max_depth),
        russian_roulette: !args.no_rr,
        ..Settings::default()
    }
}
// ANCHOR_END: setup

fn pixel_sampling(args: &Args) -> PixelSampling {
    if args.jitter {
        PixelSampling::Jittered
    } else {
        PixelSampling::Independent
    }
}

/// 1, 4, 16, ... up to `spp` (`spp` itself last if it is not a power of 4).
pub fn ladder(spp: u32) -> Result<Vec<u32>> {
    if spp == 0 {
        return Err(Error::TooFew {
            param: "spp",
            value: 0,
            min: 1,
        });
    }
    let mut steps: Vec<u32> = std::iter::successors(Some(1u32), |n| n.checked_mul(4))
        .take_while(|&n| n <= spp)
        .collect();
    if steps.last() != Some(&spp) {
        steps.push(spp);
    }
    Ok(steps)
}

/// The images of one progressive render and how they were made.
pub struct Renders {
    /// (samples per pixel, image) for each rung of the ladder, with the chosen sampling.
    pub ladder: Vec<(u32, Framebuffer)>,
    /// (strategy, image at the ladder's largest count) for every strategy.
    pub strategies: Vec<(SamplingArg, Framebuffer)>,
    /// The reference: MIS at `reference_spp`.
    pub reference: Framebuffer,
    /// Samples that came out NaN or infinite (and were dropped): should be 0.
    pub non_finite: u64,
}

// ANCHOR: progressive
/// Renders `total` samples per pixel with `sampling` in passes, calling `each` with the
/// image after every pass that ends on one of `stops`.
fn progressive(
    args: &Args,
    sampling: SamplingArg,
    seed: u64,
    stops: &[u32],
    bar: &ProgressBar,
    mut each: impl FnMut(u32, Framebuffer) -> Result<()>,
) -> Result<u64> {
    let (scene, camera) = scene(args)?;
    let settings = settings(args, sampling);
    let mut acc = Accumulator::new(&camera, seed);
    for &stop in stops {
        let spp = stop - acc.samples();
        let pixels = pixel_sampling(args);
        let image = acc.render_pass(&scene, &camera, &settings, pixels, spp, args.threads)?;
        bar.inc(u64::from(spp));
        each(stop, image)?;
    }
    Ok(acc.non_finite())
}
// ANCHOR_END: progressive

/// Pass boundaries for the reference: 16 samples at a time, so its file can be
/// rewritten (atomically) as it sharpens.
fn reference_stops(spp: u32) -> Vec<u32> {
    let mut stops: Vec<u32> = (1..=spp / 16).map(|i| i * 16).collect();
    if stops.last() != Some(&spp) {
        stops.push(spp);
    }
    stops
}

/// Every image of the lesson. The ladder is one progressive render (passes of 1, 3,
/// 12, 48 samples); with `--jitter` each rung is rendered afresh instead, because
/// jittered passes need a square number of samples (1, 4, 16, 64 are; 3, 12, 48 are
/// not). The reference is rendered in passes of 16 with its own seed, its PNG
/// rewritten (atomically) after each.
pub fn render_all(args: &Args, bar: &ProgressBar) -> Result<Renders> {
    let steps = ladder(args.spp)?;
    if args.reference_spp == 0 {
        return Err(Error::TooFew {
            param: "reference-spp",
            value: 0,
            min: 1,
        });
    }
    let mut ladder_images = Vec::new();
    let passes: Vec<&[u32]> = if args.jitter {
        steps.chunks(1).collect()
    } else {
        vec![&steps]
    };
    let mut non_finite = 0;
    for stops in passes {
        non_finite += progressive(args, args.sampling, args.seed, stops, bar, |n, img| {
            ladder_images.push((n, img));
            Ok(())
        })?;
    }
    let mut strategies = Vec::new();
    for s in SamplingArg::ALL {
        if s == args.sampling {
            let last = ladder_images.last().map(|(_, img)| img.clone());
            strategies.extend(last.map(|img| (s, img)));
            continue;
        }
        non_finite += progressive(args, s, args.seed, &[args.spp], bar, |_, img| {
            strategies.push((s, img));
            Ok(())
        })?;
    }
    let mut reference = None;
    let reference_seed = args.seed.wrapping_add(0x9e37_79b9);
    let stops = reference_stops(args.reference_spp);
    non_finite += progressive(
        args,
        SamplingArg::Mis,
        reference_seed,
        &stops,
        bar,
        |_, img| {
            img.save_png(&args.output.file("10_reference.png"))?;
            reference = Some(img);
            Ok(())
        },
    )?;
    Ok(Renders {
        ladder: ladder_images,
        strategies,
        reference: reference.ok_or(Error::TooFew {
            param: "reference-spp",
            value: 0,
            min: 1,
        })?,
        non_finite,
    })
}

/// The total number of samples per pixel [`render_all`] takes, for the progress bar.
pub fn total_samples(args: &Args) -> u64 {
    let ladder = if args.jitter {
        ladder(args.spp).map_or(0, |l| l.iter().map(|&n| u64::from(n)).sum())
    } else {
        u64::from(args.spp)
    };
    ladder + 3 * u64::from(args.spp) + u64::from(args.reference_spp)
}

// ANCHOR: numbers
/// The lesson's tables: error against the reference as samples grow, and the four
/// strategies side by side. Independent of timing and thread count.
pub fn numbers(args: &Args, renders: &Renders) -> Result<String> {
    let mut ladder = Table::new(
        &format!(
            "{:?} scene, {} x {}, {} sampling{}: RMSE against a {}-sample MIS reference",
            args.scene,
            args.width,
            args.height,
            args.sampling.name(),
            if args.jitter { ", jittered" } else { "" },
            args.reference_spp
        ),
        &["spp", "RMSE", "RMSE x sqrt(spp)", "mean"],
    );
    for (spp, image) in &renders.ladder {
        let e = rmse(image, &renders.reference);
        ladder.row(vec![
            spp.to_string(),
            num(e, 5),
            num(e * f64::from(*spp).sqrt(), 4),
            num(image.mean(), 5),
        ]);
    }
    let mut strategies = Table::new(
        &format!("The four strategies at {} spp", args.spp),
        &["sampling", "RMSE", "mean"],
    );
    for (s, image) in &renders.strategies {
        strategies.row(vec![
            s.name().to_string(),
            num(rmse(image, &renders.reference), 5),
            num(image.mean(), 5),
        ]);
    }
    Ok(format!(
        "{ladder}\n{strategies}\nreference mean {}; samples dropped as NaN or infinite: {}\n",
        num(renders.reference.mean(), 5),
        renders.non_finite
    ))
}
// ANCHOR_END: numbers

// ANCHOR: record_path
/// One vertex of a recorded path: where it is, which object it is on, and, at a
/// diffuse vertex, the point that next event estimation aimed at on the light and
/// whether the shadow ray reached it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PathVertex {
    /// The hit point.
    pub point: Vec3,
    /// The index of the object hit.
    pub object: usize,
    /// The light sample of next event estimation: (point, unoccluded).
    pub light_sample: Option<(Vec3, bool)>,
}

/// A path as the estimator traces it, recorded for a figure.
#[derive(Clone, Debug, PartialEq)]
pub struct RecordedPath {
    /// Where the camera ray starts.
    pub eye: Vec3,
    /// The surfaces the path met, in order.
    pub vertices: Vec<PathVertex>,
    /// The direction of the last ray if it left the scene.
    pub escaped: Option<Vec3>,
    /// The path's radiance sample with next event estimation.
    pub radiance: Vec3,
}

/// The first sample of pixel (`x`, `y`) (independent pixel samples, stream seeded from
/// (`seed`, x, y)), traced step by step as `radiance` in src/pathtrace/estimator.rs
/// does with `Sampling::NextEvent`, drawing the same random numbers in the same order,
/// and recorded. MIS draws the same numbers too, so its paths take the same turns.
pub fn record_path(
    scene: &Scene,
    camera: &LensCamera,
    s: &Settings,
    seed: u64,
    (x, y): (u32, u32),
) -> RecordedPath {
    let mut rng = Rng::for_pixel(seed, x, y);
    let position = Vec2::new(x as f32, y as f32) + rng.next_vec2();
    let mut ray = camera.ray(position, rng.next_vec2());
    let mut path = RecordedPath {
        eye: ray.origin(),
        vertices: Vec::new(),
        escaped: None,
        radiance: Vec3::ZERO,
    };
    let (mut beta, mut t_min, mut count_emission, mut bounce) = (Vec3::ONE, 0.0, true, 0);
    loop {
        let Some((hit, index)) = scene.closest(&ray, t_min, f32::INFINITY) else {
            path.radiance += beta * scene.background();
            path.escaped = Some(ray.direction());
            break;
        };
        let object = &scene.objects()[index];
        if count_emission {
            path.radiance += beta * object.emission;
        }
        let mut vertex = PathVertex {
            point: hit.point,
            object: index,
            light_sample: None,
        };
        if s.max_depth.is_some_and(|m| bounce >= m) || !hit.point.is_finite() {
            path.vertices.push(vertex);
            break;
        }
        let facing = if hit.front_face {
            hit.normal
        } else {
            -hit.normal
        };
        let (start, direction, weight) = match object.material {
            Material::Diffuse { albedo } => {
                let start = s.offset.start(hit.point, facing);
                let (sample, direct) = next_event(scene, start, facing, albedo, &mut rng, s);
                vertex.light_sample = sample;
                path.radiance += beta * direct;
                let local = cosine_hemisphere(rng.next_vec2());
                let direction = Basis::around(facing).to_world(local).normalize_or(facing);
                count_emission = false;
                (start, direction, albedo)
            }
            specular => {
                let u = rng.next_f32();
                let Some(next) =
                    specular.scatter_specular(ray.direction(), facing, hit.front_face, u)
                else {
                    path.vertices.push(vertex);
                    break;
                };
                let side = if next.transmitted { -facing } else { facing };
                count_emission = true;
                (s.offset.start(hit.point, side), next.direction, next.weight)
            }
        };
        path.vertices.push(vertex);
        beta *= weight;
        bounce += 1;
        // Russian roulette, as src/pathtrace/roulette.rs plays it.
        if beta.max_element() <= 0.0 {
            break;
        }
        if s.russian_roulette && bounce >= RR_START {
            let q = beta.max_element().min(RR_MAX_SURVIVAL);
            if rng.next_f32() >= q {
                break;
            }
            beta /= q;
        }
        let Ok(next) = Ray::new(start.0, direction) else {
            break;
        };
        (ray, t_min) = (next, start.1);
    }
    path
}

/// Next event estimation as src/pathtrace/next_event.rs does it: one light, one
/// point on it, one shadow ray. Returns the sample (point, unoccluded) and
/// f_r L_e cos / pdf.
fn next_event(
    scene: &Scene,
    (from, t_min): (Vec3, f32),
    n: Vec3,
    albedo: Vec3,
    rng: &mut Rng,
    s: &Settings,
) -> (Option<(Vec3, bool)>, Vec3) {
    let count = scene.lights().len();
    if count == 0 {
        return (None, Vec3::ZERO);
    }
    let pick = ((rng.next_f32() * count as f32) as usize).min(count - 1);
    let light = &scene.objects()[scene.lights()[pick]];
    let Some(y) = light::sample(&light.shape, from, rng.next_vec2(), s.sphere_lights) else {
        return (None, Vec3::ZERO);
    };
    let visible = (|| {
        let cos = n.dot((y.point - from).try_normalize()?);
        if cos.is_nan() || cos <= 0.0 {
            return None;
        }
        let n_l = if y.normal.dot(from - y.point) >= 0.0 {
            y.normal
        } else {
            -y.normal
        };
        let (to, t_end) = s.offset.start(y.point, n_l);
        let ray = Ray::new(from, to - from).ok()?;
        let t_max = (to - from).length() - t_end;
        (!scene.occluded(&ray, t_min, t_max)).then_some(cos)
    })();
    let pdf = y.pdf / count as f32;
    let direct = visible.map_or(Vec3::ZERO, |cos| {
        diffuse_brdf(albedo) * light.emission * (cos * 1.0 / pdf)
    });
    (Some((y.point, visible.is_some())), direct)
}
// ANCHOR_END: record_path

/// The pixel (of the default 160 x 120 render, seed 1) whose first sample gives the
/// first path, in row order, that `wanted` accepts; a short search, done once.
fn find_path(
    scene: &Scene,
    camera: &LensCamera,
    s: &Settings,
    wanted: impl Fn(&Scene, &RecordedPath) -> bool,
) -> Option<((u32, u32), RecordedPath)> {
    let (w, h) = (camera.film().width(), camera.film().height());
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|pixel| (pixel, record_path(scene, camera, s, 1, pixel)))
        .find(|(_, path)| wanted(scene, path))
}

/// `true` if the path's vertices, seen along -z, lie at least 9 units from each other
/// and from `others`: a figure with readable numbers.
fn spread(path: &RecordedPath, others: &[Vec3]) -> bool {
    let xy = |v: Vec3| Vec2::new(v.x, v.y);
    let points: Vec<Vec2> = path.vertices.iter().map(|v| xy(v.point)).collect();
    points.iter().enumerate().all(|(i, p)| {
        points[..i]
            .iter()
            .copied()
            .chain(others.iter().map(|o| xy(*o)))
            .all(|q| p.distance(q) >= 9.0)
    })
}

/// A diffuse surface that is not a light.
fn is_diffuse(scene: &Scene, v: &PathVertex) -> bool {
    let object = &scene.objects()[v.object];
    matches!(object.material, Material::Diffuse { .. }) && !object.is_emissive()
}

// ANCHOR: path_figure
/// The figure of the Cornell box seen along -z (the x-y plane; the back wall is the
/// page), with two real paths of the default render: one that bounces between the
/// diffuse walls, its light sample at the first bounce drawn dashed, and one that
/// goes through the glass sphere.
pub fn path_figure() -> Result<Diagram> {
    let (scene, camera) = scenes::cornell(160, 120)?;
    let s = Settings {
        sampling: Sampling::NextEvent,
        ..Settings::default()
    };
    let diffuse_path = find_path(&scene, &camera, &s, |scene, p| {
        (4..=5).contains(&p.vertices.len())
            && p.vertices.iter().all(|v| is_diffuse(scene, v))
            && p.vertices[0].point.y < 60.0
            && p.vertices[0]
                .light_sample
                .is_some_and(|(y, seen)| seen && y.distance(p.vertices[0].point) > 40.0)
            && spread(p, &[])
    });
    let taken: Vec<Vec3> = diffuse_path
        .iter()
        .flat_map(|(_, p)| p.vertices.iter().map(|v| v.point))
        .collect();
    let glass_path = find_path(&scene, &camera, &s, |scene, p| {
        (4..=5).contains(&p.vertices.len())
            && scene.objects()[p.vertices[0].object].material == Material::Glass { ior: 1.5 }
            && p.vertices[1].object == p.vertices[0].object
            && is_diffuse(scene, &p.vertices[p.vertices.len() - 1])
            && spread(p, &taken)
    });
    let mut d = Diagram::new(900, 760, (-6.0, 106.0), (-10.0, 92.0))?;
    d.title("Two paths of the Cornell box, seen along -z");
    let xy = |v: Vec3| Vec2::new(v.x, v.y);
    let (red, blue, grey) = (Rgb(190, 60, 60), Rgb(60, 60, 190), Rgb(150, 150, 150));
    d.line(Vec2::new(1.0, 0.0), Vec2::new(1.0, 81.6), red, 4.0);
    d.line(Vec2::new(99.0, 0.0), Vec2::new(99.0, 81.6), blue, 4.0);
    d.line(Vec2::new(1.0, 0.0), Vec2::new(99.0, 0.0), grey, 4.0);
    d.line(Vec2::new(1.0, 81.6), Vec2::new(99.0, 81.6), grey, 4.0);
    let half = scenes::CORNELL_LIGHT_SIDE / 2.0;
    let light_y = 81.6 - scenes::CORNELL_LIGHT_GAP;
    d.line(
        Vec2::new(50.0 - half, light_y),
        Vec2::new(50.0 + half, light_y),
        palette::PLANE,
        7.0,
    );
    d.text(Vec2::new(50.0, 81.6), "light", palette::INK, Place::Above);
    d.circle(Vec2::new(27.0, 16.5), 16.5, palette::INK, 1.5);
    d.circle(Vec2::new(73.0, 16.5), 16.5, palette::INK, 1.5);
    d.text(Vec2::new(10.5, 16.5), "mirror", palette::INK, Place::Left);
    d.text(Vec2::new(89.5, 16.5), "glass", palette::INK, Place::Right);
    d.text(Vec2::new(1.0, 78.0), "x = 1", red, Place::Left);
    d.text(Vec2::new(99.0, 78.0), "x = 99", blue, Place::Right);
    let paths = [(diffuse_path, palette::RAY), (glass_path, palette::CAMERA)];
    for (found, colour) in &paths {
        let Some((_, path)) = found else { continue };
        let mut from = xy(path.eye);
        for (i, v) in path.vertices.iter().enumerate() {
            let p = xy(v.point);
            d.arrow(from, p, *colour, 2.0);
            from = p;
            if i == 0
                && let Some((target, true)) = v.light_sample
            {
                d.dashed(p, xy(target), palette::HIT, 2.0);
                d.dot(xy(target), 4.0, palette::HIT);
            }
        }
        if let Some(dir) = path.escaped {
            let end = from + 12.0 * xy(dir).normalize_or(Vec2::Y);
            d.arrow(from, end, *colour, 2.0);
        }
        for (i, v) in path.vertices.iter().enumerate() {
            d.dot(xy(v.point), 5.0, *colour);
            d.text(xy(v.point), &(i + 1).to_string(), *colour, Place::Right);
        }
    }
    d.dot(xy(camera_eye(&camera)), 6.0, palette::INK);
    d.text(
        xy(camera_eye(&camera)),
        "eye (z = 295.6)",
        palette::INK,
        Place::Above,
    );
    let mut legend = Vec::new();
    for ((found, _), name) in paths.iter().zip(["blue", "purple"]) {
        if let Some(((x, y), p)) = found {
            legend.push(format!(
                "{name}: first sample of pixel ({x}, {y}), {} surfaces",
                p.vertices.len()
            ));
        }
    }
    legend.push("dashed: the shadow ray of next event estimation".to_string());
    for (i, line) in legend.iter().enumerate() {
        d.text(
            Vec2::new(50.0, -4.0 - 4.0 * i as f32),
            line,
            palette::INK,
            Place::Below,
        );
    }
    Ok(d)
}
// ANCHOR_END: path_figure

fn camera_eye(camera: &LensCamera) -> Vec3 {
    camera.ray(Vec2::splat(0.5), Vec2::ZERO).origin()
}

/// A map from the unit square to directions.
type Mapping = fn(Vec2) -> Vec3;

// ANCHOR: hemisphere_figure
/// Hemisphere samples seen from the side: the same `n` uniform points of the unit
/// square (seed 1, the stream of pixel (0, 0)) mapped by `uniform_hemisphere` and by
/// `cosine_hemisphere`, and the density per unit solid angle of each, counted in 9
/// bins of equal solid angle, against 1 / (2 pi) and cos(theta) / pi.
pub fn hemisphere_figure() -> Result<Diagram> {
    const N: usize = 1000;
    const BINS: usize = 9;
    let mut rng = Rng::for_pixel(1, 0, 0);
    let us: Vec<Vec2> = (0..N).map(|_| rng.next_vec2()).collect();
    let mut d = Diagram::new(1500, 440, (-1.1, 7.4), (-0.5, 1.7))?;
    d.title(&format!(
        "{N} directions around the normal +z, seen from the side"
    ));
    let strategies: [(&str, Mapping, Rgb); 2] = [
        ("uniform: pdf 1/(2 pi)", uniform_hemisphere, palette::RAY),
        ("cosine: pdf cos(theta)/pi", cosine_hemisphere, palette::HIT),
    ];
    // The histogram panel: theta in [0, 90] degrees across 2 units, pdf x 3.4 upwards.
    let plot = |theta: f32, pdf: f32| {
        Vec2::new(4.9 + theta / std::f32::consts::FRAC_PI_2 * 1.9, 3.4 * pdf)
    };
    for (k, (name, map, colour)) in strategies.iter().enumerate() {
        let at = Vec2::new(2.4 * k as f32, 0.0);
        let rim: Vec<Vec2> = (0..=64)
            .map(|i| at + Vec2::from_angle(std::f32::consts::PI * i as f32 / 64.0))
            .collect();
        d.outline(&rim, palette::GRID, 1.5);
        let mut counts = [0usize; BINS];
        for u in &us {
            let w = map(*u);
            d.dot(at + Vec2::new(w.x, w.z), 1.6, *colour);
            // Bins of equal solid angle: equal steps of cos(theta).
            let bin = ((1.0 - w.z) * BINS as f32) as usize;
            counts[bin.min(BINS - 1)] += 1;
        }
        d.arrow(at, at + Vec2::new(0.0, 1.25), palette::NORMAL, 2.0);
        d.text(
            at + Vec2::new(0.0, 1.25),
            "n",
            palette::NORMAL,
            Place::Right,
        );
        d.text(at + Vec2::new(0.0, -0.05), name, *colour, Place::Below);
        for (b, &count) in counts.iter().enumerate() {
            let (top, bottom) = (
                1.0 - b as f32 / BINS as f32,
                1.0 - (b + 1) as f32 / BINS as f32,
            );
            let solid_angle = std::f32::consts::TAU / BINS as f32;
            let density = count as f32 / (N as f32 * solid_angle);
            let theta = (0.5 * (top + bottom)).acos();
            d.dot(plot(theta, density), 4.0, *colour);
        }
    }
    let curve = |f: fn(f32) -> f32| -> Vec<Vec2> {
        (0..=45)
            .map(|i| i as f32 / 45.0 * std::f32::consts::FRAC_PI_2)
            .map(|t| plot(t, f(t)))
            .collect()
    };
    let uniform = curve(|_| 1.0 / std::f32::consts::TAU);
    let cosine = curve(|t| t.cos() / std::f32::consts::PI);
    for pair in uniform.windows(2) {
        d.line(pair[0], pair[1], palette::RAY, 1.5);
    }
    for pair in cosine.windows(2) {
        d.line(pair[0], pair[1], palette::HIT, 1.5);
    }
    d.arrow(plot(0.0, 0.0), plot(1.75, 0.0), palette::INK, 1.5);
    d.arrow(plot(0.0, 0.0), plot(0.0, 0.4), palette::INK, 1.5);
    d.text(plot(1.75, 0.0), "theta", palette::INK, Place::Right);
    for deg in [0.0f32, 30.0, 60.0, 90.0] {
        let p = plot(deg.to_radians(), 0.0);
        d.text(p, &format!("{deg}°"), palette::INK, Place::Below);
    }
    for v in [0.1f32, 0.2, 0.3] {
        let p = plot(0.0, v);
        d.line(p, p + Vec2::new(-0.03, 0.0), palette::INK, 1.0);
        d.text(p, &num(f64::from(v), 1), palette::INK, Place::Left);
    }
    d.text(
        plot(0.0, 0.4),
        "density per unit solid angle",
        palette::INK,
        Place::Right,
    );
    d.text(
        plot(std::f32::consts::FRAC_PI_4, 0.0) + Vec2::new(0.0, -0.22),
        "dots: histogram of the samples; lines: the pdfs",
        palette::INK,
        Place::Below,
    );
    Ok(d)
}
// ANCHOR_END: hemisphere_figure

fn progress_bar(total: u64) -> ProgressBar {
    let bar = ProgressBar::new(total);
    if let Ok(style) =
        ProgressStyle::with_template("{bar:40} {pos}/{len} samples per pixel, {eta} left")
    {
        bar.set_style(style);
    }
    bar
}

fn main() -> ExitCode {
    let args = Args::parse();
    lesson::run(|| {
        let start = Instant::now();
        let bar = progress_bar(total_samples(&args));
        let renders = render_all(&args, &bar)?;
        bar.finish_and_clear();
        let seconds = start.elapsed().as_secs_f64();
        lesson::print(&numbers(&args, &renders)?);
        lesson::print(&format!("rendered in {seconds:.1} s\n"));
        for (spp, image) in &renders.ladder {
            args.output.image(&format!("10_{spp}spp.png"), image)?;
        }
        for (s, image) in &renders.strategies {
            args.output
                .image(&format!("10_{:?}.png", s).to_lowercase(), image)?;
        }
        args.output.image("10_reference.png", &renders.reference)?;
        let ladder: Vec<&Framebuffer> = renders.ladder.iter().map(|(_, img)| img).collect();
        args.output
            .image("10_convergence.png", &Framebuffer::beside(&ladder, 4)?)?;
        args.output.diagram("10_path.png", &path_figure()?)?;
        args.output
            .diagram("10_hemisphere.png", &hemisphere_figure()?)?;
        let pfm = args.output.file("10_reference.pfm");
        save_pfm(&pfm, &renders.reference)?;
        lesson::wrote(&pfm);
        Ok(())
    })
}
