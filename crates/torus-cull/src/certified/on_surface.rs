//! The certified f32 path for rays from a surface point ([`Ray::from_surface`]) that
//! leave into the outside: the literal certificate, started past the origin's own root.
//!
//! **The lemma** (docs/math.md §9). Let `G(t) = g(o + t·d̂)` with `g` the signed distance
//! from the tube (`g = h − r`, `h` the distance from the core circle; negative inside),
//! `c = d̂·∇g(o)`, and `m = min(h(o), ρ(o))` (ρ the distance from the axis). `g`'s
//! Hessian has the eigenvalues 0, 1/h and (ρ − R)/(ρ·h), so its norm is at most
//! max(1/h, 1/ρ); both h and ρ are 1-Lipschitz, so along `[0, t]` the norm is at most
//! 1/(m − t) and `G′(t) ≥ c − t/(m − t)`. For `c > 0` that is positive on
//! `[0, c·m/(1 + c))`, which holds `[0, 1.5·t*]` with `t* = c·m/3` (c ≤ 1, so a start
//! rounded up by an ulp stays inside): `G` is strictly
//! increasing there, so `[0, t*]` holds at most one root, the origin's own (an
//! inside-to-outside crossing, or none if the origin lies just outside).
//!
//! **The literal origin must agree with the surface point.** The f64 path solves from the
//! origin moved onto the surface (`intersect::from_surface`); the literal line is that
//! line moved by the origin's offset `e = g(o)` along the normal. On `[0, t*]`,
//! `G′ ≥ c − c/(3 − c) ≥ c/2`, so the moved line is at least `c²m/6` outside at `t*`; where
//! that exceeds `|e|` (with the margin), the literal line is outside there too, and both
//! have left the origin: no crossing near the origin (a saddle's re-hit, which the literal
//! line misses when its excursion is below `|e|`) is lost. Closer to the tangent plane
//! there is no such start: the cubic or f64 answers.
//!
//! Hence the first crossing after the origin's own, in the range, is the literal ray's
//! first root in `[max(t_min, t*), t_max]`, and the literal certificate proves it (with
//! `F > 0` from the start of that range, which also proves that the origin's own root lies
//! before it) or escalates. A range that ends before `t*` holds no crossing but the
//! origin's: a miss. `c`, `h` and `ρ` are formed in f64 from the ray as given (its f32
//! origin, not a projected one), with a relative margin of 10⁻⁹ for their rounding.
//!
//! A ray into the tube (`c ≤ 0`), or one that leaves too close to the tangent plane for
//! the margin, has no such start and escalates.

use crate::intersect::from_surface::starts_on_the_surface;
use crate::{Ray, Torus};
use glam::DVec3;

/// Relative margin on `c` and `m` for their f64 rounding and the f64 frame's.
const MARGIN: f64 = 1e-9;

/// What the on-surface f32 path does with a ray from a surface point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Start {
    /// Certify the literal ray over this range: its first root is the first crossing
    /// after the origin's own.
    Literal(Ray),
    /// The range ends before any crossing but the origin's: a miss, proved.
    Miss,
    /// No proved start: the f64 path answers.
    Escalate,
}

/// `t*` in units of the ray's `t` for a line from a surface point, in the torus's world
/// frame (f64): the end of the stretch where the only root is the origin's own; `None`
/// when the ray does not leave into the outside by a margin. `Some(0)` for an origin too
/// far off the surface to be a surface point, which the f64 path answers as a literal ray
/// ([`starts_on_the_surface`]), and so does this one.
#[must_use]
pub(crate) fn clear_start(torus: &Torus, origin: DVec3, dir: DVec3) -> Option<f64> {
    let to_local = torus.to_local_rotation_f64();
    let o = to_local * (origin - torus.center_f64());
    let d = to_local * dir;
    if !starts_on_the_surface(torus.tube(), o) {
        return Some(0.0);
    }
    let rho = o.x.hypot(o.z);
    let major = torus.major_radius_f64();
    if rho.is_nan() || rho <= 0.0 {
        return None;
    }
    let core = DVec3::new(o.x, 0.0, o.z) * (major / rho);
    let off = o - core;
    let h = off.length();
    let len = d.length();
    if !(h > 0.0 && len > 0.0 && h.is_finite() && len.is_finite()) {
        return None;
    }
    let c = off.dot(d) / (h * len) - MARGIN;
    let m = h.min(rho) * (1.0 - MARGIN);
    if !(c > MARGIN && c <= 1.0 + MARGIN) {
        return None;
    }
    // The literal origin's offset from the surface, below what the line rises by t*.
    let offset = (h - torus.minor_radius_f64()).abs() + MARGIN * (h + rho);
    if c * c * m / 6.0 <= offset {
        return None;
    }
    let t_star = c.min(1.0) * m / 3.0 / len;
    (t_star.is_finite() && t_star > 0.0).then_some(t_star)
}

/// The literal ray the certificate proves for `ray` (from a surface point), or the
/// answer when there is nothing left to prove.
#[must_use]
pub(crate) fn start(torus: &Torus, ray: &Ray) -> Start {
    let (o, d) = (ray.origin().as_dvec3(), ray.dir().as_dvec3());
    let Some(t_star) = clear_start(torus, o, d) else {
        return Start::Escalate;
    };
    if t_star == 0.0 {
        return match Ray::with_range(ray.origin(), ray.dir(), ray.t_min(), ray.t_max()) {
            Ok(literal) => Start::Literal(literal),
            Err(_) => Start::Escalate,
        };
    }
    // Rounded down: any start in (0, t*] keeps the lemma (t* is positive and finite).
    let mut from = t_star as f32;
    if from == 0.0 || from.is_infinite() {
        return Start::Escalate;
    }
    if f64::from(from) > t_star {
        from = f32::from_bits(from.to_bits() - 1); // one ulp down, still positive or 0
    }
    if from == 0.0 {
        return Start::Escalate;
    }
    let t_min = ray.t_min().max(from);
    if t_min > ray.t_max() {
        return Start::Miss;
    }
    match Ray::with_range(ray.origin(), ray.dir(), t_min, ray.t_max()) {
        Ok(literal) => Start::Literal(literal),
        Err(_) => Start::Escalate,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    #[test]
    fn outward_rays_start_past_their_origin_and_inward_ones_escalate() {
        let torus = Torus::canonical(4.0, 1.0).expect("torus");
        // From the top of the tube: straight up, c = 1, m = min(1, 4) → t* = 1/3.
        let up = Ray::from_surface(Vec3::new(4.0, 1.0, 0.0), Vec3::Y).expect("ray");
        let Start::Literal(literal) = start(&torus, &up) else {
            panic!("an outward ray has a start");
        };
        assert!(!literal.starts_on_surface());
        assert!((literal.t_min() - 1.0 / 3.0).abs() < 1e-6 && literal.t_min() <= 1.0 / 3.0);
        // Scaled direction: t* in units of t.
        let up2 = Ray::from_surface(Vec3::new(4.0, 1.0, 0.0), Vec3::Y * 2.0).expect("ray");
        let Start::Literal(literal) = start(&torus, &up2) else {
            panic!("an outward ray has a start");
        };
        assert!((literal.t_min() - 1.0 / 6.0).abs() < 1e-6);
        // A range inside [0, t*]: nothing but the origin.
        assert_eq!(start(&torus, &up.with_t_max(0.3).unwrap()), Start::Miss);
        // Into the tube, or along the tangent plane: no start.
        let down = Ray::from_surface(Vec3::new(4.0, 1.0, 0.0), Vec3::NEG_Y).expect("ray");
        assert_eq!(start(&torus, &down), Start::Escalate);
        let along = Ray::from_surface(Vec3::new(4.0, 1.0, 0.0), Vec3::X).expect("ray");
        assert_eq!(start(&torus, &along), Start::Escalate);
        // From the inner equator across the hole: c = 1, m = min(1, 3).
        let across = Ray::from_surface(Vec3::new(3.0, 0.0, 0.0), Vec3::NEG_X).expect("ray");
        let Start::Literal(literal) = start(&torus, &across) else {
            panic!("across the hole has a start");
        };
        assert!((literal.t_min() - 1.0 / 3.0).abs() < 1e-6);
        // An origin 0.5·R off the surface is no surface point: the literal ray, as f64.
        let off = Ray::from_surface(Vec3::new(4.0, 3.0, 0.0), Vec3::NEG_Y).expect("ray");
        let Start::Literal(literal) = start(&torus, &off) else {
            panic!("answered as a literal ray");
        };
        assert_eq!((literal.t_min(), literal.starts_on_surface()), (0.0, false));
    }
}
