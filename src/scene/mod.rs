//! A scene: a plain list of primitives, each with a material and the light it emits,
//! the background (the radiance a ray that hits nothing sees), and an optional point
//! light. No acceleration structure: every ray is tested against every primitive, as
//! in Appel's ray casting (Lecture 4); lesson 11 measures when that stops paying, and
//! [`BvhScene`] asks the same questions through a tree ([`list_or_tree`] chooses
//! between the two).
//!
//! One type serves every renderer, and each part means the same to all of them; what
//! differs is how much of the scene's light each renderer gathers:
//!
//! | part | ray caster (08), rasterizer (09) | path tracer (10) |
//! |---|---|---|
//! | point light | lights surfaces: rho I cos / d^2 | the same, by shadow rays |
//! | background | seen by rays that miss | seen, and lights surfaces |
//! | emission | not drawn | seen, and lights surfaces |
//! | light between surfaces | the ambient share k_a rho | every bounce |
//!
//! So a matte surface lit by the point light alone, under a black background, is
//! the same in both (less the ray caster's k_a rho) at a path depth of 1; a sky
//! lights the path tracer's surfaces and not the ray caster's, whose ambient term
//! stands in for it and for all other indirect light
//! (`tests/lessons/lesson_10_point_light.rs` checks both).

use std::f32::consts::PI;
use std::sync::Arc;

use glam::Vec3;

use crate::error::{Error, Problem, Result, finite3};
use crate::material::Material;
use crate::ray::{Interval, Ray};
use crate::shapes::{Hit, PreparedRay, Shape, ShapesByKind};
use crate::texture::Texture;

pub mod list_or_tree;
mod tree;

pub use list_or_tree::{BUILD_COST, ListOrTree, TEST_COST, WALK_COST};
pub use tree::BvhScene;

/// One primitive with its material and the radiance L_e it emits.
///
/// Emission is two-sided ([`Object::emitting`]): L_e leaves the surface on both
/// sides, which the furnace seen from inside a sphere needs. A lamp
/// ([`Object::lamp`]) shines from its front only, the side its normal points to,
/// as a ceiling panel does: its back emits nothing. A textured object
/// ([`Object::textured`]) takes its albedo at each point from its texture
/// ([`Object::albedo_at`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// The surface.
    pub shape: Shape,
    /// How it scatters light.
    pub material: Material,
    /// The radiance it emits, linear RGB; zero for most objects.
    pub emission: Vec3,
    /// `true` if it emits from its front side only (a lamp).
    pub front_only: bool,
    /// The texture its diffuse albedo is looked up in, by the texture coordinates of
    /// each hit (a mesh's; every other shape's are 0), or none.
    pub texture: Option<Arc<Texture>>,
}

impl Object {
    /// A surface that does not emit.
    pub fn new(shape: impl Into<Shape>, material: Material) -> Object {
        Object {
            shape: shape.into(),
            material,
            emission: Vec3::ZERO,
            front_only: false,
            texture: None,
        }
    }

    /// A Lambertian surface of colour `albedo` (linear RGB, each channel in [0, 1]):
    /// what the ray caster and the rasterizer paint.
    pub fn diffuse(shape: impl Into<Shape>, albedo: Vec3) -> Object {
        Object::new(shape, Material::Diffuse { albedo })
    }

    /// A Lambertian surface whose albedo at each point is `texture`'s colour at the
    /// point's texture coordinates ([`Object::albedo_at`]); its material's albedo is
    /// the texture's mean ([`Texture::mean`]), for a renderer that looks up no point.
    pub fn textured(shape: impl Into<Shape>, texture: Arc<Texture>) -> Object {
        Object {
            texture: Some(texture.clone()),
            ..Object::diffuse(shape, texture.mean())
        }
    }

    /// A surface that emits `emission` from both sides.
    pub fn emitting(
        shape: impl Into<Shape>,
        material: Material,
        emission: Vec3,
    ) -> Object {
        Object {
            shape: shape.into(),
            material,
            emission,
            front_only: false,
            texture: None,
        }
    }

    /// A lamp: a black surface that emits `emission` from its front side only, the
    /// side its outward normal points to.
    pub fn lamp(shape: impl Into<Shape>, emission: Vec3) -> Object {
        Object {
            shape: shape.into(),
            material: Material::BLACK,
            emission,
            front_only: true,
            texture: None,
        }
    }

    /// The radiance it emits towards a viewer on the `front` side (or the back):
    /// [`Object::emission`], or zero from the back of a lamp.
    pub fn emission_seen(&self, front: bool) -> Vec3 {
        if front || !self.front_only {
            self.emission
        } else {
            Vec3::ZERO
        }
    }

    /// The colour the ray caster paints: the material's albedo
    /// ([`Material::albedo`]).
    pub fn colour(&self) -> Vec3 {
        self.material.albedo()
    }

    // ANCHOR: albedo_at
    /// The albedo at `hit`: the texture's colour at the hit's texture coordinates
    /// ([`Texture::sample`]), or the material's albedo ([`Object::colour`]).
    pub fn albedo_at(&self, hit: &Hit) -> Vec3 {
        match &self.texture {
            Some(texture) => texture.sample(hit.uv),
            None => self.colour(),
        }
    }

    /// The material at `hit`: a diffuse material takes the albedo there
    /// ([`Object::albedo_at`]); mirrors and glass are not textured.
    pub fn material_at(&self, hit: &Hit) -> Material {
        match self.material {
            Material::Diffuse { .. } if self.texture.is_some() => Material::Diffuse {
                albedo: self.albedo_at(hit),
            },
            material => material,
        }
    }
    // ANCHOR_END: albedo_at

    /// `true` if it emits any light.
    pub fn is_emissive(&self) -> bool {
        self.emission != Vec3::ZERO
    }
}

/// The closest hit in a scene: where the ray crosses a surface, and which object
/// that surface belongs to.
///
/// ```
/// use glam::Vec3;
/// use render_lessons::ray::{Interval, Ray};
/// use render_lessons::scene::{Object, Scene};
/// use render_lessons::shapes::Sphere;
///
/// let ball = Sphere::new(Vec3::new(0.0, 0.0, -5.0), 1.0)?;
/// let scene = Scene::new(vec![Object::diffuse(ball, Vec3::ONE)], Vec3::ZERO)?;
/// let ray = Ray::new(Vec3::ZERO, Vec3::NEG_Z)?;
/// let found = scene.closest(&ray, Interval::AHEAD).expect("the ray meets the ball");
/// assert_eq!((found.object, found.hit.t), (0, 4.0));
/// # Ok::<(), render_lessons::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneHit {
    /// Where the ray crosses the surface.
    pub hit: Hit,
    /// The object hit: its index into [`Scene::objects`].
    pub object: usize,
}

/// A point light: all its light leaves one point (lessons 08 to 10).
///
/// Its `intensity` is the lessons' I, with the pi of Lambert's BRDF folded in: a
/// matte surface of albedo rho facing it at a distance d, at an angle theta, sends
/// rho I cos(theta) / d^2 towards the eye. The ray caster paints that (plus its
/// ambient share, [`crate::lighting::lambert`]); the path tracer gets the same from
/// the rendering equation with f_r = rho / pi and the light's radiant intensity
/// pi I ([`PointLight::radiant_intensity`]), in every sampling strategy.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLight {
    /// Where it is.
    pub position: Vec3,
    /// Its colour and strength, linear RGB: the radiant intensity divided by pi.
    pub intensity: Vec3,
}

impl PointLight {
    /// A light at `position` of `intensity`; [`Scene::with_light`] checks both.
    pub fn new(position: Vec3, intensity: Vec3) -> PointLight {
        PointLight {
            position,
            intensity,
        }
    }

    /// The power it sends per unit solid angle, the same in every direction: pi
    /// [`PointLight::intensity`] (a white surface of f_r = 1 / pi facing it head on
    /// at distance d reflects I / d^2, what lesson 08 paints).
    pub fn radiant_intensity(&self) -> Vec3 {
        PI * self.intensity
    }
}

/// Objects, the emitting ones among them, what escaping rays see, and an optional
/// point light.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    objects: Vec<Object>,
    /// The objects' shapes again, in runs of one kind: what the closest-hit loop
    /// walks ([`Scene::closest`]).
    by_kind: ShapesByKind,
    emitters: Vec<usize>,
    background: Vec3,
    point_light: Option<PointLight>,
}

/// `v` if finite and not negative in any channel.
fn check_radiance(param: &'static str, v: Vec3) -> Result<Vec3> {
    let v = finite3(param, v)?;
    if v.min_element() >= 0.0 {
        Ok(v)
    } else {
        Err(Error::Value {
            param,
            problem: Problem::Invalid {
                reason: "must not be negative",
            },
        })
    }
}

impl Scene {
    /// A scene of `objects` under `background`, a uniform sky: the radiance
    /// (linear RGB) arriving along every ray that hits nothing. Every renderer shows
    /// it where a camera ray meets nothing; only the path tracer is also lit by it
    /// (see the module's table). No point light: add one with [`Scene::with_light`].
    ///
    /// Rejects NaN, infinite or negative emission and background, materials that
    /// fail [`Material::check`], and emission on any shape but a sphere or a quad:
    /// every emitter must be a light that next event estimation can sample, or its
    /// light would be missed.
    pub fn new(objects: Vec<Object>, background: Vec3) -> Result<Scene> {
        let mut emitters = Vec::new();
        for (i, o) in objects.iter().enumerate() {
            check_radiance("emission", o.emission)?;
            o.material.check()?;
            if o.is_emissive() {
                if !matches!(o.shape, Shape::Sphere(_) | Shape::Quad(_)) {
                    return Err(Error::Value {
                        param: "emission",
                        problem: Problem::Invalid {
                            reason: "is only allowed on spheres and quads (the lights we can sample)",
                        },
                    });
                }
                emitters.push(i);
            }
        }
        Ok(Scene {
            by_kind: ShapesByKind::new(objects.iter().map(|o| &o.shape)),
            objects,
            emitters,
            background: check_radiance("background", background)?,
            point_light: None,
        })
    }

    /// The same scene lit by the point `light`, in every renderer.
    pub fn with_light(self, light: PointLight) -> Result<Scene> {
        finite3("light position", light.position)?;
        check_radiance("light intensity", light.intensity)?;
        Ok(Scene {
            point_light: Some(light),
            ..self
        })
    }

    /// The primitives.
    pub fn objects(&self) -> &[Object] {
        &self.objects
    }

    /// The object a hit found: [`SceneHit::object`] looked up in [`Scene::objects`].
    pub fn object(&self, found: &SceneHit) -> &Object {
        &self.objects[found.object]
    }

    /// The indices (into [`Scene::objects`]) of the emissive objects.
    pub fn emitters(&self) -> &[usize] {
        &self.emitters
    }

    /// The radiance of rays that hit nothing, the uniform sky ([`Scene::new`]).
    pub fn background(&self) -> Vec3 {
        self.background
    }

    /// The point light, if the scene has one.
    pub fn point_light(&self) -> Option<PointLight> {
        self.point_light
    }

    // ANCHOR: closest_hit
    /// The closest crossing in `range` over every primitive, and the object it
    /// belongs to: the inner loop of the lecture's ray casting algorithm, shared by
    /// every renderer. Every object is asked in the list's order, and each hit found
    /// shrinks `range.max`, so later ones only count if nearer; on a tie the first
    /// object wins.
    ///
    /// The loop runs over the shapes as [`ShapesByKind`] stores them, in runs of one
    /// kind, so that one test serves a whole run; it asks each primitive only for its
    /// [`crate::shapes::Candidate`] (`t` and a few numbers), and the point and normal
    /// are computed once, for the winner.
    pub fn closest(&self, ray: &Ray, range: Interval) -> Option<SceneHit> {
        let prepared = PreparedRay::new(ray);
        let (candidate, object) = self.by_kind.closest(&prepared, range)?;
        let hit = self.objects[object].shape.record(&prepared, candidate);
        Some(SceneHit { hit, object })
    }

    /// The object [`Scene::closest`] finds, without building its hit record: all
    /// that shadowless ray casting needs.
    pub fn closest_object(&self, ray: &Ray, range: Interval) -> Option<usize> {
        self.by_kind.closest_index(&PreparedRay::new(ray), range)
    }
    // ANCHOR_END: closest_hit

    /// True if anything lies on the ray within `range` (a shadow ray's question).
    pub fn occluded(&self, ray: &Ray, range: Interval) -> bool {
        self.by_kind.any(&PreparedRay::new(ray), range)
    }
}

// ANCHOR: intersect
/// What every renderer asks of a scene (pbrt's `Intersect` and `IntersectP`): the
/// closest hit on a ray, and whether anything lies on it. The plain list,
/// [`Scene`], answers by testing every object; lesson 11's tree (`BvhScene`) gives
/// the same answers, faster once the scene is big. The ray caster, the path tracer
/// and the rasterizer's reference take either.
pub trait Intersect: Sync {
    /// The scene: its objects, lights and background.
    fn scene(&self) -> &Scene;

    /// The closest hit within `range`, and its object; on a tie (equal `t`), the
    /// object listed first.
    fn closest(&self, ray: &Ray, range: Interval) -> Option<SceneHit>;

    /// The index (into [`Scene::objects`]) of the object [`Intersect::closest`]
    /// finds, for a renderer that needs no more (shadowless ray casting); the
    /// scene's list answers it without building the hit record.
    fn closest_object(&self, ray: &Ray, range: Interval) -> Option<usize> {
        self.closest(ray, range).map(|found| found.object)
    }

    /// True if anything lies on the ray within `range` (a shadow ray's question).
    fn occluded(&self, ray: &Ray, range: Interval) -> bool;

    /// The object a hit found ([`Scene::object`]).
    fn object(&self, found: &SceneHit) -> &Object {
        self.scene().object(found)
    }

    /// The scene's primitives ([`Scene::objects`]).
    fn objects(&self) -> &[Object] {
        self.scene().objects()
    }

    /// The emitters' indices ([`Scene::emitters`]).
    fn emitters(&self) -> &[usize] {
        self.scene().emitters()
    }

    /// What rays that hit nothing see ([`Scene::background`]).
    fn background(&self) -> Vec3 {
        self.scene().background()
    }

    /// The point light, if any ([`Scene::point_light`]).
    fn point_light(&self) -> Option<PointLight> {
        self.scene().point_light()
    }
}
// ANCHOR_END: intersect

/// The plain list: every object tested for every ray ([`Scene::closest`]).
impl Intersect for Scene {
    fn scene(&self) -> &Scene {
        self
    }

    fn closest(&self, ray: &Ray, range: Interval) -> Option<SceneHit> {
        Scene::closest(self, ray, range)
    }

    fn closest_object(&self, ray: &Ray, range: Interval) -> Option<usize> {
        Scene::closest_object(self, ray, range)
    }

    fn occluded(&self, ray: &Ray, range: Interval) -> bool {
        Scene::occluded(self, ray, range)
    }
}
