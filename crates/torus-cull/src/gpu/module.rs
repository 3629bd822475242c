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

    /// The module's `TorusRay` for `ray`, as the library's kernel gets it:
    ///
    /// - a ray from a surface point ([`Ray::from_surface`]) goes as its literal ray past
    ///   its origin's own root (the origin's root divided out in f64), or the host
    ///   answers it: a proved miss, or [`Escalation::OnSurface`] (it goes into the tube or
    ///   along the tangent plane);
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
        }
    }
}

impl PreparedRay {
    /// [`PreparedRay::words`] as the 32 little-endian bytes of a `TorusRay`.
    pub fn bytes(&self) -> [u8; 32] {
        let mut out = [0; 32];
        for (chunk, w) in out.chunks_exact_mut(4).zip(self.words) {
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
}

#[cfg(test)]
mod tests {
    use super::super::{CODE_ESCALATE, CODE_HIT, CODE_MISS, GpuCull, Mode};
    use super::*;

    fn torus() -> Torus {
        Torus::new(Vec3::new(1.0, 2.0, 3.0), Vec3::new(0.2, 1.0, 0.1), 4.0, 1.0).unwrap()
    }

    /// `TorusParams` is the kernel's uniform block less its `config` row.
    #[test]
    fn the_params_are_the_kernels_block() {
        let t = torus();
        let module = ModuleTorus::new(&t);
        let block = Frame::of(&t).params(5, GpuCull::Skala, Mode::Intersect);
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
}
