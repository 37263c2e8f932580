//! Lesson 09: the rasterization pipeline of Lecture 2, side by side with ray casting.
//!
//! Lesson 08's scene drawn triangle by triangle (the spheres become meshes, the
//! infinite floor a large square) and compared with the ray caster's image of the
//! true scene. The lecture's claim, measured: rasterization is fast but not realistic;
//! it has no shadows until a second trick (a shadow map) adds them, with artefacts.
//!
//!     cargo run --release --example 09_rasterization
//!     cargo run --release --example 09_rasterization -- --mesh assets/meshes/teapot.obj
//!     cargo run --release --example 09_rasterization -- --mesh assets/meshes/teapot.obj --subdivide 4
//!     cargo run --release --example 09_rasterization -- --mesh head.obj --texture head_diffuse.tga

use std::{path::PathBuf, process::ExitCode};

use clap::Parser;
use glam::Vec3;
use render_lessons::course::compare::{
    Agreement, TOLERANCE, agreement, difference, reference,
};
use render_lessons::course::lesson::{self, ImageFlags, Output};
use render_lessons::course::{
    image_tables::agreement_table, parsers, report::Timings,
    triangle_table::triangle_table,
};
use render_lessons::mesh::{Model, check_segments, tessellate};
use render_lessons::raster::Shading::{PerPixel, PerVertex};
use render_lessons::raster::{Shadows, floor_settings, point_light, rasterize};
use render_lessons::scenes::{
    PlacedMesh, STILL_LIFE_OBJECTS, TORUS_OBJ, Up, floor_and_mesh, mesh_on_the_floor,
    still_life, still_life_pinhole, still_life_shadows,
};
use render_lessons::{Result, camera::Camera, lesson_images, render::render};
use render_lessons::{raycast::lit, scene::Scene, spawn::Offset};

fn main() -> ExitCode {
    let args = lesson::parse::<Args>();
    // The images it keeps, and as many again while it works (z-buffers, shadows).
    args.image.run(2 * Images::COUNT, |(width, height)| {
        let scene = still_life(Vec3::ZERO)?;
        let camera = still_life_pinhole(width, height)?;
        check_segments(&scene, args.segments)?;
        let shadows = still_life_shadows(args.shadow_map_size, args.bias);
        let mesh = mesh_on_the_floor(&args.mesh, args.up, args.subdivide, &camera)
            .map_err(lesson::flag("--mesh"))?;
        let texture = args.texture.as_deref();
        let mesh = mesh.textured(texture).map_err(lesson::flag("--texture"))?;
        let lesson = images(&scene, &camera, args.segments, shadows, &mesh.model)?;
        let file = args.mesh.file_name().unwrap_or_default().to_string_lossy();
        lesson::print(&numbers(&scene, args.segments, (&mesh, &file), &lesson)?);
        lesson::print(&lesson.times.table().to_string()); // the terminal only
        Ok(args.output.images(lesson.images.named())?)
    })
}

// ANCHOR: images
/// Lecture 2's pipeline beside the ray caster: the scene ray cast (the reference); as
/// triangles (spheres of `segments` slices), lit, transformed, clipped, rasterized
/// and shaded per pixel and per vertex; shadows both ways (the map with its bias,
/// none, 50 times too much); the floor with `mesh` both ways.
pub fn images(
    scene: &Scene,
    camera: &Camera,
    segments: u32,
    shadows: Shadows,
    mesh: &Model,
) -> Result<Lesson> {
    let mut t = Timings::default();
    let ray_cast = t.time("ray cast, analytic scene", || reference(scene, camera))?;

    let models = tessellate(scene, segments)?; // modeling: vertex and triangle lists
    let light = point_light(scene)?; // lighting
    let pipeline = |models: &[Model], shading, shadows| {
        let settings = floor_settings(scene).with(shading, shadows);
        rasterize(models, camera, &light, &settings) // transform ... shading
    };
    let per_pixel = t.time("rasterized, per-pixel shading", || {
        pipeline(&models, PerPixel, None)
    })?;
    let per_vertex = pipeline(&models, PerVertex, None)?;
    let difference = difference(&ray_cast.image, &per_pixel, &ray_cast.silhouettes)?;

    let shadow_ray = t.time("ray cast with shadow rays", || {
        render(camera, |r| lit(scene, r, Offset::Scaled))
    })?;
    let mapped = |bias| pipeline(&models, PerPixel, Some(shadows.with_bias(bias)));
    let shadow_map = t.time("rasterized with a shadow map", || mapped(shadows.bias))?;
    let (acne, peter_pan) = (mapped(0.0)?, mapped(50.0 * shadows.bias)?);

    let both = floor_and_mesh(scene, mesh)?; // the mesh as one shape, with its tree
    let meshed = t.time("ray cast, floor + mesh", || reference(&both, camera))?;
    drop(both); // a big mesh: the ray caster's copy goes, the rasterizer's comes
    let floor_and_mesh_models = [models[0].clone(), mesh.clone()];
    let mesh_raster = t.time("rasterized, floor + mesh", || {
        pipeline(&floor_and_mesh_models, PerPixel, None)
    })?;

    // Each rasterized image against its ray-cast counterpart, away from silhouettes.
    let mask = &ray_cast.silhouettes;
    let cast = ("ray_cast.png", &ray_cast.image, mask);
    let traced = ("shadow_ray.png", &shadow_ray, mask);
    let mesh = ("mesh_ray_cast.png", &meshed.image, &meshed.silhouettes);
    let agreements = [
        ("per-pixel shading", &per_pixel, cast),
        ("per-vertex (Gouraud)", &per_vertex, cast),
        ("shadow map, bias 0", &acne, traced),
        ("shadow map", &shadow_map, traced),
        ("shadow map, bias x 50", &peter_pan, traced),
        ("floor + mesh", &mesh_raster, mesh),
    ]
    .map(|(label, a, (name, b, mask))| (label, name, agreement(a, b, mask, TOLERANCE)));
    let images = Images {
        ray_cast: ray_cast.image,
        per_pixel,
        per_vertex,
        difference,
        shadow_ray,
        shadow_map,
        shadow_map_acne: acne,
        shadow_map_peter_pan: peter_pan,
        mesh_ray_cast: meshed.image,
        mesh_raster,
    };
    Ok(Lesson {
        images,
        agreements,
        times: t,
    })
}
// ANCHOR_END: images

/// The images; each rasterized one against its reference; each renderer's time.
pub struct Lesson {
    pub images: Images,
    pub agreements: [(&'static str, &'static str, Agreement); 6],
    pub times: Timings,
}

lesson_images! {
    /// The lesson's images, each beside the file it is saved as.
    Images {
        ray_cast: "09_ray_cast.png",
        per_pixel: "09_per_pixel.png",
        per_vertex: "09_per_vertex.png",
        difference: "09_difference.png",
        shadow_ray: "09_shadow_ray.png",
        shadow_map: "09_shadow_map.png",
        shadow_map_acne: "09_shadow_map_acne.png",
        shadow_map_peter_pan: "09_shadow_map_peter_pan.png",
        mesh_ray_cast: "09_mesh_ray_cast.png",
        mesh_raster: "09_mesh_raster.png",
    }
}

/// The lesson's tables: the scene as triangles, the agreements (no timings).
pub fn numbers(
    scene: &Scene,
    segments: u32,
    (mesh, file): (&PlacedMesh, &str),
    lesson: &Lesson,
) -> Result<String> {
    let models = tessellate(scene, segments)?;
    let counts = triangle_table(&STILL_LIFE_OBJECTS, &models, mesh, file);
    let reference = &lesson.images.ray_cast;
    let size = (reference.width(), reference.height());
    let compare = agreement_table(size, TOLERANCE, &lesson.agreements);
    Ok(format!("{counts}\n{compare}"))
}

/// The lesson's parameters; every one has a default that reproduces the book.
#[derive(Parser, Debug)]
#[command(about = "Lesson 09: the rasterization pipeline beside ray casting")]
#[command(allow_negative_numbers = true)]
pub struct Args {
    #[command(flatten)]
    image: ImageFlags,
    /// Slices of longitude of each tessellated sphere (bands of latitude: half).
    #[arg(long, default_value_t = 64)]
    segments: u32,
    /// Texels along each side of the shadow map.
    #[arg(long, default_value_t = 1024)]
    shadow_map_size: u32,
    /// The shadow map's bias, in texel footprints (0 or more).
    #[arg(long, default_value = "1", value_parser = parsers::non_negative)]
    bias: f32,
    /// The mesh both renderers draw (Wavefront OBJ; larger faces become triangles).
    #[arg(long, default_value = TORUS_OBJ)]
    mesh: PathBuf,
    /// An image (PNG or TGA) the mesh is textured with, by its vt coordinates.
    #[arg(long)]
    texture: Option<PathBuf>,
    /// The axis that points up in the mesh's file.
    #[arg(long, value_enum, default_value_t = Up::Y)]
    pub up: Up,
    /// Split each triangle in four this many times (4: a million-triangle teapot).
    #[arg(long, default_value_t = 0)]
    subdivide: u32,
    #[command(flatten)]
    output: Output,
}
