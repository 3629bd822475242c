//! The host's side of the WGSL module ([`super::wgsl_module`]): what a renderer that
//! includes `torus_intersect` in its own shader packs, and how it reads the answer back.
//! The library's own kernel packs and reads through the same code ([`Frame`]), so the
//! module's contract is the kernel's.
//!
//! - [`ModuleTorus::params`]: the module's `TorusParams`, once per torus (112 bytes):
//!   rows of the world → torus rotation M with R, r, r/R in w; 1/R; the culls' bounds at
//!   R = 1 with the tube padded by the GPU's margin (the CPU's η plus the kernel's line
//!   error, `bounds.rs`), which only Rust computes.
//! - [`ModuleTorus::prepare`]: the module's `TorusRay`, per ray (32 bytes), and what the
//!   host keeps: the shift `t0` of a far origin and the host's own answer where it has
//!   one (an origin beyond 2²⁰·R, a ray from a surface point that does not leave into the
//!   outside).
//! - [`PreparedRay::verdict`], [`PreparedRay::finish`]: the shader's `TorusHit` as the
//!   ray's verdict, and finished in f64 on the host where it escalated.
//!
//! The f64 module ([`super::wgsl_finish_module`]), where the device has `SHADER_F64`:
//!
//! - [`ModuleTorus::params64`]: its `TorusParams64`, once per torus (136 bytes, the
//!   library's f64 pass's torus buffer);
//! - [`ModuleTorus::prepare_f64`]: its `TorusWorldRay` and instruction, per ray (the
//!   library pass's world record and instruction);
//! - [`PreparedRay::finish_with_device`]: the f32 answer, the device's f64 answer where
//!   the ray escalated and the device answered ([`ModuleHit64::answer`]), else the host's,
//!   as [`super::GpuIntersector::intersect_finished_where`] decides.

use super::Finished;
use super::finish as device;
use super::{Escalation, Frame, shifted};
use crate::certified::{F32Hit, F32Verdict, finish};
use crate::{Ray, Torus};
use glam::Vec3;

/// A torus prepared for the WGSL module: its `TorusParams` block and the host's ray
/// preparation.
pub struct ModuleTorus {
    frame: Frame,
    torus: Torus,
}

impl std::fmt::Debug for ModuleTorus {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ModuleTorus")
            .field("torus", &self.torus)
            .finish_non_exhaustive()
    }
}

/// A ray prepared for the WGSL module, and what the host adds to the shader's answer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PreparedRay {
    /// The module's `TorusRay`: `origin` (o − c, rounded once from f64, moved to the
    /// line's foot point if it was farther than 2·(R + r)), `t_min`, `direction`, `t_max`
    /// (shifted by `−t0` and clipped to where the bounding sphere can be).
    pub words: [f32; 8],
    /// How far along the ray the prepared origin is: the shader's t plus `t0` is the
    /// ray's own t.
    pub t0: f64,
    /// The host's own answer, where it has one: then the shader's answer for this ray is
    /// ignored (it may still be sent; it is a valid ray).
    pub host: Option<(F32Verdict, Option<Escalation>)>,
    /// The module's `TorusSurfaceRay` (16 words, four `vec4<f32>`): for a ray from a
    /// surface point, the cubic left once its origin's root is divided out, formed in f64
    /// and rounded with bounds, its range, and the literal start past the root; the last
    /// word is 0 for a literal ray. Pass it to `torus_intersect_from_surface`, which
    /// answers a literal ray as `torus_intersect` does.
    pub surface: [f32; 16],
}

/// A ray prepared for the f64 module ([`ModuleTorus::prepare_f64`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PreparedRay64 {
    /// The module's `TorusWorldRay`: `origin`, `t_min`, `direction`, `t_max` of the ray
    /// as the caller gave it (world space), the range clipped to
    /// `|t| ≤ (|o − c| + 4(R + r))/|d|`, beyond which no root lies.
    pub words: [f32; 8],
    /// The `instruction` argument of `torus_finish_wanted` and `torus_finish_f64`:
    /// `TORUS_F64_FOLLOW` (finish it where the f32 module escalates), `_ALWAYS` (the host
    /// sent the f32 module nothing it could prove: an origin beyond 2²⁰·R),
    /// `_SURFACE_FOLLOW`, `_SURFACE_ALWAYS` (the same for a ray from a surface point, its
    /// own root divided out), or `_HOST` (the host answers it: a range f32 cannot clip,
    /// or an answer the host already has).
    pub instruction: u32,
}

impl PreparedRay64 {
    /// [`PreparedRay64::words`] as the 32 little-endian bytes of a `TorusWorldRay`.
    pub fn bytes(&self) -> [u8; 32] {
        words_bytes(self.words)
    }
}

/// The f32 module's `TorusHit` as a renderer reads it back.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModuleHit {
    /// t along the prepared ray (add [`PreparedRay::t0`]; [`PreparedRay::verdict`] does).
    pub t: f32,
    /// The unit world normal of a hit.
    pub normal: Vec3,
    /// `TORUS_MISS`, `TORUS_HIT` or `TORUS_ESCALATE`.
    pub code: u32,
    /// `TORUS_WHY_*` of an escalated ray.
    pub why: u32,
}

/// The f64 module's `TorusHit64` as a renderer reads it back.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModuleHit64 {
    /// t along the world ray, rounded once from f64.
    pub t: f32,
    /// The unit world normal, rounded once from f64.
    pub normal: Vec3,
    /// The hit point `o + t·d`, rounded once from f64.
    pub point: Vec3,
    /// `TORUS_F64_STATUS_FRONT`, `_BACK`, `_MISS` or `_HOST` (or `_PROVED`, the library
    /// pass's word for "not run").
    pub status: u32,
}

impl ModuleHit64 {
    /// The device's answer: a hit from the outside (`FRONT`) or the inside (`BACK`), or a
    /// miss (`MISS`), marked escalated; `None` where the host must finish the ray with the
    /// f64 path (`HOST`, `PROVED`, or an unknown status).
    pub fn answer(&self) -> Option<F32Hit> {
        let (n, p) = (self.normal, self.point);
        device::device_answer([self.t, n.x, n.y, n.z, p.x, p.y, p.z, self.status as f32])
    }
}

fn words_bytes(words: [f32; 8]) -> [u8; 32] {
    let mut out = [0; 32];
    for (chunk, w) in out.chunks_exact_mut(4).zip(words) {
        chunk.copy_from_slice(&w.to_le_bytes());
    }
    out
}

impl ModuleTorus {
    /// The torus as the module reads it.
    pub fn new(torus: &Torus) -> ModuleTorus {
        ModuleTorus {
            frame: Frame::of(torus),
            torus: *torus,
        }
    }

    /// The torus.
    pub fn torus(&self) -> &Torus {
        &self.torus
    }

    /// The module's `TorusParams`, seven `vec4<f32>` in order: `rot_x`, `rot_y`, `rot_z`
    /// (rows of M; w: R, r, r/R), `scale` (x: 1/R), `bounds_a`, `bounds_b`, `bounds_c`.
    pub fn params(&self) -> [f32; 28] {
        self.frame.torus_params()
    }

    /// [`ModuleTorus::params`] as 112 little-endian bytes (a uniform or storage buffer).
    pub fn params_bytes(&self) -> Vec<u8> {
        self.params().iter().flat_map(|f| f.to_le_bytes()).collect()
    }

    /// The f64 module's `TorusParams64`, 17 `f64` in order: the centre c, the columns of
    /// the world → torus rotation M (`M·(o − c)` is the origin in the torus frame), R,
    /// 1/R, r/R, 1 − (r/R)², 1 + r/R, as the CPU's f64 path holds them.
    pub fn params64(&self) -> [f64; 17] {
        device::torus_values(&self.torus)
    }

    /// [`ModuleTorus::params64`] as 136 little-endian bytes (a storage buffer).
    pub fn params64_bytes(&self) -> Vec<u8> {
        device::torus_bytes(&self.torus)
    }

    /// The f64 module's `TorusWorldRay` and instruction for `ray`, given what
    /// [`ModuleTorus::prepare`] made of it for the f32 module (its host answer decides
    /// the instruction), as the library's f64 pass gets them.
    pub fn prepare_f64(&self, ray: &Ray, prepared: &PreparedRay) -> PreparedRay64 {
        let (words, instruction) = device::world_record(&self.torus, ray, prepared.host);
        PreparedRay64 {
            words,
            instruction: instruction as u32,
        }
    }

    /// The module's `TorusRay` and `TorusSurfaceRay` for `ray`, as the library's kernel
    /// gets them:
    ///
    /// - a ray from a surface point ([`Ray::from_surface`]) goes with its cubic, the
    ///   origin's root divided out in f64 ([`PreparedRay::surface`]), and the start past
    ///   that root for the literal certificate to fall back on; where the cubic has nothing
    ///   to prove from, as its literal ray past the root; or the host answers it: a proved
    ///   miss (the range ends first), or [`Escalation::OnSurface`] (neither);
    /// - the origin relative to the centre, o − c in f64 rounded once; an origin farther
    ///   than 2·(R + r) moved to its line's foot point, `t0 = −(o − c)·d/|d|²` in f64, the
    ///   range shifted by `−t0` and clipped to `|t| ≤ (|foot| + 4(R + r))/|d|`;
    /// - an origin beyond 2²⁰·R: [`Escalation::FarOrigin`] (the f64 foot point's own error
    ///   would no longer be negligible beside the kernel's line error bound).
    pub fn prepare(&self, ray: &Ray) -> PreparedRay {
        let packed = self.frame.prepare(ray);
        PreparedRay {
            words: packed.words,
            t0: packed.t0,
            host: packed.host,
            surface: packed.surface,
        }
    }
}

impl PreparedRay {
    /// [`PreparedRay::words`] as the 32 little-endian bytes of a `TorusRay`.
    pub fn bytes(&self) -> [u8; 32] {
        words_bytes(self.words)
    }

    /// This ray as a shader that calls `torus_intersect_from_surface` with
    /// [`PreparedRay::surface`] reads it: [`PreparedRay::host`] is then none for a ray the
    /// shader proves from its cubic alone (a ray from a surface point with no start past
    /// its origin's root, which `torus_intersect` cannot answer). Decode and finish that
    /// shader's answers through this copy ([`PreparedRay::verdict`],
    /// [`ModuleTorus::prepare_f64`]).
    #[must_use]
    pub fn from_surface(&self) -> PreparedRay {
        PreparedRay {
            host: super::frame::kernel_host(self.host, &self.surface),
            ..*self
        }
    }

    /// [`PreparedRay::surface`] as the 64 little-endian bytes of a `TorusSurfaceRay`.
    pub fn surface_bytes(&self) -> [u8; 64] {
        let mut out = [0; 64];
        for (chunk, w) in out.chunks_exact_mut(4).zip(self.surface) {
            chunk.copy_from_slice(&w.to_le_bytes());
        }
        out
    }

    /// The ray's verdict from the shader's `TorusHit` (`t`, `normal`, `code`, `why`): the
    /// host's answer where it has one; else a hit with t shifted by `t0` (escalated if
    /// that is not finite in f32), a miss, or an escalation with its [`Escalation`] (an
    /// unknown code escalates).
    pub fn verdict(
        &self,
        t: f32,
        normal: Vec3,
        code: u32,
        why: u32,
    ) -> (F32Verdict, Option<Escalation>) {
        if let Some(answer) = self.host {
            return answer;
        }
        let record = [
            t,
            normal.x,
            normal.y,
            normal.z,
            code as f32,
            why as f32,
            0.0,
            0.0,
        ];
        shifted(super::verdict(record), self.t0)
    }

    /// [`PreparedRay::verdict`] finished: an escalated ray is answered by the f64 solver
    /// ([`crate::intersect()`]) on the host, so the hit or miss is the f64 path's.
    pub fn finish(
        &self,
        torus: &Torus,
        ray: &Ray,
        t: f32,
        normal: Vec3,
        code: u32,
        why: u32,
    ) -> F32Hit {
        finish(self.verdict(t, normal, code, why).0, torus, ray)
    }

    /// The ray's answer with the device's f64 finish, and who gave it, as
    /// [`super::GpuIntersector::intersect_finished_where`] decides: the f32 verdict where
    /// it is proved ([`Finished::Proved`]); where it escalated, the f64 module's answer
    /// ([`ModuleHit64::answer`], [`Finished::Device`]) if the shader ran
    /// `torus_finish_f64` and it answered, else the f64 path on the host
    /// ([`crate::intersect()`], [`Finished::Host`]).
    pub fn finish_with_device(
        &self,
        torus: &Torus,
        ray: &Ray,
        hit: &ModuleHit,
        hit64: Option<&ModuleHit64>,
    ) -> (F32Hit, Finished) {
        let (verdict, _) = self.verdict(hit.t, hit.normal, hit.code, hit.why);
        if verdict != F32Verdict::Escalate {
            return (finish(verdict, torus, ray), Finished::Proved);
        }
        match hit64.and_then(ModuleHit64::answer) {
            Some(answer) => (answer, Finished::Device),
            None => (finish(verdict, torus, ray), Finished::Host),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::{CODE_ESCALATE, CODE_HIT, CODE_MISS, GpuCull, Mode};
    use super::*;

    fn torus() -> Torus {
        Torus::new(Vec3::new(1.0, 2.0, 3.0), Vec3::new(0.2, 1.0, 0.1), 4.0, 1.0).unwrap()
    }

    /// `TorusParams` is the kernel's parameter block less its `config` row.
    #[test]
    fn the_params_are_the_kernels_block() {
        let t = torus();
        let module = ModuleTorus::new(&t);
        let block = Frame::of(&t).params(5, GpuCull::Skala, Mode::Intersect, false);
        assert_eq!(module.params_bytes().len(), 112);
        assert_eq!(module.params_bytes()[..], block[..112]);
        assert_eq!(module.params()[3], 4.0); // rot_x.w = R
    }

    /// A near ray goes as is (o − c), a far one moves to its foot point, one beyond 2²⁰·R
    /// and a surface ray into the tube are the host's.
    #[test]
    fn the_host_prepares_as_the_kernel_does() {
        let t = torus();
        let module = ModuleTorus::new(&t);
        let c = t.center();
        let near = Ray::new(c + Vec3::new(0.0, 8.0, 0.5), Vec3::NEG_Y).unwrap();
        let p = module.prepare(&near);
        assert_eq!((p.t0, p.host), (0.0, None));
        assert_eq!(p.words[..3], (near.origin() - c).to_array());
        assert_eq!(p.words[4..7], near.dir().to_array());
        let far = Ray::new(c + Vec3::new(0.5, 1e4, 0.0), Vec3::NEG_Y).unwrap();
        let p = module.prepare(&far);
        assert!((p.t0 - 1e4).abs() < 1e-2, "{}", p.t0);
        assert_eq!(p.host, None);
        // The shader's hit at t = 3 along the prepared ray is the ray's hit at t0 + 3.
        let (v, _) = p.verdict(3.0, Vec3::Y, CODE_HIT, 0);
        assert_eq!(
            v,
            F32Verdict::Hit {
                t: (p.t0 + 3.0) as f32,
                normal: Vec3::Y
            }
        );
        assert_eq!(p.verdict(0.0, Vec3::ZERO, CODE_MISS, 0).0, F32Verdict::Miss);
        assert_eq!(
            p.verdict(0.0, Vec3::ZERO, CODE_ESCALATE, 5),
            (F32Verdict::Escalate, Some(Escalation::NoSignChange))
        );
        let beyond = Ray::new(c + Vec3::new(0.0, 1e7, 0.0), Vec3::NEG_Y).unwrap();
        let p = module.prepare(&beyond);
        assert_eq!(
            p.host,
            Some((F32Verdict::Escalate, Some(Escalation::FarOrigin)))
        );
        // Whatever the shader says, the host's answer stands; finished, it is the f64 path's.
        assert_eq!(p.verdict(1.0, Vec3::Y, CODE_HIT, 0), p.host.unwrap());
        let finished = p.finish(&t, &beyond, 1.0, Vec3::Y, CODE_HIT, 0);
        assert!(finished.escalated);
        assert_eq!(
            finished.hit.map(|h| h.t),
            crate::intersect(&t, &beyond).map(|h| h.t)
        );
        assert_eq!(p.bytes()[..4], p.words[0].to_le_bytes());
    }

    /// The f64 module's inputs are the library pass's (torus bytes, world record,
    /// instruction), and `finish_with_device` decides who answers as the library does.
    #[test]
    fn the_f64_inputs_and_the_answer_are_the_library_passes() {
        use super::super::finish::torus_bytes;
        use super::super::finish_words::{Instruction, Status};
        let t = torus();
        let module = ModuleTorus::new(&t);
        assert_eq!(module.params64_bytes(), torus_bytes(&t));
        assert_eq!(module.params64_bytes().len(), 136);
        assert_eq!(module.params64()[12], 4.0); // R
        let c = t.center();
        let near = Ray::new(c + Vec3::new(0.0, 8.0, 0.5), Vec3::NEG_Y).unwrap();
        let p = module.prepare(&near);
        let p64 = module.prepare_f64(&near, &p);
        assert_eq!(p64.instruction, Instruction::Follow as u32);
        // The world ray as given (not o − c), its range clipped to where the torus is.
        assert_eq!(p64.words[..3], near.origin().to_array());
        assert_eq!(p64.words[4..7], near.dir().to_array());
        assert!(p64.words[7].is_finite() && p64.words[7] > 8.0);
        assert_eq!(p64.bytes()[28..], p64.words[7].to_le_bytes());
        let beyond = Ray::new(c + Vec3::new(0.0, 1e7, 0.0), Vec3::NEG_Y).unwrap();
        let pb = module.prepare(&beyond);
        assert_eq!(
            module.prepare_f64(&beyond, &pb).instruction,
            Instruction::Always as u32
        );
        // Proved by f32: the f64 answer is not read.
        let miss = ModuleHit {
            t: 0.0,
            normal: Vec3::ZERO,
            code: CODE_MISS,
            why: 0,
        };
        let device_hit = ModuleHit64 {
            t: 7.0,
            normal: Vec3::Y,
            point: Vec3::ONE,
            status: Status::Front as u32,
        };
        let (answer, who) = p.finish_with_device(&t, &near, &miss, Some(&device_hit));
        assert_eq!((answer.hit, who), (None, Finished::Proved));
        // Escalated: the device's answer, or the host's where the device handed it back.
        let escalated = ModuleHit {
            code: CODE_ESCALATE,
            why: 5,
            ..miss
        };
        let (answer, who) = p.finish_with_device(&t, &near, &escalated, Some(&device_hit));
        assert_eq!(who, Finished::Device);
        assert_eq!(answer.hit.map(|h| (h.t, h.front_face)), Some((7.0, true)));
        for back in [
            None,
            Some(ModuleHit64 {
                status: Status::Host as u32,
                ..device_hit
            }),
            Some(ModuleHit64 {
                status: Status::Proved as u32,
                ..device_hit
            }),
        ] {
            let (answer, who) = p.finish_with_device(&t, &near, &escalated, back.as_ref());
            assert_eq!(who, Finished::Host);
            assert_eq!(
                answer.hit.map(|h| h.t),
                crate::intersect(&t, &near).map(|h| h.t)
            );
        }
    }
}
