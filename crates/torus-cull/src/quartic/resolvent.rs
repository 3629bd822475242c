//! The greatest root of Ferrari's resolvent, solved for `z = m²` directly.
//!
//! For `x⁴ + p x² + q x + r = (x² + m x + n₁)(x² − m x + n₂)` the square `z = m²` is a root
//! of the resolvent cubic
//!
//! `h(z) = z³ + 2p z² + (p² − 4r) z − q²`
//!
//! (Descartes' form: its roots are `(x₁ + x₂)²` over the pairings of the quartic's roots).
//! Since `h(0) = −q² ≤ 0` and `h → +∞`, the greatest root is real and `≥ 0`, so `m` is real.
//!
//! **Why `z` and not Ferrari's `ξ` (with `m² = 2ξ − p`).** When `q` is small, `m²` is about
//! `q²/(p² − 4r)`, tiny next to `|p|`, and `2ξ − p` cannot represent it: the old solver got
//! `ξ` one ulp *below* `p/2`, took that as impossible, fell back to a Newton search that
//! stalled at a local minimum of the cubic, and then lost every real root (a line inside the
//! tube near the hole edge, whose quartic has two real roots and a near-double complex pair
//! near 0). In `z`, the small root keeps full relative precision through Vieta:
//! `z·|z₂|² = q²`, with `z₂` the larger complex root that Cardano gives along with `z`
//! (or, with three real roots, by the fixed point `z = q²/((z + 2p)z + p² − 4r)`).
//!
//! **No libm.** The cube root and the trisection `cos(arccos(x)/3)` are roots of cubics:
//! each is a polynomial seed good to 2·10⁻⁶ and one Halley step (cubic convergence), which
//! is far shorter than libm's `cbrt`, `acos` and `cos` on the critical path.
//!
//! **One source.** The steps ([`Cubic`] with its small-root fixed point and guarded Newton
//! polish, [`cardano`], [`trigonometric`]) are generic over [`Real`], and the lane
//! solver (`crate::batch::quartic::resolvent`) calls the same functions on its registers.
//! What differs is the driver: this one branches (Vieta's `z`, a Newton polish only where
//! the closed form loses digits, the careful near-double case), the lanes select.

use super::trisect::trisect_u;
use crate::num::{Real, RealMask, Sc, sc, sc_mask};

/// Below this `|Δ| / scale` the sign of the cubic's discriminant is not trusted: a
/// near-double pair of roots may be real or complex by rounding. Then the pair is classified
/// by the value of `h` at its local minimum instead.
pub(crate) const DISC_NEAR: f64 = 1e-9;

/// Below this `|Δ| / scale` the closed form is Newton-polished.
pub(crate) const POLISH_BELOW: f64 = 1e-4;

/// A greatest root `z` with `z·(z + |a|) ≤ SMALL_ROOT·b` is out of the closed form's
/// reach (it has cancelled in `w − a/3`) and is taken from the fixed point
/// `z = q²/((z + a)z + b)` instead ([`small_root`]).
pub(crate) const SMALL_ROOT: f64 = 1e-3;

/// The resolvent `h(z) = z³ + a z² + b z + c` (`a = 2p`, `b = p² − 4r`, `c = −q²`) of
/// `x⁴ + p x² + q x + r`, with its depressed form `w³ + 3P′w + 2Q′` (`z = w − a/3`), the
/// cubic's discriminant `Δ = Q′² + P′³` and the size `scale` its rounding is measured by.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Cubic<R> {
    pub a: R,
    pub b: R,
    pub c: R,
    /// `a/3`.
    pub a3: R,
    /// `P′`.
    pub third_p: R,
    /// `Q′`.
    pub half_q: R,
    /// `Δ = Q′² + P′³`.
    pub disc: R,
    /// `Q′² + |P′³|`.
    pub scale: R,
}

/// The resolvent cubic of `x⁴ + p x² + q x + r`.
#[inline(always)]
pub(crate) fn cubic<R: Real>(p: R, q: R, r: R) -> Cubic<R> {
    let a = p.k(2.0) * p;
    let b = p * p - p.k(4.0) * r;
    let c = q.negate() * q;
    // z = w − a/3 gives w³ + P w + Q. Thirds by multiplication: a division is on the
    // critical path, and the last bit of these is below what the formulas resolve.
    // In p, q, r directly: P' = −(p²/9 + 4r/3), Q' = p(4r/3 − p²/27) − q²/2 (a shorter
    // chain than through a, b and c).
    let a3 = a * p.k(1.0 / 3.0);
    let (p2, r43) = (p * p, r * p.k(4.0 / 3.0));
    let third_p = (p2 * p.k(1.0 / 9.0) + r43).negate();
    let half_q = p * (r43 - p2 * p.k(1.0 / 27.0)) - p.k(0.5) * (q * q);
    let disc = half_q * half_q + third_p * third_p * third_p;
    let scale = half_q * half_q + (third_p * third_p * third_p).abs();
    Cubic {
        a,
        b,
        c,
        a3,
        third_p,
        half_q,
        disc,
        scale,
    }
}

impl<R: Real> Cubic<R> {
    /// `h(z)`, Horner.
    #[inline(always)]
    pub(crate) fn h(&self, z: R) -> R {
        ((z + self.a) * z + self.b) * z + self.c
    }

    /// `h′(z)`, Horner.
    #[inline(always)]
    pub(crate) fn dh(&self, z: R) -> R {
        (z.k(3.0) * z + z.k(2.0) * self.a) * z + self.b
    }

    /// Where `Δ` is within rounding of 0 ([`DISC_NEAR`]): a near-double pair of roots.
    #[inline(always)]
    pub(crate) fn near_double(&self) -> R::Mask {
        self.disc.abs().le(self.disc.k(DISC_NEAR) * self.scale)
    }

    /// Where the greatest root `z` (from a closed form) is too small for it: see
    /// [`SMALL_ROOT`].
    #[inline(always)]
    pub(crate) fn is_small_root(&self, z: R) -> R::Mask {
        self.b.gt(z.k(0.0)) & (z * (z + self.a.abs())).le(z.k(SMALL_ROOT) * self.b)
    }

    /// The small greatest root to full relative precision: near 0,
    /// `h = z·((z + a)z + b) − q²`, so two steps of the fixed point
    /// `z = q²/((z + a)z + b)` from `q²/b` (it contracts by about `z·|a|/b` per step).
    #[inline(always)]
    pub(crate) fn small_root(&self, q: R) -> R {
        let z = q * q / self.b;
        q * q / ((z + self.a) * z + self.b)
    }

    /// Two guarded Newton steps on `h` from `z`, each kept only where it lowers `|h|` (so
    /// a double root cannot be thrown away; NaN, at `h′ = 0`, keeps `z`).
    #[inline(always)]
    pub(crate) fn polish(&self, mut z: R) -> R {
        let zero = z.k(0.0);
        let mut hz = self.h(z);
        for _ in 0..2 {
            let zn = (z - hz / self.dh(z)).max(zero);
            let hn = self.h(zn);
            let better = hn.abs().lt(hz.abs());
            z = R::select(better, zn, z);
            hz = R::select(better, hn, hz);
        }
        z
    }
}

/// The resolvent's greatest root `z = m² ≥ 0`, with what Ferrari's split needs of it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Root<R: Real> {
    pub z: R,
    /// `h'(z)` (at `z_early`: it only sizes errors).
    pub dh: R,
    /// `m = √z`.
    pub m: R,
    /// `q/m` (garbage when `m = 0`).
    pub q_over_m: R,
    /// `q/m` is good to a few ulps, whatever `h'(z)` says (Vieta's `z`, below).
    pub q_over_m_exact: R::Mask,
    /// `z` to within a few `ε·|p|`, earlier on the dependency chain than `z` itself: for
    /// `p + z`, whose rounding is that large anyway.
    pub z_early: R,
}

/// The greatest real root of `h` for the depressed quartic `x⁴ + p x² + q x + r` (finite
/// inputs).
#[inline(always)]
pub(super) fn greatest_root(p: f64, q: f64, r: f64) -> Root<Sc> {
    let cubic: Cubic<Sc> = cubic(sc(p), sc(q), sc(r));
    let [a, a3, disc, scale] = [cubic.a, cubic.a3, cubic.disc, cubic.scale].map(|x| x.v);
    let (third_p, half_q) = (cubic.third_p, cubic.half_q);
    let near = cubic.near_double().any();
    let (mut z, mut m, mut q_over_m, mut z_early);
    let mut small_root = false;
    let mut vieta = false;
    if !near && disc > 0.0 {
        let (u, v, _) = cardano(third_p, half_q, cubic.disc);
        let (u, v) = (u.v, v.v);
        z = (u + v - a3).max(0.0);
        // The other roots are a complex pair z₂, z̄₂ with 4|z₂|² = (z + a)² + 3(u − v)²
        // (both squares free of cancellation), and z·|z₂|² = q². When z is small next to
        // |a| or to |u − v|, u + v − a/3 has cancelled and z = 4q²/pair keeps full
        // relative precision; m and q/m then follow from √pair without the two divisions.
        // (With p = 0, a = 0 and only u + v cancels: x⁴ + 10⁻⁷⁶x − 1.5 took z from that
        // rounding and gave roots ±6.5·10⁷.) Both are computed and one is selected: which
        // one applies is a coin toss from ray to ray.
        let pair = (z + a) * (z + a) + 3.0 * (u - v) * (u - v);
        vieta = z < a3.abs().max((u - v).abs()) && pair > 0.0;
        let half_sp = 0.5 * pair.sqrt();
        let (m_direct, m_vieta) = (z.sqrt(), q.abs() / half_sp);
        m = if vieta { m_vieta } else { m_direct };
        q_over_m = if vieta {
            half_sp.copysign(q)
        } else {
            q / m_direct
        };
        z_early = z;
        z = if vieta { 4.0 * q * q / pair } else { z };
    } else {
        let w = if near {
            near_double(&cubic)
        } else {
            trigonometric(third_p, half_q).v
        };
        z = (w - a3).max(0.0);
        // A root far below ε·|a| is out of the closed form's reach, and Newton from there
        // only gains a factor ε per step: the fixed point gives it at once. Rare: the
        // greatest of three real roots is seldom tiny.
        small_root = cubic.is_small_root(sc(z)).any();
        if small_root {
            z = cubic.small_root(sc(q)).v;
        }
        m = z.sqrt();
        // q/m = (q/z)·m: the division overlaps the root instead of waiting for it.
        q_over_m = q / z * m;
        z_early = z;
    }
    // Two Newton steps polish the closed form where it loses digits: a small discriminant
    // (close roots: the trisection near −1, Cardano's cancellation; one step was
    // measurably short on tangents at the inner equator) or a root found by the fixed
    // point above. Elsewhere the closed form is good to a few ulps and the steps would
    // only lengthen the hot path; so is Vieta's z even at a small discriminant (its pair
    // is dominated by (z + a)², which has no cancellation: a tangent at the foot point).
    if !vieta && (small_root || disc.abs() <= POLISH_BELOW * scale) {
        z = cubic.polish(sc(z)).v;
        m = z.sqrt();
        q_over_m = q / m;
        z_early = z;
    }
    Root {
        z: sc(z),
        dh: cubic.dh(sc(z_early)),
        m: sc(m),
        q_over_m: sc(q_over_m),
        q_over_m_exact: sc_mask(vieta),
        z_early: sc(z_early),
    }
}

/// Cardano's `(u, v)` for `w³ + 3P' w + 2Q'` (`third_p = P'`, `half_q = Q'`, `disc > 0`):
/// the one real root is `w = u + v` with `v = −P'/u`, the cube root taken of the
/// larger-magnitude term to avoid cancellation. Also returns that term, `|Q′| + √Δ`,
/// whose range the lane solver checks for its cube root.
#[inline(always)]
pub(crate) fn cardano<R: Real>(third_p: R, half_q: R, disc: R) -> (R, R, R) {
    let zero = disc.k(0.0);
    let cube = half_q.abs() + disc.sqrt();
    // u = ±∛cube and v = −P'/u = ±(−P'/cube)·∛cube²: the division runs while the cube
    // root does.
    let ratio = third_p.negate() / cube;
    let big = cube.cbrt();
    let v = ratio * big * big;
    let negative = half_q.gt(zero);
    let (u, v) = (
        R::select(negative, big.negate(), big),
        R::select(negative, v.negate(), v),
    );
    let nonzero = big.ne(zero);
    (
        R::select(nonzero, u, zero),
        R::select(nonzero, v, zero),
        cube,
    )
}

/// The greatest of three real roots (`disc ≤ 0`, so `third_p ≤ 0`): `2k cos(θ/3)` with
/// `k = √(−P')` and `cos θ = −Q'/k³`.
#[inline(always)]
pub(crate) fn trigonometric<R: Real>(third_p: R, half_q: R) -> R {
    let one = third_p.k(1.0);
    let k = third_p.negate().max(third_p.k(0.0)).sqrt();
    // −Q'/k³ = (Q'/P')·√(−1/P'): both divisions and the root overlap the root k. P' = 0
    // makes it NaN or infinite, which `max` and `min` clamp (`clamp` would keep NaN);
    // then k·… is 0.
    let cos3 = ((half_q / third_p) * (one.negate() / third_p).sqrt())
        .max(one.negate())
        .min(one);
    // 2k·cos(θ/3) = k·(1 + u).
    k + k * trisect_u(cos3)
}

/// `disc ≈ 0`: two roots of `h` (nearly) coincide. If the pair is the top one, whether it is
/// real decides the greatest root; `h` at its local minimum `z₊` tells: `h(z₊) ≤ 0` means
/// a real root at or right of `z₊`, otherwise the only real root is left of the pair.
#[cold]
fn near_double(cubic: &Cubic<Sc>) -> f64 {
    let [a, b, a3] = [cubic.a, cubic.b, cubic.a3].map(|x| x.v);
    let (third_p, half_q) = (cubic.third_p, cubic.half_q);
    let one_root = || {
        let (u, v, _) = cardano(third_p, half_q, sc(0.0));
        u.v + v.v
    };
    let crit = a * a - 3.0 * b;
    if crit <= 0.0 {
        // h is monotone: one real root (a triple one when crit = 0).
        return one_root();
    }
    let sq = crit.sqrt();
    // Larger root of h' = 3z² + 2az + b, without cancellation.
    let z_min = if a > 0.0 {
        -b / (a + sq)
    } else {
        (sq - a) / 3.0
    };
    if cubic.h(sc(z_min)).v <= 0.0 {
        trigonometric(third_p, half_q).v.max(z_min + a3)
    } else {
        one_root()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn h(p: f64, q: f64, r: f64, z: f64) -> f64 {
        ((z + 2.0 * p) * z + p * p - 4.0 * r) * z - q * q
    }

    #[test]
    fn tiny_root_has_full_relative_precision() {
        // The reproducer: m² ≈ q²/(p² − 4r) ≈ 7.6e-26, next to |p| ≈ 3.3.
        let (p, q, r) = (
            -3.3331887926483623,
            9.194867089945546e-13,
            -0.00023409507477270552,
        );
        let Root { z, dh, .. } = greatest_root(p, q, r);
        let (z, dh) = (z.v, dh.v);
        let want = q * q / (p * p - 4.0 * r);
        assert!(((z - want) / want).abs() < 1e-6, "{z:e} vs {want:e}");
        assert!(dh > 0.0);
        // And it really is the greatest root: h > 0 everywhere right of it (h has a
        // complex pair near 3.33 here, where the old solver's search stalled).
        for i in 1..=4000 {
            let zz = z + f64::from(i) * 1e-3;
            assert!(h(p, q, r, zz) > 0.0, "h({zz}) ≤ 0");
        }
    }

    #[test]
    fn greatest_of_three_real_roots() {
        // x⁴ − 5x² + 4 = (x² − 1)(x² − 4): pairings give z ∈ {0, 1, 9}.
        let z = greatest_root(-5.0, 0.0, 4.0).z.v;
        assert!((z - 9.0).abs() < 1e-12, "{z}");
        // (x² − 1)²: z ∈ {0, 0, 4}.
        let z = greatest_root(-2.0, 0.0, 1.0).z.v;
        assert!((z - 4.0).abs() < 1e-12, "{z}");
    }

    #[test]
    fn never_negative_and_always_a_root() {
        // Random depressed quartics over many scales: z ≥ 0, h(z) ≈ 0 and h > 0 beyond z.
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_pcg::Pcg64::seed_from_u64(0x7051_0100);
        for _ in 0..50_000 {
            let s: f64 = 10f64.powf(rng.random_range(-3.0..3.0));
            let p = rng.random_range(-4.0..4.0) * s * s;
            let q =
                rng.random_range(-4.0..4.0) * s * s * s * 10f64.powf(rng.random_range(-14.0..0.0));
            let r = rng.random_range(-4.0..4.0) * s * s * s * s;
            let z = greatest_root(p, q, r).z.v;
            assert!(z >= 0.0);
            let zs = s * s;
            let mag = ((z + 2.0 * p.abs()) * z + p * p + 4.0 * r.abs()) * z + q * q;
            let hz = h(p, q, r, z);
            // A near-double top root is √-conditioned; everywhere else h(z) is at rounding.
            let beyond = h(p, q, r, z + 1e-6 * zs.max(z));
            assert!(
                hz.abs() <= 1e-9 * mag.max(f64::MIN_POSITIVE) || beyond > 0.0,
                "p={p} q={q} r={r}: z={z} h={hz} beyond={beyond}"
            );
            assert!(
                beyond >= -1e-9 * mag,
                "p={p} q={q} r={r}: not the greatest root"
            );
        }
    }
}
