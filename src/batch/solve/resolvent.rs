//! The greatest root of Ferrari's resolvent in z = m², over f64 lanes: the scalar
//! [`crate::quartic`] resolvent, lane for lane, with its cold case handed back.

use super::cube_root::{CBRT_RANGE, cbrt, trisect_cos};
use crate::batch::lanes::{F64s, M64s};
use crate::quartic::DISC_NEAR;
use pulp::Simd;

/// `(z, h′(z), fallback)`: z ≥ 0 the greatest root of
/// h!(z) = z³ + 2p z² + (p² − 4r) z − q² for x⁴ + p x² + q x + r, and the lanes the
/// scalar solver must take instead.
///
/// As in the scalar solver: z = w − 2p/3 with w the greatest root of the depressed cubic
/// w³ + 3P′w + 2Q′, by Cardano (one real root, Δ = Q′² + P′³ > 0) or the trigonometric
/// form (three), both computed on every lane and selected; a small root by the fixed
/// point z = q²/((z + 2p)z + p² − 4r), which keeps its relative precision; then two
/// Newton steps, each kept only where it lowers |h|.
///
/// Fallback lanes: |Δ| ≤ 10⁻⁹·scale (a near-double root of the resolvent, which the
/// scalar solver settles by the cubic's value at its local minimum: rare, and not worth
/// a lane's worth of work for everyone), a Cardano argument outside the lane cube
/// root's range, and anything not finite.
#[inline(always)]
pub(super) fn greatest_root<S: Simd>(
    p: F64s<S>,
    q: F64s<S>,
    r: F64s<S>,
) -> (F64s<S>, F64s<S>, M64s<S>) {
    let s = p.s;
    // Macros, not closures: a closure that LLVM leaves outlined would run without the
    // SIMD target features and call every intrinsic out of line.
    macro_rules! c_ {
        ($x:expr) => {
            F64s::splat(s, $x)
        };
    }
    let a = c_!(2.0) * p;
    let b = p * p - c_!(4.0) * r;
    let c = -q * q;
    // Thirds by multiplication (the scalar code divides): a division costs a lane as
    // much as ten multiplies, and the last bit of these is polished away by Newton below.
    let third = c_!(1.0 / 3.0);
    let a3 = a * third;
    let third_p = (b - a * a3) * third;
    let half_q = c_!(0.5) * (c - a3 * (b - c_!(2.0) * a3 * a3));
    let disc = half_q * half_q + third_p * third_p * third_p;
    let scale = half_q * half_q + (third_p * third_p * third_p).abs();
    let near_double = !disc.abs().gt(c_!(DISC_NEAR) * scale);

    // Each formula runs only if a lane of this register needs it: in a register whose
    // lanes agree (often, on coherent rays) that halves the work; otherwise both run and
    // the lane's case selects.
    let one_real = disc.gt(c_!(0.0));
    let cases = one_real.bits();
    let all = u64::MAX >> (64 - S::F64_LANES);
    let (cardano, outside_cbrt) = if cases != 0 {
        // Cardano: u = ∓∛(|Q′| + √Δ), the sign opposite to Q′'s, w = u − P′/u.
        let big_arg = half_q.abs() + disc.sqrt();
        let big = cbrt(big_arg);
        let u = half_q.gt(c_!(0.0)).select(-big, big);
        let w = u.eq(c_!(0.0)).select(c_!(0.0), u - third_p / u);
        let in_range = big_arg.ge(c_!(CBRT_RANGE.0)) & big_arg.le(c_!(CBRT_RANGE.1));
        (w, one_real & !in_range)
    } else {
        (c_!(0.0), one_real)
    };
    let trig = if cases != all {
        // Three real roots: w = 2k·cos(arccos(−Q′/k³)/3), k = √(−P′).
        let k = (-third_p).max_num(c_!(0.0)).sqrt();
        let cos3 = (-half_q / (k * k * k)).max_num(c_!(-1.0)).min_num(c_!(1.0));
        k.eq(c_!(0.0))
            .select(c_!(0.0), c_!(2.0) * k * trisect_cos(cos3))
    } else {
        c_!(0.0)
    };

    let w = one_real.select(cardano, trig);
    macro_rules! h {
        ($z:expr) => {{
            let z: F64s<S> = $z;
            ((z + a) * z + b) * z + c
        }};
    }
    macro_rules! dh {
        ($z:expr) => {{
            let z: F64s<S> = $z;
            (c_!(3.0) * z + c_!(2.0) * a) * z + b
        }};
    }
    let mut z = (w - a3).max_num(c_!(0.0));
    let tiny = b.gt(c_!(0.0)) & (z * (z + a.abs())).le(c_!(1e-3) * b);
    if tiny.bits() != 0 {
        // Rare (a line nearly through the foot point's quartic minimum): only a register
        // with such a lane pays the two divisions.
        let z_fixed = q * q / b;
        let z_fixed = q * q / ((z_fixed + a) * z_fixed + b);
        z = tiny.select(z_fixed, z);
    }
    let mut hz = h!(z);
    for _ in 0..2 {
        let zn = (z - hz / dh!(z)).max_num(c_!(0.0));
        let hn = h!(zn);
        let better = hn.abs().lt(hz.abs());
        z = better.select(zn, z);
        hz = better.select(hn, hz);
    }
    let dz = dh!(z);
    let fallback = near_double | outside_cbrt | !z.is_finite() | !dz.is_finite();
    (z, dz, fallback)
}
