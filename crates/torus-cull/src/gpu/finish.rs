//! Escalation on the device: a second compute pass, in f64, that finishes the rays the
//! certified f32 kernel escalated, where the adapter offers `wgpu::Features::SHADER_F64`.
//!
//! **Method.** The pass (`wgsl/finish_module/*.wgsl` and `wgsl/finish.wgsl`, behind the header [`super::FinishConstants`]
//! generates from the Rust constants) is the CPU's f64 path ([`crate::intersect()`] on a
//! ray that does not start on the surface) step for step, in the same operation order:
//! the line to the torus frame in f64 (`M·(o − c)`, `M·d`), the foot point scaled by
//! 1/R, the bounding sphere's chord test, the depressed quartic's coefficients in their
//! non-cancelling forms, then `nearest_root_in_range`: `surely_no_real_root`, the even
//! quartic (`q = 0`, its near-double `y` decided by the exact sign of `p² − 4r` in
//! integers held in f64, where the CPU rounds a fused multiply-add once: docs/gpu.md), Ferrari's split
//! on the resolvent's greatest root (Cardano with Vieta's small `z`, the trisection, the
//! near-double resolvent, the small-root fixed point and the guarded Newton polish), the
//! clear factors, and the near-double factors decided on the quartic (the cold path).
//! What differs from the CPU: the cube root is seeded in f32 (Kahan's seed and two f32
//! Halley steps, ≲ 2·10⁻⁷) and finished by one f64 Halley step (≲ 10⁻²⁰, below
//! rounding; the CPU's is a fit and one Halley step, also below rounding); the device
//! may contract `a·b + c` into an fma; infinities are replaced by finite sentinels
//! (WGSL may assume there are none). So the answers agree with the CPU's to rounding,
//! not to the bit; tests/gpu/gpu.rs checks them against the CPU's f64 path and the oracle.
//!
//! **Rays from a surface point** ([`crate::Ray::from_surface`]) take the CPU's
//! `intersect/from_surface.rs` path where the origin is within its reach of the surface:
//! the origin's own root (three guarded Newton steps on the quartic from `u₀`) divided
//! out, and the nearest root past it of the cubic left, by monotone pieces between its
//! critical points (a sign change and safeguarded Newton; a double root within rounding
//! at a critical point). The reach test uses `√(a² + b²)` for the CPU's `hypot`.
//!
//! **What goes back to the host** (counted, [`Finished::Host`]): a ray whose range cannot
//! be clipped to finite f32 (an origin near f32's largest value); a quartic or split that
//! is not finite; a hit point beyond f32's range. Everything else the f32 kernel
//! escalated, far origins and rays from surface points included, is finished on the
//! device.
//!
//! **Buffers** (one bind group, four storage buffers and the kernel's parameter block):
//! the world rays as the caller gave them, `(o, t_min)` and `(d, t_max)` as f32 with the
//! range clipped to where the bounding sphere can be (32 bytes a ray); the f32 kernel's
//! records (read); the torus in f64 (centre, the rotation's columns, R, 1/R, r/R,
//! 1 − (r/R)², 1 + r/R: 136 bytes); and the finished records, which the host fills with
//! an instruction per ray ([`Instruction`], word 7) and the pass overwrites with
//! `(t, n.xyz)` and `(point.xyz, status)` ([`Status`]), rounded once from f64 as the
//! CPU's [`crate::Hit`] is. Both passes go in one command buffer: the host reads back
//! once.

use super::GpuError;
use super::finish_words::{Instruction, Status};
use crate::Torus;
use crate::certified::{F32Hit, F32Verdict};
use crate::intersect::Hit;
use glam::Vec3;

/// The f64 pass compiled on a device with `SHADER_F64`.
pub(crate) struct FinishPipeline {
    pub(crate) pipeline: wgpu::ComputePipeline,
    pub(crate) layout: wgpu::BindGroupLayout,
}

/// The pass's own buffers, beside the kernel's ([`super::Buffers`]).
pub(crate) struct FinishBuffers {
    pub(crate) world: wgpu::Buffer,
    pub(crate) torus: wgpu::Buffer,
    pub(crate) finished: wgpu::Buffer,
    pub(crate) staging: wgpu::Buffer,
    pub(crate) bind_group: wgpu::BindGroup,
}

/// What the f64 pass reads of one dispatch, beside the kernel's own buffers: the torus
/// in f64 ([`torus_bytes`]) and each ray's world and instruction records
/// ([`world_record`]).
pub(crate) struct FinishInput<'a> {
    pub(crate) torus: &'a [u8],
    pub(crate) world: &'a [[f32; 8]],
    pub(crate) instructions: &'a [[f32; 8]],
}

/// Bytes of the torus in f64: 17 values.
pub(crate) const TORUS64_BYTES: u64 = 17 * 8;

impl FinishPipeline {
    /// Compiles the pass; `None` with the reason where the device refuses it.
    pub(crate) async fn new(device: &wgpu::Device) -> Result<FinishPipeline, GpuError> {
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        use wgpu::BufferBindingType as B;
        let (pipeline, layout) = super::compute_pipeline(
            device,
            "torus-cull f64 finish",
            super::finish_source(),
            &[
                B::Storage { read_only: true },
                B::Storage { read_only: true },
                B::Storage { read_only: true },
                B::Storage { read_only: true },
                B::Storage { read_only: false },
            ],
            "finish_main",
        );
        if let Some(e) = scope.pop().await {
            return Err(GpuError::Kernel(format!("the f64 finish pass: {e}")));
        }
        Ok(FinishPipeline { pipeline, layout })
    }

    /// The pass's buffers for `rays` rays a dispatch, bound beside the kernel's parameter
    /// block `params` and result buffer `verdicts`.
    pub(crate) fn buffers(
        &self,
        device: &wgpu::Device,
        rays: usize,
        params: &wgpu::Buffer,
        verdicts: &wgpu::Buffer,
    ) -> FinishBuffers {
        let size = rays as u64 * super::RAY_BYTES;
        let buffer = |label, size, usage| super::dispatch::buffer(device, label, size, usage);
        use wgpu::BufferUsages as Use;
        let world = buffer("torus-cull world rays", size, Use::STORAGE | Use::COPY_DST);
        let torus = buffer(
            "torus-cull torus f64",
            TORUS64_BYTES,
            Use::STORAGE | Use::COPY_DST,
        );
        let finished = buffer(
            "torus-cull finished",
            size,
            Use::STORAGE | Use::COPY_DST | Use::COPY_SRC,
        );
        let staging = buffer(
            "torus-cull finished staging",
            size,
            Use::MAP_READ | Use::COPY_DST,
        );
        let bind_group = super::dispatch::bind_group(
            device,
            &self.layout,
            "torus-cull f64 finish bind group",
            &[params, &world, verdicts, &torus, &finished],
        );
        FinishBuffers {
            world,
            torus,
            finished,
            staging,
            bind_group,
        }
    }
}

/// The torus as the pass reads it: centre, the columns of the world → torus rotation,
/// R, 1/R, r/R, 1 − (r/R)², 1 + r/R (the CPU's `Tube`), as little-endian f64.
pub(crate) fn torus_bytes(torus: &Torus) -> Vec<u8> {
    torus_values(torus)
        .iter()
        .flat_map(|v| v.to_le_bytes())
        .collect()
}

/// [`torus_bytes`]'s 17 values.
pub(crate) fn torus_values(torus: &Torus) -> [f64; 17] {
    let c = torus.center_f64();
    let m = torus.to_local_rotation_f64();
    let tube = torus.tube();
    [
        c.x,
        c.y,
        c.z,
        m.x_axis.x,
        m.x_axis.y,
        m.x_axis.z,
        m.y_axis.x,
        m.y_axis.y,
        m.y_axis.z,
        m.z_axis.x,
        m.z_axis.y,
        m.z_axis.z,
        tube.major,
        tube.inv_major,
        tube.minor_rel,
        tube.k,
        tube.outer,
    ]
}

/// One ray's world record and the host's instruction: `(o, t_min, d, t_max)` with the
/// range clipped to `|t| ≤ L = (|o − c| + 4(R + r))/|d|` (no root lies beyond, so no
/// answer changes, and the pass sees no infinity), and what the pass is to do with it,
/// from the host's own answer for the f32 kernel ([`super::Frame::prepare`]'s `host`).
pub(crate) fn world_record(
    torus: &Torus,
    ray: &crate::Ray,
    host: Option<(F32Verdict, Option<super::Escalation>)>,
) -> ([f32; 8], Instruction) {
    let (o, d) = (ray.origin(), ray.dir());
    let reach = ((o.as_dvec3() - torus.center_f64()).length()
        + 4.0 * (torus.major_radius_f64() + torus.minor_radius_f64()))
        / d.as_dvec3().length()
        * (1.0 + 1e-6);
    // NaN (no such ray: its parts are finite) would go to the host too.
    let clippable = reach < f64::from(f32::MAX);
    let instruction = match (clippable, ray.starts_on_surface(), host) {
        (false, _, _) => Instruction::Host,
        // A ray not from the surface has a host answer only where its origin is too far
        // for the f32 kernel (`Escalation::FarOrigin`): the kernel proves nothing of it.
        (true, false, None) => Instruction::Follow,
        (true, false, Some(_)) => Instruction::Always,
        // The kernel has the literal ray past the origin's root (`Frame::prepare`).
        (true, true, None) => Instruction::SurfaceFollow,
        // Into the tube, or a far origin: the host sent nothing the kernel could prove.
        (true, true, Some((F32Verdict::Escalate, _))) => Instruction::SurfaceAlways,
        // The host proved it (a range that ends first).
        (true, true, Some(_)) => Instruction::Host,
    };
    let limit = if clippable { reach as f32 } else { f32::MAX };
    let t_min = ray.t_min().clamp(-limit, limit);
    let t_max = ray.t_max().clamp(-limit, limit);
    ([o.x, o.y, o.z, t_min, d.x, d.y, d.z, t_max], instruction)
}

/// The finished record the host uploads for one ray: its instruction in word 7.
pub(crate) fn instruction_record(instruction: Instruction) -> [f32; 8] {
    let mut finished = [0.0; 8];
    finished[7] = instruction as u32 as f32;
    finished
}

/// One escalated ray's answer from its finished record: the device's, or `None` where
/// the host must finish it.
pub(crate) fn device_answer(record: [f32; 8]) -> Option<F32Hit> {
    let hit = |front_face| {
        Some(Hit {
            t: record[0],
            normal: Vec3::new(record[1], record[2], record[3]),
            point: Vec3::new(record[4], record[5], record[6]),
            front_face,
        })
    };
    let hit = match Status::of(record[7])? {
        Status::Front => hit(true),
        Status::Back => hit(false),
        Status::Miss => None,
        Status::Proved | Status::Host => return None,
    };
    Some(F32Hit {
        hit,
        escalated: true,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_record_decodes_to_the_device_answer_or_the_host() {
        let mut record = [
            2.5,
            0.0,
            1.0,
            0.0,
            1.0,
            2.0,
            3.0,
            Status::Front as u32 as f32,
        ];
        let answer = device_answer(record).expect("a device hit");
        let hit = answer.hit.expect("a hit");
        assert!(answer.escalated && hit.front_face && hit.t == 2.5);
        assert_eq!(hit.point, Vec3::new(1.0, 2.0, 3.0));
        record[7] = Status::Miss as u32 as f32;
        assert_eq!(device_answer(record).map(|a| a.hit), Some(None));
        for host in [Status::Host, Status::Proved] {
            record[7] = host as u32 as f32;
            assert_eq!(device_answer(record), None);
        }
        record[7] = 9.0;
        assert_eq!(
            device_answer(record),
            None,
            "an unknown status goes to the host"
        );
    }
}
