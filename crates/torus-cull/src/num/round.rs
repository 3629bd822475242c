//! f64 values rounded to f32 in a chosen direction: boxes and bounds that must hold what
//! the f64 value holds after the rounding.

/// The smallest f32 ≥ `x`: `+∞` past f32's range, the least positive subnormal for a
/// positive `x` below it; NaN for NaN.
pub(crate) fn up(x: f64) -> f32 {
    let y = x as f32;
    if x.is_nan() || f64::from(y) >= x {
        y
    } else if y > 0.0 {
        f32::from_bits(y.to_bits() + 1)
    } else if y < 0.0 {
        f32::from_bits(y.to_bits() - 1)
    } else {
        f32::from_bits(1)
    }
}

/// The largest f32 ≤ `x`.
pub(crate) fn down(x: f64) -> f32 {
    -up(-x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_brackets_the_value() {
        for x in [
            0.0,
            1e-50,
            -1e-50,
            0.1,
            -0.1,
            1.0 / 3.0,
            -7.25,
            1e39,
            -1e39,
            3.4e38,
        ] {
            let (lo, hi) = (down(x), up(x));
            assert!(f64::from(lo) <= x && x <= f64::from(hi), "{x}: {lo} {hi}");
            // Adjacent or equal: no f32 lies strictly between the two.
            if lo != hi && lo.is_finite() && hi.is_finite() {
                assert_eq!(lo.next_up(), hi, "{x}");
            }
        }
        assert_eq!(up(0.5), 0.5);
        assert_eq!(down(0.5), 0.5);
        assert_eq!(up(1e39), f32::INFINITY);
        assert_eq!(down(-1e39), f32::NEG_INFINITY);
        assert!(up(f64::NAN).is_nan() && down(f64::NAN).is_nan());
    }
}
