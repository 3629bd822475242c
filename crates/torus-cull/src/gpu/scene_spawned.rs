//! Secondary rays in the GPU BVH: a ray spawned on one torus of the scene
//! ([`SpawnedRay`]: a bounce, a refraction or a shadow ray from a hit, made with
//! [`Torus::spawn`](crate::Torus::spawn)), traced on the device with its own torus on the
//! surface path and every other torus on the literal ray, as the CPU's scenes trace it.
//!
//! **Why the torus must be named.** [`Ray::from_surface`] names no shape: every torus whose
//! surface passes within 10⁻²·R of the origin would divide "its" root out, and a
//! neighbour that touches the origin's torus (the chain's links) would then report a
//! crossing the line does not have. So the ray's own torus sees the surface ray (the
//! origin's root divided out, no ε), and every other its [`Ray::literal`].
//!
//! **The record** (`TorusSceneOwn`, 112 bytes after the 32-byte world ray; `wgsl/scene.wgsl`):
//! the module's `TorusRay` for the own torus and its `TorusSurfaceRay`, formed on the host
//! in f64 exactly as the single-torus kernel's ([`super::ModuleTorus::prepare`], then
//! [`super::PreparedRay::from_surface`]), and `(torus, what to do there, 0, 0)` as `u32`:
//! [`OWN_CERTIFY`] (the module's `torus_intersect_from_surface`), [`OWN_MISS`] (the host
//! proved the range ends before any other crossing) or [`OWN_ESCALATE`] (the f64 finish
//! from the surface on the device, `TORUS_F64_SURFACE_ALWAYS`, else the host).

use super::scene_bvh::{OWN_CERTIFY, OWN_ESCALATE, OWN_MISS};
use super::{GpuError, ModuleTorus, SceneBvh, SceneHit};
use crate::certified::F32Verdict;
use crate::{Ray, Torus};

/// Words in a spawned ray's kernel record: the world ray (8), the own torus's `TorusRay`
/// (8), its `TorusSurfaceRay` (16), `(torus, what to do, 0, 0)` (4, `u32` bits).
pub const SPAWNED_WORDS: usize = 36;

/// A secondary ray and the torus of the scene it starts on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpawnedRay {
    /// The ray: [`crate::Torus::spawn`] of a hit on torus `from` (marked as starting on its
    /// surface). A ray not so marked is traced as a literal ray on every torus.
    pub ray: Ray,
    /// The torus it starts on: its index in the slice the scene was built from.
    pub from: u32,
}

impl SceneBvh {
    /// The kernel's record for a spawned ray (`TorusRay` and `TorusSceneOwn`,
    /// [`SPAWNED_WORDS`] words; the last four are `u32` bit patterns, `f32::to_bits`),
    /// or `None` where the host answers the ray ([`SceneBvh::prepare`] of its literal ray).
    ///
    /// # Errors
    ///
    /// [`GpuError::Scene`] where `from` is not a torus of the scene (the message names the
    /// allowed range).
    pub fn prepare_from(
        &self,
        spawned: &SpawnedRay,
    ) -> Result<Option<[f32; SPAWNED_WORDS]>, GpuError> {
        let own = self.own(spawned)?;
        let Some(world) = self.prepare(&spawned.ray.literal()) else {
            return Ok(None);
        };
        let mut words = [0.0; SPAWNED_WORDS];
        words[..8].copy_from_slice(&world);
        if !spawned.ray.starts_on_surface() {
            words[32] = f32::from_bits(u32::MAX);
            return Ok(Some(words));
        }
        let prepared = ModuleTorus::new(own).prepare(&spawned.ray).from_surface();
        // A surface point is within 2·(R + r) of its centre, so the module's origin is not
        // moved (t0 = 0) and its t is the ray's; anything else goes to the f64 path.
        let what = match prepared.host {
            None if prepared.t0 == 0.0 => OWN_CERTIFY,
            Some((F32Verdict::Miss, _)) => OWN_MISS,
            _ => OWN_ESCALATE,
        };
        words[8..16].copy_from_slice(&prepared.words);
        words[16..32].copy_from_slice(&prepared.surface);
        words[32] = f32::from_bits(spawned.from);
        words[33] = f32::from_bits(what);
        Ok(Some(words))
    }

    /// The host's answer for a spawned ray: [`crate::intersect()`] of the surface ray on
    /// its own torus and of the literal ray at every other leaf it enters, the nearest
    /// kept (the lowest index on a tie), as the CPU's brute force over the scene.
    ///
    /// # Errors
    ///
    /// As [`SceneBvh::prepare_from`].
    pub fn host_trace_from(&self, spawned: &SpawnedRay) -> Result<Option<SceneHit>, GpuError> {
        let own = self.own(spawned)?;
        let literal = spawned.ray.literal();
        let mine = host_own_leaf(own, &spawned.ray).map(|h| SceneHit {
            torus: spawned.from,
            t: h.t,
            normal: h.normal,
        });
        let theirs = self.host_trace_skipping(&literal, Some(spawned.from));
        Ok(match (mine, theirs) {
            (Some(a), Some(b)) if b.t < a.t || (b.t == a.t && b.torus < a.torus) => Some(b),
            (Some(a), _) => Some(a),
            (None, b) => b,
        })
    }

    /// The host's any-hit answer for a spawned shadow ray ([`crate::occluded()`], the
    /// surface ray on its own torus, the literal ray elsewhere).
    ///
    /// # Errors
    ///
    /// As [`SceneBvh::prepare_from`].
    pub fn host_occluded_from(&self, spawned: &SpawnedRay) -> Result<bool, GpuError> {
        let own = self.own(spawned)?;
        Ok(crate::occluded(own, &spawned.ray)
            || self.host_occluded_skipping(&spawned.ray.literal(), Some(spawned.from)))
    }

    /// The torus `spawned` starts on, or the error that names the allowed range.
    fn own(&self, spawned: &SpawnedRay) -> Result<&Torus, GpuError> {
        self.tori().get(spawned.from as usize).ok_or_else(|| {
            GpuError::Scene(format!(
                "a spawned ray's torus {} is not in the scene (allowed: 0 ..= {})",
                spawned.from,
                self.tori().len() - 1
            ))
        })
    }
}

/// The f64 path for a spawned ray's own torus on the host: the surface ray's nearest
/// crossing past its origin's own root.
pub(crate) fn host_own_leaf(torus: &Torus, ray: &Ray) -> Option<crate::Hit> {
    crate::intersect(torus, ray)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    /// A spawned ray's record: the literal ray's world record, its own torus's module ray
    /// and surface record as the single-torus kernel gets them, its index and what to do;
    /// a literal ray names no torus; a torus the scene lacks is an error naming the range;
    /// the host's answer is the brute force's (own torus on the surface ray).
    #[test]
    fn a_spawned_ray_carries_its_torus_and_its_surface_record() {
        let tori = [
            Torus::new(Vec3::ZERO, Vec3::Y, 1.0, 0.25).unwrap(),
            Torus::new(Vec3::new(1.2, 0.0, 0.0), Vec3::Z, 1.0, 0.25).unwrap(),
        ];
        let bvh = SceneBvh::new(&tori).unwrap();
        let down = Ray::new(Vec3::new(1.0, 5.0, 0.0), Vec3::NEG_Y).unwrap();
        let hit = crate::intersect(&tori[0], &down).expect("a hit");
        let into = tori[0]
            .spawn(&down, hit.t, Vec3::new(0.1, -1.0, 0.05))
            .unwrap();
        let spawned = SpawnedRay { ray: into, from: 0 };
        let words = bvh.prepare_from(&spawned).unwrap().expect("on the device");
        assert_eq!(words[..8], bvh.prepare(&into.literal()).unwrap());
        let own = ModuleTorus::new(&tori[0]).prepare(&into).from_surface();
        assert_eq!(words[8..16], own.words);
        assert_eq!(words[16..32], own.surface);
        assert_eq!(words[32].to_bits(), 0);
        assert!([OWN_CERTIFY, OWN_MISS, OWN_ESCALATE].contains(&words[33].to_bits()));
        let literal = SpawnedRay { ray: down, from: 1 };
        let words = bvh.prepare_from(&literal).unwrap().unwrap();
        assert_eq!(words[32].to_bits(), u32::MAX);
        let stray = SpawnedRay { from: 2, ..spawned };
        let err = bvh.prepare_from(&stray).unwrap_err();
        assert!(err.to_string().contains("allowed: 0 ..= 1"), "{err}");
        // The host: the own torus sees the surface ray, the other one the literal ray.
        let brute = [
            crate::intersect(&tori[0], &into).map(|h| (0, h.t)),
            crate::intersect(&tori[1], &into.literal()).map(|h| (1, h.t)),
        ]
        .into_iter()
        .flatten()
        .min_by(|a, b| a.1.total_cmp(&b.1));
        let host = bvh.host_trace_from(&spawned).unwrap();
        assert_eq!(host.map(|h| (h.torus, h.t)), brute);
        assert!(brute.is_some());
    }
}
