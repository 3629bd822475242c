//! Paired timing for the torus family (`torus_cull::family::Toroid`): what an elliptical
//! tube or a spindle costs against the circular torus, and each cull's `total_ns` against
//! `cychosz` on the member ([`super::shapes`]).
//!
//! Contenders, one pass each over the same rays per round: the circular member (R, a, a)'s
//! exact intersection on the same rays, the same on the rays' images (y scaled by a/b:
//! the lines the member's own solve sees, so the ratio to it is the family path's
//! overhead alone, the geometry factored out), the member's exact intersection, and the
//! member behind each cull of the table ([`CullKind::TIMED`]; a cull that does not accept
//! the member's shape is declined, so it costs the exact intersection alone).

use super::engine::timed_pass;
use super::shapes::{CulledPass, Pair, ShapeRatio, TimedShape, time_contenders};
use std::time::Duration;
use torus_cull::family::Toroid;
use torus_cull::{Cull, CullKind, Ray};

/// The members `time family` and `cargo bench` time, (R, a, b) with a = 1: the
/// elliptical ring tube at ν = R/a = 4 with b/a = 1/4, 1/2, 1, 2, 4, the horn torus, and
/// the spindle at R/a = 3/4 with b/a = 1 and 2.
pub const MEMBERS: [(f64, f64, f64); 8] = [
    (4.0, 1.0, 0.25),
    (4.0, 1.0, 0.5),
    (4.0, 1.0, 1.0),
    (4.0, 1.0, 2.0),
    (4.0, 1.0, 4.0),
    (1.0, 1.0, 1.0),
    (0.75, 1.0, 1.0),
    (0.75, 1.0, 2.0),
];

/// The members of [`MEMBERS`], as [`super::shapes::shape_records`] times them.
///
/// # Errors
///
/// An invalid member, named.
pub fn members() -> Result<Vec<Toroid>, String> {
    MEMBERS
        .iter()
        .map(|&(big, a, b)| Toroid::canonical(big, a, b))
        .collect::<Result<_, _>>()
        .map_err(|e| e.to_string())
}

/// The family's ratios for `member` (in its own frame: centre 0, axis +y) on `rays`:
/// its exact intersection over the circular member (R, a, a)'s on the same rays and on
/// their images, and each cull's total over `cychosz`'s, from `runs` runs of about
/// `seconds` each. `None` for an empty ray set, a posed member or a run without rounds.
impl TimedShape for Toroid {
    const METRIC: &'static str = "family_total_ns";

    fn box_radii(&self) -> (f64, f64, f64) {
        let a = self.radial_semi_axis_f64();
        (self.major_radius_f64(), a, self.axial_semi_axis_f64())
    }

    /// A member's case in a results file: `family_<kind>_b<b/a>` (`family_ring_b0.25`,
    /// `family_spindle_b2`); its ν field is R/a.
    fn case_name(&self) -> String {
        let kind = format!("{:?}", self.kind()).to_lowercase();
        let aspect = self.axial_semi_axis_f64() / self.radial_semi_axis_f64();
        format!("family_{kind}_b{aspect}")
    }

    #[inline(always)]
    fn hit_culled<C: Cull>(&self, cull: &C, ray: &Ray) -> bool {
        self.intersect_culled(cull, ray).is_some()
    }

    fn ratios(&self, rays: &[Ray], timing: (usize, f64, u64)) -> Option<Vec<ShapeRatio>> {
        let own_frame = self.center_f64() == glam::DVec3::ZERO && self.axis_f64() == glam::DVec3::Y;
        if !own_frame {
            return None;
        }
        let a = self.radial_semi_axis_f64();
        let circular = Toroid::canonical(self.major_radius_f64(), a, a).ok()?;
        let scale = glam::Vec3::new(1.0, (a / self.axial_semi_axis_f64()) as f32, 1.0);
        let images: Vec<Ray> = rays
            .iter()
            .map(|r| Ray::with_range(r.origin() * scale, r.dir() * scale, r.t_min(), r.t_max()))
            .collect::<Result<_, _>>()
            .ok()?;
        // Contenders 0: the circular exact; 1: the same on the images; 2: the member's
        // exact; 3..: each cull's total on the member.
        let culls = CullKind::TIMED;
        let cychosz = 3 + culls.iter().position(|&k| k == CullKind::Cychosz)?;
        let name = |s: &str| s.to_string();
        let mut pairs: Vec<Pair> = vec![
            (2, 0, name("exact"), name("circular_exact")),
            (2, 1, name("exact"), name("circular_exact_on_images")),
        ];
        for (i, kind) in culls.iter().enumerate() {
            pairs.push((3 + i, cychosz, name(kind.name()), name("cychosz")));
        }
        time_contenders(3 + culls.len(), pairs, timing, rays.len(), |_| {
            let (rays, images) = (rays.to_vec(), images.clone());
            move |i| match i {
                0 => exact_pass(&circular, &rays),
                1 => exact_pass(&circular, &images),
                2 => exact_pass(self, &rays),
                _ => culls[i - 3].visit(CulledPass {
                    shape: self,
                    rays: &rays,
                }),
            }
        })
    }
}

/// One timed pass of the member's exact intersection over the rays.
#[inline(never)]
fn exact_pass(member: &Toroid, rays: &[Ray]) -> Duration {
    timed_pass(rays, |ray, (): &mut ()| member.intersect(ray).is_some())
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    /// The records come out complete and finite at a tiny size (speed is the bench's).
    #[test]
    fn every_cull_and_the_exact_ratios_are_reported() {
        let member = Toroid::canonical(4.0, 1.0, 0.5).unwrap();
        let rays: Vec<Ray> = (0..64)
            .map(|i| {
                let a = i as f32 * 0.1;
                let o = Vec3::new(10.0 * a.cos(), 2.0, 10.0 * a.sin());
                Ray::new(o, Vec3::new(-a.cos(), -0.2, -a.sin())).unwrap()
            })
            .collect();
        let got = member.ratios(&rays, (2, 0.05, 7)).unwrap();
        assert_eq!(got.len(), 2 + CullKind::TIMED.len());
        let first = (got[0].contender.as_str(), got[0].reference.as_str());
        assert_eq!(first, ("exact", "circular_exact"));
        for r in &got {
            assert!(r.ratio.is_finite() && r.ratio > 0.0, "{r:?}");
            assert_eq!(r.run_ratios.len(), 2);
            assert!(r.between.is_some(), "{r:?}");
        }
    }
}
