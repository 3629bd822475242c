//! Line families built to break a quartic solver, in the torus frame (centre 0, axis +y),
//! as `(point, unit direction)` in f64. The tests and the solver bench draw from them.
//!
//! - [`hole_edge_line`]: in a plane parallel to the axis at `a = (R − r) ± ε·r` with
//!   ε log-uniform in [1e-5, 1e-1] (inside the tube 3 times in 4), small slopes and lifts.
//!   Its quartic has two real roots and a near-double complex pair (or four real roots
//!   with a close pair): where a Ferrari resolvent taken in `ξ = (m² + p)/2` loses `m²`.
//! - [`tangent_line`]: tangent at a random point of one of the four special circles
//!   ([`SpecialCircle`]) in a random tangent direction, pushed along the outward normal by
//!   `δ·r` (δ < 0 enters the tube: a near-double pair of real roots; δ > 0 misses).

use glam::{DVec3, Vec3};
use rand::{Rng, RngExt};
use torus_cull::{Ray, Torus};

/// The circles of the torus where tangent lines are hardest: the equators, where the
/// section is a circle of radius r around a tube point, and the top and bottom circles,
/// where the Gaussian curvature is 0 and a line along the circle has a contact of order 4.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpecialCircle {
    /// ρ = R − r, y = 0 (the hole's edge); the outward normal points to the axis.
    InnerEquator,
    /// ρ = R + r, y = 0.
    OuterEquator,
    /// ρ = R, y = r.
    Top,
    /// ρ = R, y = −r.
    Bottom,
}

impl SpecialCircle {
    /// All four, in a fixed order.
    pub const ALL: [SpecialCircle; 4] = [
        SpecialCircle::InnerEquator,
        SpecialCircle::OuterEquator,
        SpecialCircle::Top,
        SpecialCircle::Bottom,
    ];

    /// The stable name.
    pub fn name(self) -> &'static str {
        match self {
            SpecialCircle::InnerEquator => "inner_equator",
            SpecialCircle::OuterEquator => "outer_equator",
            SpecialCircle::Top => "top",
            SpecialCircle::Bottom => "bottom",
        }
    }

    /// The point at azimuth `radial` (unit, horizontal), its outward normal, and the
    /// tangent of the meridian section there.
    fn frame(self, major: f64, minor: f64, radial: DVec3) -> (DVec3, DVec3, DVec3) {
        match self {
            SpecialCircle::InnerEquator => (radial * (major - minor), -radial, DVec3::Y),
            SpecialCircle::OuterEquator => (radial * (major + minor), radial, DVec3::Y),
            SpecialCircle::Top => (radial * major + DVec3::Y * minor, DVec3::Y, radial),
            SpecialCircle::Bottom => (radial * major - DVec3::Y * minor, -DVec3::Y, radial),
        }
    }
}

/// A torus of radii R = `major`, r = `minor` at a random world pose: axis uniform on the
/// sphere, centre uniform in the cube of half-side 3R around the origin.
pub fn random_pose_torus(rng: &mut rand_pcg::Pcg64, major: f32, minor: f32) -> Torus {
    let axis = super::unit_vector(rng).as_vec3();
    let center = Vec3::new(
        rng.random_range(-3.0..3.0),
        rng.random_range(-3.0..3.0),
        rng.random_range(-3.0..3.0),
    ) * major;
    Torus::new(center, axis, major, minor).expect("valid radii at any pose")
}

/// The horizontal unit vectors at a random azimuth: radial ρ̂ and along the circle φ̂.
pub fn random_azimuth(rng: &mut impl Rng) -> (DVec3, DVec3) {
    let phi: f64 = rng.random_range(0.0..std::f64::consts::TAU);
    let (s, c) = phi.sin_cos();
    (DVec3::new(c, 0.0, s), DVec3::new(-s, 0.0, c))
}

fn random_sign(rng: &mut impl Rng) -> f64 {
    if rng.random_bool(0.5) { 1.0 } else { -1.0 }
}

/// A line hugging the hole's edge (see the module docs).
pub fn hole_edge_line(rng: &mut impl Rng, major: f64, minor: f64) -> (DVec3, DVec3) {
    let eps = 10f64.powf(rng.random_range(-5.0..-1.0));
    let side = if rng.random_bool(0.75) { 1.0 } else { -1.0 };
    let a = (major - minor) + side * eps * minor;
    let (radial, along) = random_azimuth(rng);
    let slope = if rng.random_bool(0.2) {
        0.0
    } else {
        10f64.powf(rng.random_range(-5.0..-1.0)) * random_sign(rng)
    };
    let lift = minor * rng.random_range(-1.0..1.0) * 10f64.powf(rng.random_range(-4.0..0.0));
    let shift = rng.random_range(-0.5..0.5) * major;
    let point = radial * a + along * shift + DVec3::Y * lift;
    (point, (along + DVec3::Y * slope).normalize())
}

/// A line tangent to `circle` pushed out along the normal by `delta·r` (see the module
/// docs). The tangent direction is along the circle, along the meridian, or random
/// between, one time in four, four and two.
pub fn tangent_line(
    rng: &mut impl Rng,
    major: f64,
    minor: f64,
    circle: SpecialCircle,
    delta: f64,
) -> (DVec3, DVec3) {
    let (radial, along) = random_azimuth(rng);
    let (point, normal, meridian) = circle.frame(major, minor, radial);
    let alpha: f64 = match rng.random_range(0..4) {
        0 => 0.0,
        1 => std::f64::consts::FRAC_PI_2,
        _ => rng.random_range(0.0..std::f64::consts::PI),
    };
    let dir = along * alpha.cos() + meridian * alpha.sin();
    (point + normal * (delta * minor), dir.normalize())
}

/// Offsets δ (× r) of [`LineFamily::Tangent`], where a solver's accuracy goal applies.
pub const TANGENT_OFFSETS: [f64; 6] = [1e-6, -1e-6, 1e-5, -1e-5, 1e-4, -1e-4];

/// Offsets of [`LineFamily::TangentLimit`], closer than 1e-7·r: f64 conditioning sets the
/// error there.
pub const TANGENT_LIMIT_OFFSETS: [f64; 6] = [1e-7, -1e-7, 1e-8, -1e-8, 1e-9, -1e-9];

/// The adversarial line families the solvers are measured and tested on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineFamily {
    /// [`hole_edge_line`]s.
    HoleEdge,
    /// [`tangent_line`]s, the four circles in turn, offsets cycling through
    /// [`TANGENT_OFFSETS`].
    Tangent,
    /// The same with [`TANGENT_LIMIT_OFFSETS`].
    TangentLimit,
}

/// `count` lines of `family` on the canonical torus R = 1, r = 1/ν, as rays starting
/// 3·(R + r) back along each line (the rays a line's f32 rounding refuses are left out).
pub fn family_rays(
    family: LineFamily,
    nu: f64,
    count: usize,
    rng: &mut rand_pcg::Pcg64,
) -> (Torus, Vec<Ray>) {
    let torus = Torus::canonical(1.0, (1.0 / nu) as f32).expect("nu > 1");
    let (big, small) = (1.0, f64::from(torus.minor_radius()));
    let rays = (0..count)
        .filter_map(|i| {
            let (p, d) = match family {
                LineFamily::HoleEdge => hole_edge_line(rng, big, small),
                LineFamily::Tangent | LineFamily::TangentLimit => {
                    let offsets = if family == LineFamily::Tangent {
                        &TANGENT_OFFSETS
                    } else {
                        &TANGENT_LIMIT_OFFSETS
                    };
                    let circle = SpecialCircle::ALL[i % 4];
                    tangent_line(rng, big, small, circle, offsets[(i / 4) % 6])
                }
            };
            let o = p - d * 3.0 * (big + small);
            Ray::new(o.as_vec3(), d.as_vec3()).ok()
        })
        .collect();
    (torus, rays)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    /// Distance from a point to the core circle minus r: the signed distance to the tube.
    fn tube_distance(major: f64, minor: f64, x: DVec3) -> f64 {
        let rho = (x.x * x.x + x.z * x.z).sqrt();
        (rho - major).hypot(x.y) - minor
    }

    #[test]
    fn tangent_lines_touch_at_the_requested_offset() {
        let mut rng = rand_pcg::Pcg64::seed_from_u64(5);
        for circle in SpecialCircle::ALL {
            for delta in [1e-3, -1e-3] {
                let (p, d) = tangent_line(&mut rng, 2.0, 0.5, circle, delta);
                assert!((d.length() - 1.0).abs() < 1e-12);
                // The point is δ·r off the surface, and the line is tangent there: moving
                // along it changes the distance only to second order.
                let g = tube_distance(2.0, 0.5, p);
                assert!((g - delta * 0.5).abs() < 1e-12, "{circle:?}: {g}");
                let h = 1e-4;
                let slope = (tube_distance(2.0, 0.5, p + d * h)
                    - tube_distance(2.0, 0.5, p - d * h))
                    / (2.0 * h);
                assert!(slope.abs() < 1e-3, "{circle:?}: slope {slope}");
            }
        }
    }

    #[test]
    fn hole_edge_lines_pass_the_hole_edge() {
        let mut rng = rand_pcg::Pcg64::seed_from_u64(6);
        let (big, small) = (1.0, 1.0 / 1.2);
        for _ in 0..1000 {
            let (p, d) = hole_edge_line(&mut rng, big, small);
            // Distance of the line's projection from the axis.
            let h = DVec3::new(d.x, 0.0, d.z);
            let a = (p.x * d.z - p.z * d.x).abs() / h.length();
            assert!((a - (big - small)).abs() <= 0.1 * small + 1e-12, "{a}");
        }
    }
}
