//! Lesson 09, shading, the shadow map and the comparison with ray casting (chapters
//! 09_4 to 09_6): the unshadowed rasterizer is Lambert where nothing blocks the light,
//! the ray-cast reference and its silhouettes, the shadow map's occlusion and its bias
//! (acne against detached shadows), and the same image on any number of threads.

use crate::lesson_09_rasterization::{DEPTH, pinhole};

use render_lessons::ray::Interval;

use glam::Vec3;
use render_lessons::camera::Camera;
use render_lessons::course::compare::reference;
use render_lessons::mesh::{Mesh, Model};
use render_lessons::raster::{RasterSettings, ShadowMap, Shadows, rasterize};
use render_lessons::render::with_threads;
use render_lessons::scene::PointLight;
use render_lessons::scenes::{still_life, still_life_pinhole};

#[test]
fn the_reference_is_the_unshadowed_ray_cast_and_its_silhouettes_are_where_objects_change()
 {
    // One pass gives what two passes gave: the colours of lit_unshadowed, bit for bit,
    // and a silhouette flag wherever one of the 8 neighbours sees another object.
    use render_lessons::raycast::lit_unshadowed;
    use render_lessons::render::render;
    let scene = still_life(Vec3::ZERO).unwrap();
    let camera = still_life_pinhole(96, 54).unwrap();
    let one_pass = reference(&scene, &camera).unwrap();
    let colours = render(&camera, |r| lit_unshadowed(&scene, r)).unwrap();
    assert_eq!(one_pass.image, colours);
    let id = |x: i64, y: i64| {
        let ray = camera.ray(x.clamp(0, 95) as u32, y.clamp(0, 53) as u32);
        scene
            .closest(&ray, Interval::AHEAD)
            .map(|found| found.object)
    };
    let mut flagged = 0;
    for y in 0..54i64 {
        for x in 0..96i64 {
            let edge =
                (-1..=1).any(|dy| (-1..=1).any(|dx| id(x + dx, y + dy) != id(x, y)));
            assert_eq!(
                one_pass.silhouettes[(y * 96 + x) as usize],
                edge,
                "({x}, {y})"
            );
            flagged += usize::from(edge);
        }
    }
    assert!(flagged > 0 && flagged * 5 < 96 * 54, "{flagged}");
}

#[test]
fn unshadowed_lambert_is_lambert_where_nothing_blocks_the_light() {
    use render_lessons::raycast::{lit, lit_unshadowed};
    use render_lessons::spawn::Offset;
    let scene = still_life(Vec3::ZERO).unwrap();
    let camera = still_life_pinhole(96, 54).unwrap();
    let (mut same, mut shadowed) = (0, 0);
    for y in 0..54 {
        for x in 0..96 {
            let ray = camera.ray(x, y);
            let open = lit_unshadowed(&scene, &ray);
            let traced = lit(&scene, &ray, Offset::Scaled);
            if open == traced {
                same += 1;
            } else {
                // A shadow only ever removes light.
                assert!(traced.cmple(open).all(), "({x}, {y}): {traced} > {open}");
                shadowed += 1;
            }
        }
    }
    assert!(same > 4 * shadowed && shadowed > 0, "{same} {shadowed}");
}

fn floor_and_blocker() -> Vec<Model> {
    vec![
        Model::new(Mesh::floor(Vec3::ZERO, 20.0).unwrap(), Vec3::ONE),
        Model::new(
            Mesh::cuboid(Vec3::new(-1.0, 2.0, -1.0), Vec3::new(1.0, 2.5, 1.0)).unwrap(),
            Vec3::ONE,
        ),
    ]
}

const OVERHEAD: PointLight = PointLight {
    position: Vec3::new(0.0, 8.0, 0.5),
    intensity: Vec3::splat(50.0),
};

fn shadows(bias: f32) -> Shadows {
    Shadows {
        size: 256,
        bias,
        centre: Vec3::ZERO,
        radius: 6.0,
    }
}

#[test]
fn shadow_map_shadows_what_is_under_an_occluder() {
    let map = ShadowMap::build(&floor_and_blocker(), &OVERHEAD, &shadows(1.0)).unwrap();
    // The light is straight above: under the slab is dark, beside it is lit.
    assert!(!map.lit(Vec3::new(0.0, 0.0, 0.0), Vec3::Y));
    assert!(!map.lit(Vec3::new(0.6, 0.0, -0.6), Vec3::Y));
    assert!(map.lit(Vec3::new(3.0, 0.0, 0.0), Vec3::Y));
    assert!(map.lit(Vec3::new(-2.5, 0.0, 3.0), Vec3::Y));
    // The slab's own top is lit, and so is a point outside the map.
    assert!(map.lit(Vec3::new(0.2, 2.5, 0.2), Vec3::Y));
    assert!(map.lit(Vec3::new(50.0, 0.0, 0.0), Vec3::Y));
    // The map recorded the slab's top straight below the light: 8 - 2.5 = 5.5 away.
    let centre = map.size() / 2;
    let d = map.distance(centre, centre).unwrap();
    assert!((d - 5.5).abs() < 0.05, "{d}");
}

#[test]
fn shadow_map_bias_trades_acne_for_detached_shadows() {
    // A floor lit at a slant, nothing above it: every point should be lit.
    let light = PointLight {
        position: Vec3::new(6.0, 3.0, 0.0),
        intensity: Vec3::splat(50.0),
    };
    let floor = [Model::new(
        Mesh::floor(Vec3::ZERO, 20.0).unwrap(),
        Vec3::ONE,
    )];
    let dark = |bias| {
        let map = ShadowMap::build(&floor, &light, &shadows(bias)).unwrap();
        let points = (0..40).flat_map(|i| (0..40).map(move |j| (i, j)));
        points
            .filter(|&(i, j)| {
                let p = Vec3::new(-4.0 + 0.2 * i as f32, 0.0, -4.0 + 0.2 * j as f32);
                !map.lit(p, Vec3::Y)
            })
            .count()
    };
    // No bias: the floor shadows itself in a pattern of stripes (acne).
    assert!(dark(0.0) > 100, "{}", dark(0.0));
    // One texel footprint, scaled by the slope: none.
    assert_eq!(dark(1.0), 0);
}

#[test]
fn shadow_map_bad_input_names_the_parameter() {
    let instances = floor_and_blocker();
    let build = |s: Shadows| ShadowMap::build(&instances, &OVERHEAD, &s).unwrap_err();
    assert_eq!(build(shadows(-1.0)).param(), "shadow bias");
    assert_eq!(build(shadows(f32::NAN)).param(), "shadow bias");
    assert_eq!(
        build(Shadows {
            radius: 0.0,
            ..shadows(1.0)
        })
        .param(),
        "shadow radius"
    );
    assert_eq!(
        build(Shadows {
            size: 0,
            ..shadows(1.0)
        })
        .param(),
        "shadow map size"
    );
    let too_close = Shadows {
        radius: 9.0,
        ..shadows(1.0)
    };
    assert!(build(too_close).to_string().contains("shadow radius"));
}

#[test]
fn shadowed_rasterization_is_the_same_on_any_number_of_threads() {
    let camera: Camera = pinhole().into();
    let settings = RasterSettings {
        depth: DEPTH,
        shadows: Some(shadows(1.0)),
        ..RasterSettings::default()
    };
    let draw = |threads| {
        with_threads(threads, || {
            rasterize(&floor_and_blocker(), &camera, &OVERHEAD, &settings)
        })
    };
    assert_eq!(draw(Some(1)).unwrap(), draw(Some(2)).unwrap());
}

#[test]
fn images_side_by_side() {
    use render_lessons::framebuffer::Framebuffer;
    let a = Framebuffer::from_fn(3, 2, |_, _| Vec3::X).unwrap();
    let b = Framebuffer::from_fn(2, 1, |_, _| Vec3::Z).unwrap();
    let both = Framebuffer::beside(&[&a, &b], 1).unwrap();
    assert_eq!((both.width(), both.height()), (6, 2));
    assert_eq!(both.get(2, 1), Some(Vec3::X));
    assert_eq!(both.get(3, 0), Some(Vec3::ONE), "the gap is white");
    assert_eq!(both.get(4, 0), Some(Vec3::Z));
    assert_eq!(
        both.get(5, 1),
        Some(Vec3::ONE),
        "below the shorter image: white"
    );
}
