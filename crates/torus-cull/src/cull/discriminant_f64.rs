//! `discriminant_f64`: the `discriminant` cull's classification ([`super::discriminant`])
//! evaluated in f64, scalar only (it has no batch form and no GPU form).

use super::discriminant::no_real_root;
use super::kernel::Cull;
use super::CullBounds;
use crate::num::sc;
use glam::Vec3;

/// [`DiscriminantCull`](super::discriminant::DiscriminantCull) evaluated in f64 from the f32 line: same bound and padding, about
/// 2⁻²⁹ times the rounding of the f32 arithmetic (the f32 line itself, from the
/// world → torus transform, still needs the padding). Scalar only: it has no batch form.
#[derive(Debug, Clone, Copy, Default)]
pub struct DiscriminantF64Cull;

impl Cull for DiscriminantF64Cull {
    fn name(&self) -> &'static str {
        "discriminant_f64"
    }

    fn shapes(&self) -> &'static [crate::cull::Shape] {
        DiscriminantF64Cull::SHAPES
    }

    #[inline(always)]
    fn keeps(&self, b: &CullBounds, origin: Vec3, dir: Vec3) -> bool {
        let (o, d) = (origin.as_dvec3(), dir.as_dvec3());
        let m = o.cross(d);
        let inv_len_sq = 1.0 / d.length_squared();
        let f_sq = m.length_squared() * inv_len_sq;
        let f_y = (d.z * m.x - d.x * m.z) * inv_len_sq;
        let inside_sphere = f_sq <= f64::from(b.outer_safe_sq);
        let fy_sq = f_y * f_y * b.inv_major_sq_f64;
        let rho_sq = f_sq * b.inv_major_sq_f64 - fy_sq;
        let unit_y_sq = d.y * d.y * inv_len_sq;
        let rootless = no_real_root(sc(rho_sq), sc(fy_sq), sc(unit_y_sq), sc(b.minor_rel_sq_f64));
        inside_sphere & !rootless.m
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cull::DiscriminantCull;

    /// The verdict does not depend on how the direction is scaled, from 1e-19 (|d|² just
    /// above f32's smallest normal) to 1e19 (|d|² just below its largest).
    #[test]
    fn direction_scale_does_not_matter() {
        let b = CullBounds::new(4.0, 1.0);
        let lines = [
            (Vec3::new(0.5, 10.0, 0.0), Vec3::new(0.01, -1.0, 0.0)), // hole: rejected
            (Vec3::new(-9.0, 0.3, 3.9), Vec3::new(1.0, 0.0, 0.05)),  // tube: kept
            (Vec3::new(-30.0, 20.0, 5.0), Vec3::new(1.0, -0.6, -0.2)),
        ];
        for (o, d) in lines {
            let unit = (
                DiscriminantCull.keeps(&b, o, d),
                DiscriminantF64Cull.keeps(&b, o, d),
            );
            assert_eq!(unit.0, unit.1, "{o} {d}");
            for scale in [1e-19f32, 1e-12, 1e-6, 1e6, 1e12, 1e19] {
                let scaled = d * scale;
                assert_eq!(
                    DiscriminantCull.keeps(&b, o, scaled),
                    unit.0,
                    "{o} {scaled}"
                );
                assert_eq!(
                    DiscriminantF64Cull.keeps(&b, o, scaled),
                    unit.1,
                    "{o} {scaled}"
                );
            }
        }
    }

    #[test]
    fn rejects_the_hole_and_keeps_the_tube() {
        let b = CullBounds::new(4.0, 1.0);
        for cull in [&DiscriminantCull as &dyn Cull, &DiscriminantF64Cull] {
            // Straight down the hole, and down through the tube.
            assert!(!cull.keeps(&b, Vec3::new(0.5, 10.0, 0.0), Vec3::NEG_Y));
            assert!(cull.keeps(&b, Vec3::new(4.0, 10.0, 0.0), Vec3::NEG_Y));
            // Tangent to the outer equator (ambiguous: kept), and 1 % of r outside it.
            assert!(cull.keeps(&b, Vec3::new(5.0, 10.0, 0.0), Vec3::NEG_Y));
            assert!(!cull.keeps(&b, Vec3::new(5.01, 10.0, 0.0), Vec3::NEG_Y));
            // Far outside the sphere (the degree-12 terms would overflow in f32).
            assert!(!cull.keeps(&b, Vec3::new(1e30, 0.0, 0.0), Vec3::Y));
        }
    }
}
