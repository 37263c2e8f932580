//! Lesson 10's book-only figures: two paths the estimator really traced, recorded
//! vertex by vertex, hemisphere samples with their densities, and one small
//! render per step of the chapter, each what the step's command writes.

use glam::{Vec2, Vec3};
use render_lessons::Result;
use render_lessons::camera::Camera;
use render_lessons::course::diagram::{Diagram, Place, Rgb, palette};
use render_lessons::course::lesson::Output;
use render_lessons::course::record::{PathVertex, RecordedPath, record_path};
use render_lessons::course::report::num;
use render_lessons::framebuffer::Framebuffer;
use render_lessons::material::Material;
use render_lessons::pathtrace::progressive::render_progressive;
use render_lessons::pathtrace::{Passes, PixelSampling, Sampling, Settings};
use render_lessons::rng::Rng;
use render_lessons::sampling::{
    cosine_hemisphere, cosine_hemisphere_pdf, uniform_hemisphere,
    uniform_hemisphere_pdf,
};
use render_lessons::scene::Scene;
use render_lessons::scenes::path_tracing;
use render_lessons::scenes::path_tracing::{SceneName, Staged};

/// Writes `10_path.png`, `10_hemisphere.png` and the steps' renders.
pub fn figures(out: &Output) -> Result<()> {
    out.diagram("10_path.png", &path_figure()?)?;
    out.diagram("10_hemisphere.png", &hemisphere_figure()?)?;
    for step in &STEPS {
        out.image(step.file, &step.render(step.size.0, step.size.1)?)?;
    }
    Ok(())
}

// ANCHOR: steps
/// One step of the chapter: the flags of its command
/// `cargo run --release --example 10_path_tracing -- <flags>`, and what they set.
#[derive(Clone, Copy, Debug)]
pub struct Step {
    /// The figure's file in `chapters/figures/`.
    pub file: &'static str,
    /// The command's flags, as the chapter prints them (read by the test that runs
    /// them, `each_step_figure_is_what_its_command_writes`).
    #[allow(dead_code)]
    pub flags: &'static [&'static str],
    /// `--scene`.
    pub scene: SceneName,
    /// The strategies shown, side by side: `10_<flag>.png` of each (`--sampling`
    /// for one, the study's strategies at the top count for more).
    pub shown: &'static [Sampling],
    /// Russian roulette (`--no-rr` turns it off).
    pub roulette: bool,
    /// `--aperture` (0: the pinhole); the focus is the default 220.
    pub aperture: f32,
    /// `--spp`: the top of the ladder, the count of the images shown.
    pub spp: u32,
    /// `--width` and `--height`: the example's default 160 x 120, larger where the
    /// figure shows several images side by side.
    pub size: (u32, u32),
}

/// The example's default image size.
const DEFAULT: (u32, u32) = (160, 120);

/// Steps 2 to 8 of the chapter, in order.
pub const STEPS: [Step; 7] = [
    Step {
        file: "10_step_uniform.png",
        flags: &[
            "--sampling",
            "uniform",
            "--no-rr",
            "--spp",
            "16",
            "--reference-spp",
            "16",
        ],
        scene: SceneName::Cornell,
        shown: &[Sampling::UniformHemisphere],
        roulette: false,
        aperture: 0.0,
        spp: 16,
        size: DEFAULT,
    },
    Step {
        file: "10_step_cosine.png",
        flags: &[
            "--sampling",
            "cosine",
            "--no-rr",
            "--spp",
            "16",
            "--reference-spp",
            "16",
        ],
        scene: SceneName::Cornell,
        shown: &[Sampling::Cosine],
        roulette: false,
        aperture: 0.0,
        spp: 16,
        size: DEFAULT,
    },
    Step {
        file: "10_step_roulette.png",
        flags: &[
            "--sampling",
            "cosine",
            "--spp",
            "16",
            "--reference-spp",
            "16",
        ],
        scene: SceneName::Cornell,
        shown: &[Sampling::Cosine],
        roulette: true,
        aperture: 0.0,
        spp: 16,
        size: DEFAULT,
    },
    Step {
        file: "10_step_nee.png",
        flags: &["--sampling", "nee", "--spp", "16", "--reference-spp", "16"],
        scene: SceneName::Cornell,
        shown: &[Sampling::NextEvent],
        roulette: true,
        aperture: 0.0,
        spp: 16,
        size: DEFAULT,
    },
    Step {
        file: "10_step_mis.png",
        flags: &[
            "--scene",
            "two-lights",
            "--spp",
            "16",
            "--reference-spp",
            "16",
            "--width",
            "256",
            "--height",
            "192",
        ],
        scene: SceneName::TwoLights,
        shown: &[Sampling::Cosine, Sampling::NextEvent, Sampling::Mis],
        roulette: true,
        aperture: 0.0,
        spp: 16,
        size: (256, 192),
    },
    Step {
        file: "10_step_specular.png",
        flags: &[],
        scene: SceneName::Cornell,
        shown: &[Sampling::Mis],
        roulette: true,
        aperture: 0.0,
        spp: 64,
        size: DEFAULT,
    },
    Step {
        file: "10_step_lens.png",
        flags: &["--aperture", "8", "--spp", "16", "--reference-spp", "16"],
        scene: SceneName::Cornell,
        shown: &[Sampling::Mis],
        roulette: true,
        aperture: 8.0,
        spp: 16,
        size: DEFAULT,
    },
];

impl Step {
    /// The estimator's settings the step's flags give (the example's defaults else).
    pub fn settings(&self, sampling: Sampling) -> Settings {
        Settings {
            sampling,
            max_depth: Some(8),
            russian_roulette: self.roulette,
            ..Settings::default()
        }
    }

    /// The step's images at `width` x `height`, side by side: each a progressive
    /// render with seed 1 from the scene's camera (a thin lens focused at 220 when
    /// the aperture is not 0), the calls the example's study makes.
    pub fn render(&self, width: u32, height: u32) -> Result<Framebuffer> {
        let Staged {
            scene,
            camera: pinhole,
        } = self.scene.build(width, height)?;
        let camera = match self.aperture {
            0.0 => pinhole,
            aperture => pinhole.with_lens(aperture, 220.0)?,
        };
        let passes = Passes {
            pixels: PixelSampling::Independent,
            seed: 1,
        };
        let mut images = Vec::new();
        for &sampling in self.shown {
            let settings = self.settings(sampling);
            render_progressive(
                &scene,
                &camera,
                &settings,
                passes,
                &[self.spp],
                |pass| {
                    images.push(pass.image);
                    Ok(())
                },
            )?;
        }
        Framebuffer::beside(&images.iter().collect::<Vec<_>>(), 4)
    }
}
// ANCHOR_END: steps

/// The pixel (of the default 160 x 120 render, seed 1) whose first sample gives the
/// first path, in row order, that `wanted` accepts; a short search, done once.
fn find_path(
    scene: &Scene,
    camera: &Camera,
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
/// goes through the glass sphere. Both are recorded by `record_path` from the
/// estimator's own `Path`, with next event estimation (MIS draws the same random
/// numbers, so its paths take the same turns).
pub fn path_figure() -> Result<Diagram> {
    let Staged { scene, camera } = path_tracing::cornell(160, 120)?;
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
            && scene.objects()[p.vertices[0].object].material
                == Material::Glass { ior: 1.5 }
            && p.vertices[1].object == p.vertices[0].object
            && is_diffuse(scene, &p.vertices[p.vertices.len() - 1])
            && spread(p, &taken)
    });
    let mut d = Diagram::new(800, 676, (-6.0, 106.0), (-10.0, 92.0))?;
    d.title("Two paths of the Cornell box, seen along -z");
    let xy = |v: Vec3| Vec2::new(v.x, v.y);
    let (red, blue, grey) = (Rgb(190, 60, 60), Rgb(60, 60, 190), Rgb(150, 150, 150));
    d.line(Vec2::new(1.0, 0.0), Vec2::new(1.0, 81.6), red, 4.0);
    d.line(Vec2::new(99.0, 0.0), Vec2::new(99.0, 81.6), blue, 4.0);
    d.line(Vec2::new(1.0, 0.0), Vec2::new(99.0, 0.0), grey, 4.0);
    d.line(Vec2::new(1.0, 81.6), Vec2::new(99.0, 81.6), grey, 4.0);
    let half = path_tracing::CORNELL_LIGHT_SIDE / 2.0;
    let light_y = 81.6 - path_tracing::CORNELL_LIGHT_GAP;
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

fn camera_eye(camera: &Camera) -> Vec3 {
    camera.ray_through(Vec2::splat(0.5), Vec2::ZERO).origin()
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
    let mut d = Diagram::new(800, 300, (-1.1, 7.4), (-0.5, 1.6))?;
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
    // In f32, cos(pi/2) rounds to just below 0: at the horizon the cosine is 0.
    let uniform = curve(|t| uniform_hemisphere_pdf(t.cos().max(0.0)));
    let cosine = curve(|t| cosine_hemisphere_pdf(t.cos().max(0.0)));
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
