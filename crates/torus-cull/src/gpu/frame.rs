//! The frame: the torus as the kernel's parameter block ([`Frame`], its params) and a ray
//! packed for the kernel ([`Frame::prepare`], [`Frame::pack`]): the centre subtracted in
//! f64, far origins moved to their foot point, surface rays with their cubic formed in f64
//! (and started past their own root where the cubic proves nothing).

use super::wire::{SURFACE_CUBIC, SURFACE_CUBIC_AND_START, SURFACE_NONE};
use super::{Escalation, GpuCull, Mode, PARAMS_BYTES, bounds};
use crate::certified::F32Verdict;
use crate::{Ray, Torus};
use glam::Vec3;

/// Origins farther than this many R from the centre (2²⁰) escalate without the kernel:
/// beyond, the f64 foot point's own error (about 10⁻¹⁵ of the distance) is no longer
/// negligible beside the kernel's line error bound.
const FAR_REL: f64 = 1_048_576.0;

/// Origins farther than this many (R + r) from the centre are moved to their line's foot
/// point on the host, in f64, before the kernel sees them (see [`Frame::pack`]).
pub(crate) const REBASE_REL: f64 = 2.0;

/// The torus as the kernel's parameter block, and what packing a ray needs of it (f64).
pub(crate) struct Frame {
    torus: Torus,
    rows: [Vec3; 3],
    /// The culls' bounds at R = 1 with the GPU's margin ([`bounds::kernel_bounds`]).
    bounds: [[f32; 4]; 3],
    major: f32,
    minor: f32,
    center: glam::DVec3,
    major_f64: f64,
    outer: f64,
}

/// A ray as the kernel reads it, and what the host adds back.
pub(crate) struct Packed {
    /// `(o − c, t_min − t0, d, t_max − t0)`, the range clipped (see [`Frame::pack`]).
    pub(crate) words: [f32; 8],
    /// How far along the ray the uploaded origin is: the kernel's t plus this is the ray's.
    pub(crate) t0: f64,
    /// Within [`FAR_REL`]·R of the centre: the kernel may answer.
    pub(crate) sendable: bool,
    /// The host's own answer, whatever `torus_intersect` writes ([`Frame::prepare`]; the
    /// library's kernel uses [`Packed::kernel_host`]).
    pub(crate) host: Option<(F32Verdict, Option<Escalation>)>,
    /// The ray's `TorusSurfaceRay` ([`Frame::prepare`]); `start.w` = 0 for a literal ray.
    pub(crate) surface: [f32; 16],
}

/// The host's answer `host` for `torus_intersect` as `torus_intersect_from_surface` reads
/// the ray with its surface record `surface`: none where the kernel proves the cubic.
pub(crate) fn kernel_host(
    host: Option<(F32Verdict, Option<Escalation>)>,
    surface: &[f32; 16],
) -> Option<(F32Verdict, Option<Escalation>)> {
    if surface[15] == SURFACE_CUBIC {
        None
    } else {
        host
    }
}

impl Packed {
    /// Whether the kernel reads this ray's surface record.
    pub(crate) fn has_surface(&self) -> bool {
        self.surface[15] != SURFACE_NONE
    }

    /// The host's own answer where the kernel reads the surface records
    /// (`torus_intersect_from_surface`): [`Packed::host`], but none for a ray whose cubic
    /// the kernel proves (the host escalates it only for `torus_intersect`).
    pub(crate) fn kernel_host(&self) -> Option<(F32Verdict, Option<Escalation>)> {
        kernel_host(self.host, &self.surface)
    }
}

impl Frame {
    pub(crate) fn of(torus: &Torus) -> Frame {
        let m = torus.to_local_rotation().transpose(); // columns of Mᵀ = rows of M
        let major_f64 = torus.major_radius_f64();
        let rr = (torus.minor_radius_f64() / major_f64) as f32;
        Frame {
            torus: *torus,
            rows: [m.x_axis, m.y_axis, m.z_axis],
            bounds: bounds::bounds_rows(&bounds::kernel_bounds(rr)),
            major: torus.major_radius(),
            minor: torus.minor_radius(),
            center: torus.center_f64(),
            major_f64,
            outer: major_f64 + torus.minor_radius_f64(),
        }
    }

    /// `ray` packed for the kernel ([`Frame::pack`]), with the host's own answer where it
    /// has one: an origin beyond [`FAR_REL`]·R escalates ([`Escalation::FarOrigin`]).
    ///
    /// A ray from a surface point goes as the CPU's certified path takes it
    /// (`certified::prove`). Its words are the literal ray past the origin's own root
    /// (`on_surface`), which `torus_intersect` may answer alone; its surface record holds
    /// the cubic left once that root is divided out (`surface_cubic`, formed in f64), and
    /// the ray's own `t_min`, for `torus_intersect_from_surface`, which tries the cubic
    /// first. The host answers a proved miss (the range ends before any other root), and
    /// escalates ([`Escalation::OnSurface`]) a ray with no start past its root: for
    /// `torus_intersect` always, for `torus_intersect_from_surface` only where it has no
    /// cubic either ([`Packed::kernel_host`]).
    pub(crate) fn prepare(&self, ray: &Ray) -> Packed {
        use crate::certified::on_surface::{Start, start};
        use crate::certified::surface_cubic::{Setup, setup};
        let mut surface = [0.0; 16];
        let escalate = Some((F32Verdict::Escalate, Some(Escalation::OnSurface)));
        let (sent, on_surface) = if ray.starts_on_surface() {
            let line = self.torus.line_to_local_f64(ray);
            let range = (f64::from(ray.t_min()), f64::from(ray.t_max()));
            let cubic = setup(&self.torus, line, range.0, range.1);
            let start = start(&self.torus, ray);
            if let Setup::Cubic(cubic) = cubic {
                surface[..14].copy_from_slice(&cubic.words());
                surface[14] = ray.t_min();
                surface[15] = match start {
                    Start::Literal(_) => SURFACE_CUBIC_AND_START,
                    _ => SURFACE_CUBIC,
                };
            }
            match (cubic, start) {
                (Setup::Miss, _) | (_, Start::Miss) => (*ray, Some((F32Verdict::Miss, None))),
                (_, Start::Literal(literal)) => (literal, None),
                (_, Start::Escalate) => (*ray, escalate),
            }
        } else {
            (*ray, None)
        };
        let mut packed = self.pack(&sent);
        // A surface point is within 2·(R + r) of the centre, so the origin is not moved
        // (t0 = 0) and the cubic's t is the kernel's.
        if packed.t0 == 0.0 && (on_surface.is_none() || on_surface == escalate) {
            packed.surface = surface;
        }
        packed.host = if packed.sendable {
            on_surface
        } else {
            Some((F32Verdict::Escalate, Some(Escalation::FarOrigin)))
        };
        packed
    }

    /// The parameter block: the torus ([`Frame::torus_params`]); the count, the cull, the
    /// mode, and whether the kernel reads the surface records.
    pub(crate) fn params(&self, count: u32, cull: GpuCull, mode: Mode, surfaces: bool) -> Vec<u8> {
        let mut bytes = Vec::with_capacity(PARAMS_BYTES as usize);
        for f in self.torus_params() {
            bytes.extend_from_slice(&f.to_le_bytes());
        }
        for u in [count, cull.code(), mode as u32, u32::from(surfaces)] {
            bytes.extend_from_slice(&u.to_le_bytes());
        }
        bytes
    }

    /// The module's `TorusParams`: rows of M with R, r, r/R; 1/R; the culls' bounds
    /// (three rows).
    pub(crate) fn torus_params(&self) -> [f32; 28] {
        let rr = (f64::from(self.minor) / self.major_f64) as f32;
        let inv_major = (1.0 / self.major_f64) as f32;
        let floats: [f32; 16] = [
            self.rows[0].x,
            self.rows[0].y,
            self.rows[0].z,
            self.major,
            self.rows[1].x,
            self.rows[1].y,
            self.rows[1].z,
            self.minor,
            self.rows[2].x,
            self.rows[2].y,
            self.rows[2].z,
            rr,
            inv_major,
            0.0,
            0.0,
            0.0,
        ];
        let mut out = [0.0; 28];
        for (o, f) in out
            .iter_mut()
            .zip(floats.into_iter().chain(self.bounds.into_iter().flatten()))
        {
            *o = f;
        }
        out
    }

    /// A ray as the kernel reads it.
    ///
    /// The origin goes relative to the centre, `o − c` formed in f64 and rounded once
    /// (the same value as an f32 subtraction on the device). An origin farther than
    /// [`REBASE_REL`]·(R + r) first moves along its line to the foot point, `t0 = −(o −
    /// c)·d/|d|²` (f64, as [`Torus::line_to_local`] does for the culls): the kernel's line
    /// error grows with the origin's distance, and from there it is that of a near ray.
    /// The range becomes `[t_min − t0, t_max − t0]`, clipped to `|t| ≤ T`, T = (|foot| +
    /// 4(R + r))/|d| rounded up: no point beyond is within the bounding sphere, so no
    /// root is lost, and the kernel's sums stay finite.
    pub(crate) fn pack(&self, ray: &Ray) -> Packed {
        let d = ray.dir().as_dvec3();
        let rel = ray.origin().as_dvec3() - self.center;
        let sendable = rel.length() <= FAR_REL * self.major_f64;
        let len_sq = d.length_squared();
        let t0 = if rel.length() > REBASE_REL * self.outer {
            -rel.dot(d) / len_sq
        } else {
            0.0
        };
        let start = rel + d * t0;
        let reach = (start.length() + 4.0 * self.outer) / len_sq.sqrt();
        let limit = (reach * (1.0 + 1e-6)).min(f64::from(f32::MAX));
        let t_min = (f64::from(ray.t_min()) - t0).clamp(-limit, limit) as f32;
        let t_max = (f64::from(ray.t_max()) - t0).clamp(-limit, limit) as f32;
        let (o, d) = (start.as_vec3(), ray.dir());
        Packed {
            words: [o.x, o.y, o.z, t_min, d.x, d.y, d.z, t_max],
            t0,
            sendable,
            host: None,
            surface: [0.0; 16],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_parameter_block_has_its_size() {
        let torus = Torus::canonical(4.0, 1.0).unwrap();
        let frame = Frame::of(&torus);
        let bytes = frame.params(7, GpuCull::Skala, Mode::CullOnly, false);
        assert_eq!(bytes.len() as u64, PARAMS_BYTES);
        let word = |k: usize| u32::from_le_bytes(bytes[4 * k..4 * k + 4].try_into().unwrap());
        // config = (count, cull, mode, 0), the last row.
        assert_eq!([word(28), word(29), word(30), word(31)], [7, 5, 1, 0]);
    }
}
