//! The peer of the certified f32 path (issue 19): the plain f32 closed-form ray–torus
//! intersection as shader code does it, with no error bounds and no escalation.
//!
//! **Source.** The method is the one Inigo Quilez published for shaders ("Ray-Surface
//! Intersectors", <https://iquilezles.org/articles/intersectors/>, the torus entry, and
//! its Shadertoy <https://www.shadertoy.com/view/4sBGDy>): the torus quartic in the ray
//! parameter, depressed, reduced through Ferrari's resolvent cubic (solved in closed form:
//! Cardano with one real root, the trigonometric form with three), factored into two
//! quadratics, everything in f32. It is written here from that published math (the
//! algebra is re-derived below), not from its code. The published routine's safeguards
//! are kept because a shader using it has them: the bounding-sphere early-out, and the
//! switch to the quartic in `v = 2/t` when the depressed linear coefficient is near zero
//! (where the resolvent root nears zero and Ferrari's `Q/(2w)` is 0/0).
//!
//! **The math.** Torus frame (axis +y), unit direction `d̂`, origin `o`, and
//! `m = |o|²`, `n = o·d̂`, `k = (m − R² − r²)/2`. With `(|p|² + R² − r²)² − 4R²(px² + pz²)`
//! rewritten as `(|p|² − R² − r²)² − 4R²(r² − py²)`, the point `p = o + t d̂` gives
//!
//! `t⁴ + 4a t³ + 4b t² + 8c t + 4e = 0`, with `a = n`, `b = n² + k + R² d̂y²`,
//! `c = k n + R² oy d̂y`, `e = k² + R² oy² − R² r²`.
//!
//! `t = x − a` depresses it to `x⁴ + P x² + Q x + S` with `P = 4b − 6a²`,
//! `Q = 8(a(a² − b) + c)`, `S = 4e − 8ac + 4a²b − 3a⁴`. Ferrari: with `m = P/2 + y` and
//! `w = √(2y)`, `x⁴ + P x² + Q x + S = (x² + m)² − (w x − Q/(2w))²` exactly when `y` is a
//! root of the resolvent `y³ + P y² + (P²/4 − S) y − Q²/8 = 0`; the quartic is then the
//! product of `x² ± w x + m ∓ Q/(2w)`. The published routine solves the resolvent in
//! closed form (Cardano with one real root, the trigonometric form with three) and takes
//! its smallest real root: with three, it is positive when the quartic has four real
//! roots and negative (no real root: a miss) when it has none. When `|y| < 1e-4` it takes
//! `|Q/(2w)|` from its square `Q²/(8y) = m² − S` and keeps `y` in the place of `w/2`.
//! The quadratics' roots count only where their discriminant is > 0 (a tangency is not a
//! hit). When `|a(a² − b) + c| < 0.01` (`|Q|/8`, where `Q/(2w)` is 0/0) it solves the
//! quartic in `v = 2/t` instead, which has the same form with
//! `(a, b, c, e) → (c/e, b/e, a/e, 1/e)`.
//!
//! **Three choices, all in the peer's favour.** The published thresholds are absolute,
//! for a torus of unit size; the peer works in units of R (origin and r divided by R, `t`
//! multiplied back), so the scale sweep measures f32 and not the thresholds' units, and
//! f32's cube of the coefficients does not overflow at R = 1000. The `acos` argument is
//! clamped to [−1, 1] (GLSL leaves `acos(1 + ε)` undefined). And the published routine
//! has no `t_min` (it takes the smallest t > 0): the origin moves to `o + t_min·d` first,
//! as a shader offsets a shadow ray's origin, so that from a surface point the
//! quartic's constant term, which the reciprocal switch divides by, is not ~0.
//!
//! The ray goes to the torus frame in f32 (`to_local_rotation() * (o − c)`), as a shader
//! transforms it: not through [`Torus::line_to_local`], whose far-origin branch moves the
//! origin to the foot point in f64 (a help no shader has, and a change of `t`).

use glam::DVec3;
use std::ops::{Add, Div, Mul, Neg, Sub};
use torus_cull::{Ray, Torus};

/// The threshold below which the published routine switches to the `v = 2/t` quartic:
/// `|a(a² − b) + c|` (that is `|Q|/8`) in units of R³.
const RECIPROCAL_BELOW: f64 = 0.01;

/// The threshold below which `2y` counts as zero (the biquadratic case), units of R².
const BIQUADRATIC_BELOW: f64 = 1e-300;

/// The nearest `t ∈ [t_min, t_max]` (units of the ray's direction) where the ray meets the
/// torus, by the plain f32 closed form (see the module docs); `None` for a miss.
///
/// No error bound and no fallback: near tangencies, near the hole's edge and from far
/// origins it misses hits and reports hits that are not there. That is what it is for.
#[must_use]
pub fn intersect_peer_f32(torus: &Torus, ray: &Ray) -> Option<f32> {
    let rot = torus.to_local_rotation();
    let o = rot * (ray.origin() - torus.center());
    let d = rot * ray.dir();
    nearest(
        torus.major_radius(),
        torus.minor_radius(),
        o.to_array(),
        d.to_array(),
        ray.t_min(),
        ray.t_max(),
    )
}

/// The same closed form, every step in f64 (the ray moved to the torus frame in f64):
/// not a peer, but the proof that the peer's errors are f32's and not its algebra's.
#[must_use]
pub fn intersect_peer_f64(torus: &Torus, ray: &Ray) -> Option<f64> {
    let (o, d): (DVec3, DVec3) = torus.line_to_local_f64(ray);
    nearest(
        f64::from(torus.major_radius()),
        f64::from(torus.minor_radius()),
        o.to_array(),
        d.to_array(),
        f64::from(ray.t_min()),
        f64::from(ray.t_max()),
    )
}

/// The float type the closed form runs in: f32 (the peer) or f64 (its check).
trait Real:
    Copy
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    const NAN: Self;
    fn of(x: f64) -> Self;
    fn sqrt(self) -> Self;
    fn cbrt(self) -> Self;
    fn abs(self) -> Self;
    fn signum(self) -> Self;
    fn acos(self) -> Self;
    fn cos(self) -> Self;
    fn clamp(self, lo: Self, hi: Self) -> Self;
}

macro_rules! real {
    ($t:ty) => {
        impl Real for $t {
            const NAN: $t = <$t>::NAN;
            #[inline(always)]
            fn of(x: f64) -> $t {
                x as $t
            }
            #[inline(always)]
            fn clamp(self, lo: $t, hi: $t) -> $t {
                <$t>::clamp(self, lo, hi)
            }
            real!(@unary $t: sqrt, cbrt, abs, signum, acos, cos);
        }
    };
    // The one-argument methods, each the inherent method of the same name.
    (@unary $t:ty: $($f:ident),*) => {
        $(
            #[inline(always)]
            fn $f(self) -> $t {
                <$t>::$f(self)
            }
        )*
    };
}
real!(f32);
real!(f64);

fn dot<T: Real>(a: [T; 3], b: [T; 3]) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The closed form on the torus-frame line `o + t·d` (R = `major`, r = `minor`).
#[inline(always)]
fn nearest<T: Real>(major: T, minor: T, o: [T; 3], d: [T; 3], t_min: T, t_max: T) -> Option<T> {
    let (zero, one, two, half) = (T::of(0.0), T::of(1.0), T::of(2.0), T::of(0.5));
    let inv_major = one / major;
    let len = dot(d, d).sqrt();
    let dh = d.map(|x| x / len);
    let o = o.map(|x| x * inv_major);
    let rr = minor * inv_major;
    // t in units of R along d̂: t_ray = t·R/|d|.
    let scale = major / len;

    // The published routine intersects t > 0 from its origin; a ray's range starts at
    // t_min, so the origin moves there first (as a shader offsets a shadow ray's origin).
    // From an origin on the surface the quartic's constant term is ~0 and the routine's
    // reciprocal switch divides by it; from o + t_min·d it is not.
    let shift = t_min / scale;
    let o = [
        o[0] + shift * dh[0],
        o[1] + shift * dh[1],
        o[2] + shift * dh[2],
    ];
    let m = dot(o, o);
    let n = dot(o, dh);
    // The bounding sphere |p| ≤ 1 + rr.
    let outer = one + rr;
    if n * n - m + outer * outer < zero {
        return None;
    }
    let k = (m - rr * rr - one) * half;
    let a = n;
    let b = n * n + k + dh[1] * dh[1];
    let c = k * n + o[1] * dh[1];
    let e = k * k + o[1] * o[1] - rr * rr;

    let reciprocal = (a * (a * a - b) + c).abs() < T::of(RECIPROCAL_BELOW);
    let (a, b, c, e) = if reciprocal {
        let inv_e = one / e;
        (c * inv_e, b * inv_e, a * inv_e, inv_e)
    } else {
        (a, b, c, e)
    };
    let mut roots = [T::NAN; 4];
    depressed_roots(a, b, c, e, &mut roots);

    let mut best: Option<T> = None;
    for x in roots {
        let t = x - a;
        let t = if reciprocal { two / t } else { t };
        let t = t_min + t * scale;
        // NaN fails both comparisons.
        if t >= t_min && t <= t_max && best.is_none_or(|b| t < b) {
            best = Some(t);
        }
    }
    best
}

/// The real roots `x` of the depressed form of `t⁴ + 4a t³ + 4b t² + 8c t + 4e` (`t = x − a`)
/// into `out` (NaN where there is none), by Ferrari's resolvent with the published
/// routine's choices (see [`resolvent_root`]).
#[inline(always)]
fn depressed_roots<T: Real>(a: T, b: T, c: T, e: T, out: &mut [T; 4]) {
    let (zero, half) = (T::of(0.0), T::of(0.5));
    let (three, four, six, eight) = (T::of(3.0), T::of(4.0), T::of(6.0), T::of(8.0));
    let a2 = a * a;
    let big_p = four * b - six * a2;
    let big_q = eight * (a * (a2 - b) + c);
    let big_s = four * e - eight * a * c + four * a2 * b - three * a2 * a2;

    // x⁴ + P x² + Q x + S = (x² + m)² − (w x − Q/(2w))², m = P/2 + y, w = √(2y).
    let y = resolvent_root(big_p, big_q, big_s);
    let m = half * big_p + y;
    let (half_w, q_over_2w) = if y.abs() < T::of(BIQUADRATIC_BELOW) {
        // y ≈ 0: Q/(2w) from its square Q²/(8y) = m² − S (its sign is lost), and the
        // published routine keeps y itself in the place of w/2.
        let sq = m * m - big_s;
        if sq < zero {
            return;
        }
        (y, sq.sqrt())
    } else {
        // A negative y (the quartic has no real root) makes w imaginary: a miss.
        if y < zero {
            return;
        }
        let half_w = (half * y).sqrt();
        (half_w, big_q / (four * half_w))
    };
    // x² + w x + (m − Q/(2w)) and x² − w x + (m + Q/(2w)); a tangency (zero discriminant)
    // is not a crossing.
    let hw2 = half_w * half_w;
    let d1 = hw2 - m + q_over_2w;
    if d1 > zero {
        let s = d1.sqrt();
        out[0] = -half_w - s;
        out[1] = -half_w + s;
    }
    let d2 = hw2 - m - q_over_2w;
    if d2 > zero {
        let s = d2.sqrt();
        out[2] = half_w - s;
        out[3] = half_w + s;
    }
}

/// The root `y` of Ferrari's resolvent `y³ + P y² + (P²/4 − S) y − Q²/8` the published
/// routine uses: its smallest real root (the largest of the mirrored cubic it solves),
/// which is positive when the quartic has four real roots and negative when it has none;
/// with one real root, that one. Depressed by `y = z − P/3` to `z³ + p z + q`.
#[inline(always)]
fn resolvent_root<T: Real>(big_p: T, big_q: T, big_s: T) -> T {
    let (zero, one, two, half, three) =
        (T::of(0.0), T::of(1.0), T::of(2.0), T::of(0.5), T::of(3.0));
    let p = -big_p * big_p / T::of(12.0) - big_s;
    let q =
        -big_p * big_p * big_p / T::of(108.0) + big_p * big_s / three - big_q * big_q / T::of(8.0);
    let half_q = half * q;
    let minus_third_p = -p / three;
    let disc = half_q * half_q - minus_third_p * minus_third_p * minus_third_p;
    let z = if disc < zero {
        // Three real roots z = −2√(−p/3)·cos(θ/3 + 2πk/3), cos θ = (q/2)/(−p/3)^(3/2);
        // k = 0 is the smallest.
        let r = minus_third_p.sqrt();
        let cos_theta = (half_q / (r * minus_third_p)).clamp(-one, one);
        -two * r * (cos_theta.acos() / three).cos()
    } else {
        // One real root (Cardano): z = −sign(q)·|u + (−p/3)/u|, u = ∛(√disc + |q/2|).
        let u = (disc.sqrt() + half_q.abs()).cbrt();
        -half_q.signum() * (u + minus_third_p / u).abs()
    };
    z - big_p / three
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    #[test]
    fn finds_the_four_crossings_along_the_equator() {
        // R = 2, r = 1 (units of R: rr = 0.5): from x = −5 along +x the crossings are at
        // t = 2, 4, 6, 8.
        let torus = Torus::canonical(2.0, 1.0).unwrap();
        for (o, want) in [
            (-5.0, 2.0),
            (-3.5, 0.5),
            (-2.0, 1.0),
            (0.0, 1.0),
            (2.0, 1.0),
        ] {
            let ray = Ray::new(Vec3::new(o, 0.0, 0.0), Vec3::X).unwrap();
            let t = intersect_peer_f64(&torus, &ray).expect("hit");
            assert!((t - want).abs() < 1e-12, "o = {o}: {t}");
            // From the centre (o = 0) f32 is far off: Q = 0 sends the routine to its
            // reciprocal quartic, whose resolvent has a root at 0 where the trigonometric
            // form's acos(±1) turns 1 ulp into 1e-3 (a speckle of the method, t = 1.34).
            if o != 0.0 {
                let t = intersect_peer_f32(&torus, &ray).expect("hit");
                assert!((t - want as f32).abs() < 1e-4, "o = {o}: {t}");
            }
        }
        // t_min past the first two crossings; t_max before the first.
        let ray = Ray::with_range(Vec3::new(-5.0, 0.0, 0.0), Vec3::X, 4.5, 100.0).unwrap();
        assert!((intersect_peer_f32(&torus, &ray).unwrap() - 6.0).abs() < 1e-4);
        let ray = Ray::with_range(Vec3::new(-5.0, 0.0, 0.0), Vec3::X, 0.0, 1.5).unwrap();
        assert_eq!(intersect_peer_f32(&torus, &ray), None);
    }

    #[test]
    fn top_down_hits_and_hole_misses_at_any_pose_and_length() {
        let torus = Torus::new(Vec3::new(1.0, -2.0, 3.0), Vec3::Z, 4.0, 1.0).unwrap();
        // Down the axis (through the hole): a miss.
        let ray = Ray::new(Vec3::new(1.0, -2.0, 13.0), Vec3::new(0.0, 0.0, -2.0)).unwrap();
        assert_eq!(intersect_peer_f32(&torus, &ray), None);
        // Down onto the tube's top at distance R from the axis: |d| = 2, so t = 9/2.
        let start = torus.point_to_world(Vec3::new(4.0, 10.0, 0.0));
        let dir = torus.dir_to_world(Vec3::new(0.0, -2.0, 0.0));
        let t = intersect_peer_f32(&torus, &Ray::new(start, dir).unwrap()).expect("hit");
        assert!((t - 4.5).abs() < 1e-4, "{t}");
        // Outside the bounding sphere's shadow: a miss.
        let ray = Ray::new(Vec3::new(20.0, 20.0, 20.0), Vec3::X).unwrap();
        assert_eq!(intersect_peer_f32(&torus, &ray), None);
    }

    #[test]
    fn agrees_with_the_exact_intersection_on_easy_rays() {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_pcg::Pcg64::seed_from_u64(19);
        let torus = Torus::canonical(1.0, 0.25).unwrap();
        let (mut hits, mut disagree) = (0, 0);
        for _ in 0..2000 {
            let o = Vec3::new(
                rng.random_range(-3.0..3.0),
                rng.random_range(-3.0..3.0),
                rng.random_range(-3.0..3.0),
            );
            let aim = Vec3::new(
                rng.random_range(-1.3..1.3),
                rng.random_range(-0.3..0.3),
                rng.random_range(-1.3..1.3),
            );
            let Ok(ray) = Ray::new(o, aim - o) else {
                continue;
            };
            let exact = torus_cull::intersect(&torus, &ray).map(|h| h.t);
            // The f64 twin is close to exact wherever the ray is not tangent.
            let twin = intersect_peer_f64(&torus, &ray);
            if let (Some(a), Some(b)) = (exact, twin) {
                assert!((f64::from(a) - b).abs() < 1e-5 * (1.0 + b), "{ray:?}");
            }
            match (exact, intersect_peer_f32(&torus, &ray)) {
                (Some(a), Some(b)) if (a - b).abs() < 1e-3 * (1.0 + a) => hits += 1,
                (None, None) => {}
                _ => disagree += 1,
            }
        }
        assert!(hits > 500, "{hits}");
        // Grazing rays may disagree; on these rays they are rare.
        assert!(disagree < 20, "{disagree}");
    }
}
