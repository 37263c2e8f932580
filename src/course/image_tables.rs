//! Tables that describe rendered images (lessons 08 and 09 print them): how many
//! pixels show each object, how many pixels differ from a reference image, the
//! colour at a few named spots, and how well rasterized images agree with ray-cast
//! ones.

use glam::Vec3;

use crate::camera::Camera;
use crate::course::compare::{Agreement, agreement};
use crate::course::report::{Table, num, vec3};
use crate::framebuffer::Framebuffer;
use crate::ray::Interval;
use crate::scene::Scene;

/// How many pixels of `camera`'s image show each object of `scene` (in scene
/// order), then the background: the object of the closest hit of each pixel's ray.
pub fn coverage(scene: &Scene, camera: &Camera) -> Vec<u32> {
    let (w, h) = (camera.film().width(), camera.film().height());
    let mut counts = vec![0u32; scene.objects().len() + 1];
    for (x, y) in (0..h).flat_map(|y| (0..w).map(move |x| (x, y))) {
        let hit = scene.closest(&camera.ray(x, y), Interval::AHEAD);
        counts[hit.map_or(scene.objects().len(), |found| found.object)] += 1;
    }
    counts
}

/// A table of [`coverage`]: one row per object of `scene`, named by `names` (then
/// "background"), one column per camera, headed by its name.
pub fn coverage_table(
    title: &str,
    scene: &Scene,
    names: &[&str],
    cameras: &[(&str, &Camera)],
) -> Table {
    let header: Vec<&str> = ["primitive"]
        .into_iter()
        .chain(cameras.iter().map(|(name, _)| *name))
        .collect();
    let mut table = Table::new(title, &header);
    let counts: Vec<Vec<u32>> =
        cameras.iter().map(|(_, c)| coverage(scene, c)).collect();
    for (i, name) in names.iter().chain(&["background"]).enumerate() {
        let cells = counts.iter().map(|column| column[i].to_string());
        table.row([name.to_string()].into_iter().chain(cells).collect());
    }
    table
}

/// A table of the pixels of each labelled image that differ from `reference` by more
/// than 2/255 in a channel: the count and the share of the image. `what` heads the
/// column of labels.
pub fn differing_table(
    title: &str,
    what: &str,
    reference: &Framebuffer,
    images: &[(String, &Framebuffer)],
) -> Table {
    let mut table = Table::new(title, &[what, "pixels", "share"]);
    let total = f64::from(reference.width()) * f64::from(reference.height());
    for (label, image) in images {
        let differing = agreement(image, reference, &[], 2.0 / 255.0).differing;
        let share = format!("{}%", num(100.0 * f64::from(differing) / total, 2));
        table.row(vec![label.clone(), differing.to_string(), share]);
    }
    table
}

/// A table of the linear colour of `image` at a few named spots, each given as
/// fractions of the width and height.
pub fn spots_table(
    title: &str,
    image: &Framebuffer,
    spots: &[(&str, f32, f32)],
) -> Table {
    let mut table = Table::new(title, &["where", "pixel", "colour"]);
    let (width, height) = (image.width() as f32, image.height() as f32);
    for &(name, fx, fy) in spots {
        let (x, y) = ((fx * width) as u32, (fy * height) as u32);
        let colour = vec3(image.get(x, y).unwrap_or(Vec3::ZERO), 4);
        table.row(vec![name.to_string(), format!("({x}, {y})"), colour]);
    }
    table
}

/// A table of rasterized images against their references (label, reference name,
/// [`Agreement`]), `width` x `height` pixels compared away from silhouettes: a pixel
/// more than `tolerance` apart in a channel counts as different.
pub fn agreement_table(
    (width, height): (u32, u32),
    tolerance: f32,
    rows: &[(&str, &str, Agreement)],
) -> Table {
    let tolerance = num(f64::from(tolerance * 255.0), 0);
    let title = format!(
        "Against the ray caster, {width} x {height} pixels, away from silhouettes\n(more than {tolerance}/255 apart in a channel counts as different)"
    );
    let mut columns = vec!["rasterized image", "reference", "compared"];
    columns.extend(["differing", "agree", "max difference"]);
    let mut table = Table::new(&title, &columns);
    for (label, reference, a) in rows {
        table.row(vec![
            label.to_string(),
            reference.to_string(),
            a.compared.to_string(),
            a.differing.to_string(),
            format!("{}%", num(a.percent_agreeing(), 2)),
            num(f64::from(a.max_difference), 3),
        ]);
    }
    table
}
