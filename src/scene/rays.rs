//! The rays a renderer traces through a scene after its camera rays: per hit, a shadow
//! ray to a point light (any-hit, `t_max` at the light) and one cosine-weighted diffuse
//! bounce, both spawned on the hit torus with [`Torus::spawn`](torus_cull::Torus::spawn)
//! (the origin moved onto the surface and marked as starting there, no ε).
//!
//! A bounce may re-hit its own torus (through the tube) or a neighbour at any small t;
//! a shadow ray's direction is the whole segment to the light, so its t is in units of
//! that distance. `stretch` multiplies every direction (and divides `t_max`): the same
//! segments with long direction vectors, where a box's depth along the ray, in t, is
//! small at any scale (the case obvhs's node clamp at t = 10⁻⁴ loses; see
//! [`super::traverse`]).
//!
//! The functions take any scene of [`Surfaces`]: the tori of [`Scene`] and the family
//! shapes of [`super::family::FamilyScene`] alike.

use super::{Scene, SceneHit};
use crate::workload::CameraView;
use glam::{DVec3, Vec3};
use rand::SeedableRng;
use rand_pcg::Pcg64;
use torus_cull::{Ray, intersect};

/// What a scene's secondary rays need of it: the camera and bounds that place the light,
/// and per shape its hit's normal and its spawn API (the origin moved onto the surface).
pub trait Surfaces {
    /// The camera and the scene's bounding sphere (centre, radius).
    fn view(&self) -> (&CameraView, (DVec3, f64));
    /// Shape `id`'s nearest hit on `ray`: t and the unit normal on the side the ray came
    /// from (the outward normal where the ray enters, its opposite where it leaves).
    fn facing_hit(&self, id: u32, ray: &Ray) -> Option<(f32, DVec3)>;
    /// The ray leaving shape `id`'s hit at `t` on `ray` in `dir`, spawned with the
    /// shape's own API; `None` where the spawn fails (a point beyond f32).
    fn spawn(&self, id: u32, ray: &Ray, t: f32, dir: Vec3) -> Option<Ray>;
}

impl Surfaces for Scene {
    fn view(&self) -> (&CameraView, (DVec3, f64)) {
        (&self.camera, self.bounding_sphere)
    }

    fn facing_hit(&self, id: u32, ray: &Ray) -> Option<(f32, DVec3)> {
        let h = intersect(&self.tori[id as usize], ray)?;
        let normal = h.normal.as_dvec3();
        Some((h.t, if h.front_face { normal } else { -normal }))
    }

    fn spawn(&self, id: u32, ray: &Ray, t: f32, dir: Vec3) -> Option<Ray> {
        self.tori[id as usize].spawn(ray, t, dir).ok()
    }
}

/// A secondary ray and the shape it was spawned on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spawned {
    /// The ray (it starts on the surface of shape `from`).
    pub ray: Ray,
    /// The shape it starts on (an index into [`Scene::tori`], or into
    /// [`super::family::FamilyScene::shapes`]).
    pub from: u32,
}

impl Spawned {
    /// The same segment as a literal ray ([`Ray::with_range`]): how every torus but its
    /// own must see it. A surface ray's origin is on the surface of its own torus only;
    /// the library divides the origin's root out of any torus whose surface passes within
    /// 10⁻²·R of the origin, which a neighbour that touches or crosses the torus (the
    /// chain's links of one orientation, 2R apart, touch) does, and there it reports a
    /// crossing the line does not have.
    pub fn literal(&self) -> Ray {
        let r = &self.ray;
        Ray::with_range(r.origin(), r.dir(), r.t_min(), r.t_max())
            .expect("a valid ray's parts make a valid ray")
    }

    /// The ray torus `prim` sees: the surface ray for its own torus, `literal` (its
    /// [`Spawned::literal`]) for every other.
    #[inline]
    pub fn seen_by<'a>(&'a self, prim: usize, literal: &'a Ray) -> &'a Ray {
        if prim == self.from as usize {
            &self.ray
        } else {
            literal
        }
    }
}

/// The scene's point light: beside the camera, half the scene's radius above its eye.
pub fn light(scene: &impl Surfaces) -> DVec3 {
    let (camera, (_, radius)) = scene.view();
    camera.eye + camera.up * (0.5 * radius)
}

/// For each hit `hits[i]` of `primary[i]`, a shadow ray from the hit to `light`, spawned
/// on the hit shape, direction `(light − hit) · stretch`, `t_max = 1 / stretch` (the
/// light). A hit whose spawn fails (a point beyond f32) gives none.
pub fn shadow_rays(
    scene: &impl Surfaces,
    primary: &[Ray],
    hits: &[SceneHit],
    light: DVec3,
    stretch: f32,
) -> Vec<Spawned> {
    primary
        .iter()
        .zip(hits)
        .filter_map(|(ray, hit)| {
            let (id, t) = (*hit)?;
            let at = ray.origin().as_dvec3() + ray.dir().as_dvec3() * f64::from(t);
            let dir = ((light - at) * f64::from(stretch)).as_vec3();
            let ray = scene
                .spawn(id, ray, t, dir)?
                .with_t_max(1.0 / stretch)
                .ok()?;
            Some(Spawned { ray, from: id })
        })
        .collect()
}

/// For each hit `hits[i]` of `primary[i]`, one diffuse bounce: cosine-weighted about the
/// normal on the side the ray came from (the unit normal plus a uniform unit vector),
/// times `stretch`, spawned on the hit shape; deterministic in `seed`.
pub fn bounce_rays(
    scene: &impl Surfaces,
    primary: &[Ray],
    hits: &[SceneHit],
    seed: u64,
    stretch: f32,
) -> Vec<Spawned> {
    let mut rng = Pcg64::seed_from_u64(seed ^ 0xB0C3_5EED_0F1E_1D00);
    primary
        .iter()
        .zip(hits)
        .filter_map(|(ray, hit)| {
            let (id, _) = (*hit)?;
            let (t, facing) = scene.facing_hit(id, ray)?;
            let dir: DVec3 = facing + crate::workload::unit_vector(&mut rng);
            if dir.length_squared() < 1e-12 {
                return None;
            }
            let dir = (dir.normalize() * f64::from(stretch)).as_vec3();
            let ray = scene.spawn(id, ray, t, dir)?;
            Some(Spawned { ray, from: id })
        })
        .collect()
}

/// `rays` with their directions times `stretch` and their range divided by it: the
/// same segments, in other units of t.
pub fn stretched(rays: &[Ray], stretch: f32) -> Vec<Ray> {
    rays.iter()
        .filter_map(|r| {
            Ray::with_range(
                r.origin(),
                r.dir() * stretch,
                r.t_min() / stretch,
                r.t_max() / stretch,
            )
            .ok()
        })
        .collect()
}
