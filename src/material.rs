//! How a surface scatters light: the f_r of the rendering equation (Lecture 2,
//! Kajiya 1986) for the three materials the path tracer's scenes need.
//!
//! - `Diffuse`: Lambert's law, f_r = albedo / pi, the same in every direction.
//! - `Mirror`: a perfect mirror; f_r is a Dirac delta around the reflected direction.
//! - `Glass`: a smooth dielectric (no absorption): reflects with the exact Fresnel
//!   probability F, refracts (Snell's law) with probability 1 - F.
//!
//! The two specular materials cannot be evaluated for a given pair of directions,
//! only sampled; the estimator therefore never aims light samples at them.

use std::f32::consts::PI;

use glam::Vec3;

use crate::error::{Error, Problem, Result, finite3, positive};

/// A surface's scattering.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Material {
    /// Lambertian: f_r = albedo / pi.
    Diffuse {
        /// The fraction of light reflected, per channel.
        albedo: Vec3,
    },
    /// A perfect mirror reflecting the fraction `reflectance` of the light.
    Mirror {
        /// The fraction of light reflected, per channel.
        reflectance: Vec3,
    },
    /// A smooth dielectric with index of refraction `ior` (outside: 1, vacuum/air).
    Glass {
        /// The index of refraction inside.
        ior: f32,
    },
}

/// `v` if every component lies in [0, 1]: more would create energy.
fn fraction3(param: &'static str, v: Vec3) -> Result<Vec3> {
    let v = finite3(param, v)?;
    if v.min_element() >= 0.0 && v.max_element() <= 1.0 {
        Ok(v)
    } else {
        Err(Error::Value {
            param,
            problem: Problem::Invalid {
                reason: "must lie between 0 and 1 in every channel",
            },
        })
    }
}

impl Material {
    /// A Lambertian surface; rejects an albedo outside [0, 1].
    pub fn diffuse(albedo: Vec3) -> Result<Material> {
        Ok(Material::Diffuse {
            albedo: fraction3("albedo", albedo)?,
        })
    }

    /// A mirror; rejects a reflectance outside [0, 1].
    pub fn mirror(reflectance: Vec3) -> Result<Material> {
        Ok(Material::Mirror {
            reflectance: fraction3("reflectance", reflectance)?,
        })
    }

    /// Glass; rejects an index of refraction that is not finite and positive.
    pub fn glass(ior: f32) -> Result<Material> {
        Ok(Material::Glass {
            ior: positive("ior", ior)?,
        })
    }

    /// `Ok` if the material's numbers are usable (the enum's fields are public, so a
    /// material may have been built without the constructors above).
    pub fn check(&self) -> Result<()> {
        match *self {
            Material::Diffuse { albedo } => fraction3("albedo", albedo).map(|_| ()),
            Material::Mirror { reflectance } => {
                fraction3("reflectance", reflectance).map(|_| ())
            }
            Material::Glass { ior } => positive("ior", ior).map(|_| ()),
        }
    }

    /// A black surface: absorbs everything (the back of a light, for instance).
    pub const BLACK: Material = Material::Diffuse { albedo: Vec3::ZERO };
}

// ANCHOR: lambert
/// Lambert's BRDF, f_r = albedo / pi: with it a white surface (albedo 1) under
/// uniform radiance L reflects exactly L, since the cosine integrates to pi.
pub fn diffuse_brdf(albedo: Vec3) -> Vec3 {
    albedo / PI
}
// ANCHOR_END: lambert

/// A direction a specular surface sends the path on, and the factor the path's
/// throughput is multiplied by.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Specular {
    /// The new unit direction.
    pub direction: Vec3,
    /// f_r cos / pdf for the chosen direction.
    pub weight: Vec3,
    /// `true` if the path went through the surface (refraction).
    pub transmitted: bool,
}

// ANCHOR: reflect
/// The mirror direction of `d` about the unit normal `n`: d - 2 (d . n) n.
pub fn reflect(d: Vec3, n: Vec3) -> Vec3 {
    d - 2.0 * d.dot(n) * n
}
// ANCHOR_END: reflect

// ANCHOR: fresnel
/// What light does at a smooth dielectric boundary: the share it reflects, and the
/// cosine of the angle of the refracted direction with the normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fresnel {
    /// F: the fraction reflected, unpolarised; 1 - F is refracted.
    pub reflectance: f32,
    /// cos theta_t of the refracted direction; 0 under total internal reflection,
    /// where nothing is refracted.
    pub cos_t: f32,
}

/// The exact Fresnel reflectance of a smooth dielectric for unpolarised light (the
/// mean of the s and p polarisations; Born and Wolf, pbrt-v3 section 8.2.1):
///
/// r_s = (eta cos_i - cos_t) / (eta cos_i + cos_t),
/// r_p = (cos_i - eta cos_t) / (cos_i + eta cos_t),  F = (r_s^2 + r_p^2) / 2,
///
/// where eta = `n_i_over_n_t`, the index of the side the light arrives from over the
/// index of the side it would enter (glass of index 1.5 entered from air: 1/1.5;
/// pbrt-v4's `eta` is the inverse, n_t / n_i), and `cos_i` > 0 is the cosine of the
/// incident angle. The reflectance is 1 (total internal reflection) when
/// sin_t = eta sin_i reaches 1, and at grazing incidence, cos_i = 0. Schlick's
/// approximation is not used.
///
/// ```
/// use render_lessons::material::fresnel;
///
/// let entering = fresnel(1.0, 1.0 / 1.5); // head on, from air into glass
/// assert!((entering.reflectance - 0.04).abs() < 1e-6 && entering.cos_t == 1.0);
/// let inside = fresnel(0.5, 1.5); // from glass, 60 degrees: beyond the critical angle
/// assert_eq!((inside.reflectance, inside.cos_t), (1.0, 0.0));
/// ```
pub fn fresnel(cos_i: f32, n_i_over_n_t: f32) -> Fresnel {
    let eta = n_i_over_n_t;
    let cos_i = cos_i.clamp(0.0, 1.0);
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if sin2_t >= 1.0 || cos_i == 0.0 {
        return Fresnel {
            reflectance: 1.0,
            cos_t: 0.0,
        };
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    let r_s = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    let r_p = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    Fresnel {
        reflectance: 0.5 * (r_s * r_s + r_p * r_p),
        cos_t,
    }
}
// ANCHOR_END: fresnel

impl Material {
    /// The surface's colour as the ray caster paints it: the albedo of a diffuse
    /// surface, the reflectance of a mirror, white for glass (it absorbs nothing).
    pub fn albedo(&self) -> Vec3 {
        match *self {
            Material::Diffuse { albedo } => albedo,
            Material::Mirror { reflectance } => reflectance,
            Material::Glass { .. } => Vec3::ONE,
        }
    }

    /// `true` for mirror and glass, whose f_r is a delta function.
    pub fn is_specular(&self) -> bool {
        !matches!(self, Material::Diffuse { .. })
    }

    // ANCHOR: specular
    /// Where a specular surface sends a path arriving along the unit direction `d`.
    /// `n` is the unit normal on the side the path arrives from (d . n <= 0),
    /// `entering` says whether that side is the outside, and `u` in [0, 1) chooses
    /// between reflection and refraction for glass (reflect if u < F).
    ///
    /// Refraction: t = eta d + (eta cos_i - cos_t) n (pbrt-v3 eq. 8.8 rearranged), with
    /// weight 1: choosing with probability F cancels the factor F of f_r. Radiance is
    /// not scaled by eta^2: the scenes' paths enter and leave the glass, and the two
    /// factors cancel (smallpt does the same). `None` for a diffuse material.
    pub fn scatter_specular(
        &self,
        d: Vec3,
        n: Vec3,
        entering: bool,
        u: f32,
    ) -> Option<Specular> {
        let mirror = |weight| Specular {
            direction: reflect(d, n).normalize_or(n),
            weight,
            transmitted: false,
        };
        match *self {
            Material::Diffuse { .. } => None,
            Material::Mirror { reflectance } => Some(mirror(reflectance)),
            Material::Glass { ior } => {
                let eta = if entering { 1.0 / ior } else { ior };
                let cos_i = -d.dot(n);
                let Fresnel { reflectance, cos_t } = fresnel(cos_i, eta);
                if u < reflectance {
                    return Some(mirror(Vec3::ONE));
                }
                let t = eta * d + (eta * cos_i - cos_t) * n;
                Some(Specular {
                    direction: t.normalize_or(-n),
                    weight: Vec3::ONE,
                    transmitted: true,
                })
            }
        }
    }
    // ANCHOR_END: specular
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fresnel_is_4_percent_at_normal_incidence_and_total_beyond_the_critical_angle() {
        let f = fresnel(1.0, 1.0 / 1.5).reflectance;
        assert!((f - 0.04).abs() < 1e-6, "{f}");
        let critical = (1.0f32 / 1.5).asin();
        let beyond = fresnel((critical + 0.01).cos(), 1.5);
        assert_eq!((beyond.reflectance, beyond.cos_t), (1.0, 0.0));
        assert_eq!(fresnel(0.0, 1.0 / 1.5).reflectance, 1.0);
    }

    #[test]
    fn fresnel_ratio_is_n_i_over_n_t_and_cos_t_is_snell_s() {
        // eta = n_i / n_t: from air into glass 1/1.5, Snell's law sin_t = eta sin_i.
        for degrees in [0.0f32, 15.0, 30.0, 45.0, 60.0, 75.0, 85.0] {
            let theta_i = degrees.to_radians();
            let f = fresnel(theta_i.cos(), 1.0 / 1.5);
            let sin_t = theta_i.sin() / 1.5;
            let expected = (1.0 - sin_t * sin_t).sqrt();
            assert!((f.cos_t - expected).abs() < 1e-6, "{degrees}: {}", f.cos_t);
            assert!(f.reflectance > 0.0 && f.reflectance < 1.0, "{degrees}");
            // Light is reversible: the refracted ray traced back out of the glass
            // reflects the same share.
            let back = fresnel(f.cos_t, 1.5);
            assert!((back.reflectance - f.reflectance).abs() < 1e-5, "{degrees}");
        }
        // pbrt-v4's eta = n_t / n_i = 1.5 for the same boundary would be total internal
        // reflection already at 45 degrees: the ratio's direction matters.
        assert_eq!(fresnel(45f32.to_radians().cos(), 1.5).reflectance, 1.0);
    }
}
