//! Lesson 09: the rasterization pipeline of Lecture 2, side by side with ray casting.
//!
//! Lesson 08's scene again, drawn triangle by triangle: the spheres become meshes
//! (a rasterizer only draws triangles), the infinite floor a large square. The ray
//! caster's image of the true scene is the reference. The lesson measures the
//! lecture's claim: rasterization is fast, but not realistic. It has no shadows
//! until a second trick (a shadow map) adds them, with artefacts of its own.
//!
//!     cargo run --release --example 09_rasterization
//!     cargo run --release --example 09_rasterization -- --width 1920 --height 1080

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use clap::Parser;
use glam::{Vec2, Vec3};
use render_lessons::camera::Camera;
use render_lessons::course::diagram::{Diagram, Place, Rgb, palette};
use render_lessons::course::lesson::{self, Output, parse_finite};
use render_lessons::course::report::{Table, num};
use render_lessons::framebuffer::{Framebuffer, to_srgb8};
use render_lessons::offset::Offset;
use render_lessons::raster::{ClipVertex, Cull, DepthRange, Fragment, ScreenVertex, Varyings};
use render_lessons::raster::{
    Instance, Mesh, Pipeline, Settings, Shading, Shadows, rasterize, rasterize_triangle,
};
use render_lessons::raycast::{lit, lit_unshadowed};
use render_lessons::render::render;
use render_lessons::scene::{Object, Scene};
use render_lessons::shapes::Shape;
use render_lessons::transform::Transform;
use render_lessons::{Error, Result};

#[path = "08_ray_casting.rs"]
#[allow(dead_code)]
mod lesson08;

/// The lesson's parameters; every one has a default that reproduces the book.
#[derive(Parser, Debug)]
#[command(about = "Lesson 09: the rasterization pipeline, side by side with ray casting")]
#[command(allow_negative_numbers = true)]
pub struct Args {
    /// Image width in pixels.
    #[arg(long, default_value_t = 480)]
    pub width: u32,
    /// Image height in pixels.
    #[arg(long, default_value_t = 270)]
    pub height: u32,
    /// Worker threads (default: every core). The images do not depend on it.
    #[arg(long)]
    pub threads: Option<usize>,
    /// Slices of longitude of each tessellated sphere (bands of latitude: half).
    #[arg(long, default_value_t = 64)]
    pub segments: u32,
    /// Texels along each side of the shadow map.
    #[arg(long, default_value_t = 1024)]
    pub shadow_map_size: u32,
    /// The shadow map's bias, in texel footprints.
    #[arg(long, default_value = "1", value_parser = parse_finite)]
    pub bias: f32,
    /// The mesh drawn by both renderers (a Wavefront OBJ file of triangles).
    #[arg(long, default_value = concat!(env!("CARGO_MANIFEST_DIR"), "/assets/meshes/torus.obj"))]
    pub mesh: PathBuf,
    #[command(flatten)]
    pub output: Output,
}

/// Side of the square that stands in for lesson 08's infinite floor.
pub const FLOOR_SIZE: f32 = 1e4;

/// A rasterization needs a far plane; this one lies beyond the floor's far edge.
pub const DEPTH: DepthRange = DepthRange {
    near: 0.1,
    far: 2e4,
};

/// Colours more than this apart (linear RGB, in some channel) count as different:
/// about one step of an 8-bit image.
pub const TOLERANCE: f32 = 1.0 / 255.0;

// ANCHOR: tessellate
/// Lesson 08's scene as triangle meshes, object by object in the same order: a
/// sphere becomes a uv sphere of `segments` x `segments / 2`, the box 12 triangles,
/// the floor a square of side [`FLOOR_SIZE`], the triangle itself.
pub fn tessellate(scene: &Scene, segments: u32) -> Result<Vec<Instance>> {
    let mut instances = Vec::new();
    for object in scene.objects() {
        let mesh = match &object.shape {
            Shape::Sphere(s) => Mesh::uv_sphere(s.centre(), s.radius(), segments, segments / 2)?,
            Shape::Aabb(b) => Mesh::cuboid(b.min(), b.max())?,
            Shape::Plane(p) => Mesh::floor(p.point(), FLOOR_SIZE)?,
            Shape::Triangle(t) => Mesh::new(t.vertices().to_vec(), vec![[0, 1, 2]])?,
            _ => {
                return Err(Error::Io {
                    path: "scene".into(),
                    message: "only spheres, boxes, planes and triangles are tessellated".into(),
                });
            }
        };
        instances.push(Instance::new(mesh, object.colour()));
    }
    Ok(instances)
}
// ANCHOR_END: tessellate

/// Lesson 08's scene, where lesson 08 renders it.
pub fn scene() -> Result<Scene> {
    lesson08::scene(Vec3::ZERO)
}

/// The pinhole camera of lesson 08.
pub fn camera(args: &Args) -> Result<Camera> {
    let lesson08 = lesson08_args(args);
    let [_, pinhole] = lesson08::cameras(&lesson08, Vec3::ZERO)?;
    Ok(pinhole)
}

fn lesson08_args(args: &Args) -> lesson08::Args {
    lesson08::Args {
        width: args.width,
        height: args.height,
        threads: args.threads,
        epsilon: 1e-4,
        far: Vec3::ZERO,
        output: Output {
            out: args.output.out.clone(),
        },
    }
}

// ANCHOR: shadows
/// The part of the scene the light's camera frames: every object and the shadows
/// they throw on the floor.
pub fn shadows(args: &Args, bias: f32) -> Shadows {
    Shadows {
        size: args.shadow_map_size,
        bias,
        centre: Vec3::new(0.0, 0.5, -0.5),
        radius: 6.0,
    }
}
// ANCHOR_END: shadows

/// The torus of `args.mesh`, standing on the floor at the front right of the scene,
/// flat shaded (one normal per triangle, as the ray caster sees triangles).
pub fn mesh_instance(args: &Args) -> Result<Instance> {
    let mesh = Mesh::from_obj(&args.mesh)?.flat_shaded()?;
    let model = Transform::rotation_x(-0.5)?.then(Transform::translation(2.2, 0.75, 1.6)?);
    Ok(Instance {
        mesh,
        model,
        colour: Vec3::new(0.8, 0.55, 0.3),
    })
}

/// The same mesh as a list of triangle primitives for the ray caster.
pub fn mesh_objects(instance: &Instance) -> Result<Vec<Object>> {
    let mut world = instance.mesh.clone();
    for p in &mut world.positions {
        *p = instance.model.point(*p);
    }
    world.objects(instance.colour)
}

/// Every image of the lesson by name, and how long each renderer took.
pub struct Images {
    /// File name and image.
    pub images: Vec<(&'static str, Framebuffer)>,
    /// The silhouette pixels of the lesson-08 scene and of the floor + mesh scene.
    pub silhouettes: [Vec<bool>; 2],
    /// What was timed and how long it took, in seconds.
    pub times: Vec<(String, f64)>,
}

impl Images {
    /// The image called `name`.
    pub fn get(&self, name: &str) -> Option<&Framebuffer> {
        self.images.iter().find(|(n, _)| *n == name).map(|(_, i)| i)
    }
}

fn timed<T>(times: &mut Vec<(String, f64)>, what: &str, work: impl FnOnce() -> T) -> T {
    let start = Instant::now();
    let result = work();
    times.push((what.to_string(), start.elapsed().as_secs_f64()));
    result
}

// ANCHOR: images
/// Renders everything: the ray-cast reference, the rasterized images (per pixel,
/// per vertex), the shadows both ways, and the mesh both ways.
pub fn images(args: &Args) -> Result<Images> {
    let scene = scene()?;
    let camera = camera(args)?;
    let instances = tessellate(&scene, args.segments)?;
    let light = scene.light().ok_or(Error::Invalid {
        param: "scene",
        reason: "lesson 09 needs a point light",
    })?;
    let settings = |shading, shadows| Settings {
        depth: DEPTH,
        shading,
        cull: Cull::None,
        background: scene.background(),
        shadows,
    };
    let raster = |instances: &[Instance], s: Settings| {
        rasterize(instances, &camera, &light, &s, args.threads)
    };
    let t = &mut Vec::new();
    let unshadowed = timed(t, "ray cast, analytic scene", || {
        render(&camera, args.threads, |r| lit_unshadowed(&scene, r))
    })?;
    let per_pixel = timed(t, "rasterized, per-pixel shading", || {
        raster(&instances, settings(Shading::PerPixel, None))
    })?;
    let per_vertex = raster(&instances, settings(Shading::PerVertex, None))?;
    let traced = timed(t, "ray cast with shadow rays", || {
        render(&camera, args.threads, |r| {
            lit(&scene, r, Offset::Scaled)
        })
    })?;
    let mapped = |bias| {
        raster(
            &instances,
            settings(Shading::PerPixel, Some(shadows(args, bias))),
        )
    };
    let shadow_map = timed(t, "rasterized with a shadow map", || mapped(args.bias))?;
    let acne = mapped(0.0)?;
    let peter_pan = mapped(50.0 * args.bias)?;

    let torus = mesh_instance(args)?;
    let mut mesh_scene_objects = vec![scene.objects()[0].clone()];
    mesh_scene_objects.extend(mesh_objects(&torus)?);
    let mesh_scene = Scene::new(mesh_scene_objects, scene.background()).and_then(|s| s.with_light(light))?;
    let mesh_instances = [instances[0].clone(), torus];
    let mesh_cast = timed(t, "ray cast, floor + mesh (brute force)", || {
        render(&camera, args.threads, |r| {
            lit_unshadowed(&mesh_scene, r)
        })
    })?;
    let mesh_raster = timed(t, "rasterized, floor + mesh", || {
        raster(&mesh_instances, settings(Shading::PerPixel, None))
    })?;
    let silhouettes = [
        silhouettes(&scene, &camera, args.threads)?,
        silhouettes(&mesh_scene, &camera, args.threads)?,
    ];
    let difference = difference(&unshadowed, &per_pixel, &silhouettes[0])?;
    Ok(Images {
        images: vec![
            ("09_ray_cast.png", unshadowed.clone()),
            ("09_per_pixel.png", per_pixel.clone()),
            ("09_per_vertex.png", per_vertex.clone()),
            (
                "09_side_by_side.png",
                Framebuffer::beside(&[&unshadowed, &per_pixel, &per_vertex], 8)?,
            ),
            ("09_difference.png", difference),
            (
                "09_shadows.png",
                Framebuffer::beside(&[&traced, &shadow_map], 8)?,
            ),
            (
                "09_shadow_bias.png",
                Framebuffer::beside(&[&acne, &peter_pan], 8)?,
            ),
            ("09_shadow_ray.png", traced),
            ("09_shadow_map.png", shadow_map),
            ("09_shadow_map_acne.png", acne),
            ("09_shadow_map_peter_pan.png", peter_pan),
            (
                "09_mesh.png",
                Framebuffer::beside(&[&mesh_cast, &mesh_raster], 8)?,
            ),
            ("09_mesh_ray_cast.png", mesh_cast),
            ("09_mesh_raster.png", mesh_raster),
        ],
        silhouettes,
        times: std::mem::take(t),
    })
}
// ANCHOR_END: images

// ANCHOR: silhouettes
/// The pixels next to a silhouette: where the object the ray caster sees differs
/// from what it sees at one of the 8 neighbouring pixels. There the tessellated
/// outline and the true one may fall on different sides of a pixel centre, so
/// the comparison leaves these pixels out.
pub fn silhouettes(scene: &Scene, camera: &Camera, threads: Option<usize>) -> Result<Vec<bool>> {
    // An image of object numbers (the background is one more), cast in parallel.
    let ids = render(camera, threads, |r| {
        let hit = scene.closest_hit(r, 0.0, f32::INFINITY);
        let index = hit.and_then(|(_, o)| scene.objects().iter().position(|p| std::ptr::eq(p, o)));
        Vec3::splat(index.unwrap_or(scene.objects().len()) as f32)
    })?;
    let (w, h) = (ids.width() as i64, ids.height() as i64);
    let id = |x: i64, y: i64| ids.get(x.clamp(0, w - 1) as u32, y.clamp(0, h - 1) as u32);
    Ok((0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| (-1..=1).any(|dy| (-1..=1).any(|dx| id(x + dx, y + dy) != id(x, y))))
        .collect())
}
// ANCHOR_END: silhouettes

/// |a - b| magnified 10 times, with silhouette pixels marked in grey.
pub fn difference(a: &Framebuffer, b: &Framebuffer, silhouette: &[bool]) -> Result<Framebuffer> {
    Framebuffer::from_fn(a.width(), a.height(), |x, y| {
        if silhouette[(y * a.width() + x) as usize] {
            return Vec3::splat(0.2);
        }
        let (pa, pb) = (
            a.get(x, y).unwrap_or(Vec3::ZERO),
            b.get(x, y).unwrap_or(Vec3::ZERO),
        );
        ((pa - pb).abs() * 10.0).min(Vec3::ONE)
    })
}

/// How two images compare away from silhouettes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Agreement {
    /// Pixels compared (all but the silhouettes).
    pub compared: u32,
    /// Pixels left out as silhouettes.
    pub silhouette: u32,
    /// Compared pixels differing by more than [`TOLERANCE`].
    pub differing: u32,
    /// The largest difference of a compared pixel, in some channel.
    pub max_difference: f32,
}

impl Agreement {
    /// The share of compared pixels that agree, in percent.
    pub fn percent_agreeing(&self) -> f64 {
        100.0 * (self.compared - self.differing) as f64 / self.compared.max(1) as f64
    }
}

// ANCHOR: agreement
/// Compares `a` and `b` pixel by pixel, skipping the `silhouette` pixels.
pub fn agreement(a: &Framebuffer, b: &Framebuffer, silhouette: &[bool]) -> Agreement {
    let mut result = Agreement {
        compared: 0,
        silhouette: 0,
        differing: 0,
        max_difference: 0.0,
    };
    for y in 0..a.height() {
        for x in 0..a.width() {
            if silhouette[(y * a.width() + x) as usize] {
                result.silhouette += 1;
                continue;
            }
            let d = match (a.get(x, y), b.get(x, y)) {
                (Some(pa), Some(pb)) => (pa - pb).abs().max_element(),
                _ => f32::INFINITY,
            };
            result.compared += 1;
            result.max_difference = result.max_difference.max(d);
            if d > TOLERANCE {
                result.differing += 1;
            }
        }
    }
    result
}
// ANCHOR_END: agreement

/// The lesson's tables: triangle counts, and how far each rasterized image is from
/// its ray-cast counterpart. No timings: they go to the terminal only.
pub fn numbers(args: &Args, images: &Images) -> Result<String> {
    let scene = scene()?;
    let instances = tessellate(&scene, args.segments)?;
    let torus = mesh_instance(args)?;
    let names = [
        "floor",
        "red sphere",
        "blue sphere",
        "green sphere",
        "box",
        "triangle",
    ];
    let mut counts = Table::new(
        "The scene as triangles",
        &["object", "vertices", "triangles"],
    );
    let mut total = 0;
    for (name, i) in names.iter().zip(&instances) {
        total += i.mesh.triangles.len();
        counts.row(vec![
            name.to_string(),
            i.mesh.positions.len().to_string(),
            i.mesh.triangles.len().to_string(),
        ]);
    }
    counts.row(vec!["all".into(), String::new(), total.to_string()]);
    counts.row(vec![
        "mesh (torus.obj, flat)".into(),
        torus.mesh.positions.len().to_string(),
        torus.mesh.triangles.len().to_string(),
    ]);

    let image = |name| {
        images.get(name).ok_or(Error::Io {
            path: name.into(),
            message: "not rendered".into(),
        })
    };
    let [mask, mesh_mask] = &images.silhouettes;
    let mut compare = Table::new(
        &format!(
            "Against the ray caster, {} x {} pixels, away from silhouettes (more than {}/255 apart in a channel counts as different)",
            args.width,
            args.height,
            num(f64::from(TOLERANCE * 255.0), 0)
        ),
        &[
            "rasterized image",
            "reference",
            "compared",
            "differing",
            "agree",
            "max difference",
        ],
    );
    let rows = [
        ("per-pixel shading", "09_per_pixel.png", "09_ray_cast.png"),
        (
            "per-vertex (Gouraud)",
            "09_per_vertex.png",
            "09_ray_cast.png",
        ),
        (
            "shadow map, bias 0",
            "09_shadow_map_acne.png",
            "09_shadow_ray.png",
        ),
        ("shadow map", "09_shadow_map.png", "09_shadow_ray.png"),
        (
            "shadow map, bias x 50",
            "09_shadow_map_peter_pan.png",
            "09_shadow_ray.png",
        ),
    ];
    for (label, raster, reference) in rows {
        let a = agreement(image(raster)?, image(reference)?, mask);
        compare.row(agreement_row(label, reference, &a));
    }
    let a = agreement(
        image("09_mesh_raster.png")?,
        image("09_mesh_ray_cast.png")?,
        mesh_mask,
    );
    compare.row(agreement_row("floor + mesh", "09_mesh_ray_cast.png", &a));
    Ok(format!("{counts}\n{compare}"))
}

fn agreement_row(label: &str, reference: &str, a: &Agreement) -> Vec<String> {
    vec![
        label.to_string(),
        reference.trim_start_matches("09_").to_string(),
        a.compared.to_string(),
        a.differing.to_string(),
        format!("{}%", num(a.percent_agreeing(), 2)),
        num(f64::from(a.max_difference), 3),
    ]
}

/// The timings, for the terminal only: they differ from run to run and machine to
/// machine, so no test or snapshot sees them.
pub fn timings(images: &Images) -> String {
    let mut table = Table::new("Time on this machine", &["renderer", "seconds"]);
    for (what, seconds) in &images.times {
        table.row(vec![what.clone(), num(*seconds, 3)]);
    }
    table.to_string()
}

// ANCHOR: stages
/// The figure: Lecture 2's pipeline on one triangle, in four panels. The triangle's
/// vertices in the world, the same vertices in clip space divided by w (NDC), the
/// pixel centres the rasterizer finds inside it, and the colours interpolated
/// between its three vertex colours.
pub fn stages() -> Result<Diagram> {
    use render_lessons::camera::{Film, Frame, PinholeCamera};
    let film = Film::new(16, 12, (-0.6, 0.6), (-0.45, 0.45))?;
    let frame = Frame::look(
        Vec3::new(0.0, 1.0, 4.0),
        Vec3::new(0.0, -0.25, -1.0),
        Vec3::Y,
    )?;
    let camera: Camera = PinholeCamera::new(film, 1.0, frame)?.into();
    let pipeline = Pipeline::new(
        &camera,
        DepthRange {
            near: 0.5,
            far: 20.0,
        },
    )?;
    let world = [
        Vec3::new(-1.5, 0.0, 0.5),
        Vec3::new(1.6, 0.2, -0.5),
        Vec3::new(-0.2, 1.7, -1.0),
    ];
    let colours = [Vec3::X, Vec3::Y, Vec3::Z];
    let vertex = |i: usize| ClipVertex {
        clip: pipeline.to_clip(&Transform::IDENTITY, world[i]),
        varyings: Varyings {
            world: world[i],
            normal: Vec3::Z,
            colour: colours[i],
        },
    };
    let screen = [0, 1, 2].map(|i| ScreenVertex::from_clip(&pipeline, &vertex(i)));
    let [Some(a), Some(b), Some(c)] = screen else {
        return Err(Error::NotPositive {
            param: "w of a stage-figure vertex",
            value: 0.0,
        });
    };
    let mut fragments = Vec::new();
    rasterize_triangle(&[a, b, c], Cull::None, 16, 0..12, |f| fragments.push(f));
    stage_panels(&world, &[a, b, c], &fragments)
}
// ANCHOR_END: stages

fn stage_panels(
    world: &[Vec3; 3],
    screen: &[ScreenVertex; 3],
    fragments: &[Fragment],
) -> Result<Diagram> {
    // Four panels side by side in one coordinate system, each 20 units wide; the
    // pixel grid of panels 3 and 4 is 16 x 12 units, row 0 at the top.
    let mut d = Diagram::new(1600, 360, (0.0, 80.0), (-2.0, 16.0))?;
    d.title("One triangle through the pipeline");
    let at = |k: f32, x: f32, y: f32| Vec2::new(20.0 * k + 2.0 + x, 2.0 + y);
    let label =
        |d: &mut Diagram, k: f32, s: &str| d.text(at(k, 8.0, -1.0), s, palette::INK, Place::Below);
    // 1: world (x, y), scaled to fit.
    let w2 = world.map(|v| at(0.0, 5.0 * (v.x + 1.6), 5.0 * (v.y + 0.5)));
    d.outline(&w2, palette::INK, 2.0);
    for (i, p) in w2.iter().enumerate() {
        d.dot(*p, 5.0, palette::INK);
        d.text(*p, &format!("v{i}"), palette::INK, Place::Above);
    }
    label(&mut d, 0.0, "1. three vertices (world x, y)");
    // 2: NDC: the square [-1, 1]^2 drawn 16 x 12.
    let ndc = |x: f32, y: f32| at(1.0, 8.0 + 8.0 * x, 6.0 + 6.0 * y);
    let square = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)].map(|(x, y)| ndc(x, y));
    for i in 0..4 {
        d.dashed(square[i], square[(i + 1) % 4], palette::GRID, 1.0);
    }
    let n2 = screen.map(|v| ndc(v.pixel.x / 8.0 - 1.0, 1.0 - v.pixel.y / 6.0));
    d.outline(&n2, palette::INK, 2.0);
    for p in &n2 {
        d.dot(*p, 5.0, palette::INK);
    }
    label(&mut d, 1.0, "2. P V x, divided by w (NDC)");
    // 3 and 4: the pixel grid and the triangle in pixels.
    let pixel = |k: f32, x: f32, y: f32| at(k, x, 12.0 - y);
    for k in [2.0, 3.0] {
        for x in 0..=16 {
            let x = x as f32;
            d.line(pixel(k, x, 0.0), pixel(k, x, 12.0), palette::GRID, 1.0);
        }
        for y in 0..=12 {
            let y = y as f32;
            d.line(pixel(k, 0.0, y), pixel(k, 16.0, y), palette::GRID, 1.0);
        }
    }
    for f in fragments {
        let (x, y) = (f.x as f32, f.y as f32);
        d.dot(pixel(2.0, x + 0.5, y + 0.5), 4.0, palette::HIT);
        let cell = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
            .map(|(dx, dy)| pixel(3.0, x + dx, y + dy));
        let c = f.varyings.colour;
        let rgb = Rgb(to_srgb8(c.x), to_srgb8(c.y), to_srgb8(c.z));
        d.fill(&cell, rgb, 255);
    }
    for k in [2.0, 3.0] {
        let tri = screen.map(|v| pixel(k, v.pixel.x, v.pixel.y));
        d.outline(&tri, palette::INK, 1.5);
    }
    label(&mut d, 2.0, "3. pixel centres inside (edge functions)");
    label(&mut d, 3.0, "4. colours interpolated (barycentric)");
    Ok(d)
}

fn main() -> ExitCode {
    let args = Args::parse();
    lesson::run(|| {
        let images = images(&args)?;
        lesson::print(&numbers(&args, &images)?);
        lesson::print(&timings(&images));
        for (name, image) in &images.images {
            args.output.image(name, image)?;
        }
        args.output.diagram("09_pipeline_stages.png", &stages()?)
    })
}
