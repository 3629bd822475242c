//! Roots whose sizes lie further apart than one power-of-two scaling can hold: each group
//! solved at its own scale, found from the **Newton polygon**.
//!
//! Scaling `t = 2^m·y` makes a quartic's coefficients `cₖ·2^(m(4−k))`. When its roots span
//! more than f64's exponent range (roots near 1 beside a root near 10²⁹²), no one `m`
//! keeps every coefficient that matters: at the large roots' scale the constant term
//! underflows to 0, and the unit roots' complex pair `t² + t + 1` became a spurious real
//! root at −1. The upper convex hull of the points `(degree, log₂|cₖ|)` tells the sizes
//! apart: an edge of slope `−σ` spanning `j` degrees stands for `j` roots of size about
//! `2^σ` (Ostrowski), and at that scale every coefficient off the edge is smaller than
//! the edge's, so what underflows there is negligible there.

use super::{RealRoots, pieces, times_pow2};

/// An edge whose root size lies within this many binades of the previous edge's is solved
/// with it at one scale (a group spans at most three such gaps, so its coefficients there
/// stay far inside f64's range). Groups end up more than this far apart, so the terms
/// of another group are below 2⁻¹⁰⁰ of this group's at its roots.
const GROUP: f64 = 100.0;

/// Every real root of `c[0]·t⁴ + … + c[4]` (`c[0] ≠ 0`, all finite), sorted, where the
/// roots' sizes may span more than f64's range: each group of root sizes is solved by
/// monotone pieces at its own power-of-two scale, on the terms that group's roots are
/// made of. A root too large for f64, or too small to be told from 0, is left out.
pub(super) fn real_roots(c: &[f64; 5]) -> RealRoots {
    let (mut out, degree) = pieces::zero_roots(c);
    let poly = &c[..=degree];
    // Points (j, log₂|coefficient of tʲ|), j ascending; the hull's ends are nonzero.
    let mut hull: [(f64, f64); 5] = [(0.0, 0.0); 5];
    let mut len = 0;
    for j in 0..=degree {
        let v = poly[degree - j];
        if v == 0.0 {
            continue;
        }
        let point = (j as f64, v.abs().log2());
        // Upper hull: drop the last point while it lies on or below the chord.
        while len >= 2 {
            let (a, b) = (hull[len - 2], hull[len - 1]);
            let cross = (b.0 - a.0) * (point.1 - a.1) - (b.1 - a.1) * (point.0 - a.0);
            if cross >= 0.0 {
                len -= 1;
            } else {
                break;
            }
        }
        hull[len] = point;
        len += 1;
    }
    // Each edge's root size σ = −slope, increasing along the hull; consecutive edges
    // within GROUP binades form one group, which spans degrees j_start..j_end.
    struct Group {
        lo: f64,
        hi: f64,
        j_start: usize,
        j_end: usize,
    }
    let mut groups: [Group; 4] = std::array::from_fn(|_| Group {
        lo: 0.0,
        hi: 0.0,
        j_start: 0,
        j_end: 0,
    });
    let mut n_groups = 0;
    for e in 0..len - 1 {
        let (a, b) = (hull[e], hull[e + 1]);
        let size = -(b.1 - a.1) / (b.0 - a.0);
        let (j_start, j_end) = (a.0 as usize, b.0 as usize);
        if n_groups > 0 && size - groups[n_groups - 1].hi <= GROUP {
            groups[n_groups - 1].hi = size;
            groups[n_groups - 1].j_end = j_end;
        } else {
            groups[n_groups] = Group {
                lo: size,
                hi: size,
                j_start,
                j_end,
            };
            n_groups += 1;
        }
    }
    for g in &groups[..n_groups] {
        // At this group's roots every term of degree outside j_start..j_end is below the
        // group's own by 2^−GROUP or more per degree: dropped (a relative change under
        // 2⁻¹⁰⁰ in f there), which also drops the other groups' roots.
        let m = (0.5 * (g.lo + g.hi)).round() as i32;
        let terms = &poly[degree - g.j_end..=degree - g.j_start];
        let top = terms
            .iter()
            .enumerate()
            .filter(|(_, v)| **v != 0.0)
            .map(|(i, v)| v.abs().log2() + f64::from(m) * (g.j_end - i) as f64)
            .fold(f64::NEG_INFINITY, f64::max)
            .round() as i32;
        // Coefficient of y^(j − j_start): poly's of tʲ times 2^(m·j), over 2^top.
        let mut scaled = [0.0; 5];
        for (i, v) in terms.iter().enumerate() {
            scaled[i] = times_pow2(*v, m * (g.j_end - i) as i32 - top);
        }
        for &y in pieces::roots_of_poly(&scaled[..terms.len()]).as_slice() {
            let x = times_pow2(y, m);
            if x.is_finite() && x != 0.0 {
                out.push(x);
            }
        }
    }
    out.sort();
    out
}
