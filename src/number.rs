//! How the lab writes a number for a person or a CSV cell: [`Num`].

use std::fmt;

/// An f64 as Rust's shortest round-trip text (parsing it gives the same f64 back), in
/// positional notation when `1e-5 <= |v| < 1e16` (or `v` is 0) and in scientific notation
/// otherwise: `1e300` is written `1e300`, not as 301 digits, and `3e-30` not as 31 zeros.
/// The cut-offs keep every value a person types in a workload or on the command line
/// (ν, radii, seconds) as typed, while an origin at `1e300` or an f32 limit stays one
/// short word.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Num(pub f64);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = self.0;
        if v == 0.0 || !v.is_finite() || (1e-5..1e16).contains(&v.abs()) {
            write!(f, "{v}")
        } else {
            write!(f, "{v:e}")
        }
    }
}

impl From<f32> for Num {
    /// The f32's own shortest text (not that of its f64 widening: `0.1f32` stays `0.1`).
    fn from(v: f32) -> Num {
        Num(v.to_string().parse().unwrap_or(f64::from(v)))
    }
}

/// A field of the user's input echoed in a message, as typed but cut: its first
/// [`Echo::KEPT`] characters and `…` when longer, so that a CSV field or a flag value of
/// 100 000 digits is not printed whole (what is kept still shows what was typed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Echo<'a>(pub &'a str);

impl Echo<'_> {
    /// The characters kept of a longer field.
    pub const KEPT: usize = 40;
}

impl fmt::Display for Echo<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0.char_indices().nth(Echo::KEPT) {
            None => f.write_str(self.0),
            Some((cut, _)) => write!(
                f,
                "{}… ({} characters)",
                &self.0[..cut],
                self.0.chars().count()
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{Echo, Num};

    #[test]
    fn long_fields_are_cut_when_echoed() {
        assert_eq!(Echo("1.5").to_string(), "1.5");
        let long = "9".repeat(100_000);
        let shown = Echo(&long).to_string();
        assert_eq!(shown, format!("{}… (100000 characters)", "9".repeat(40)));
        // Cut at a character, not a byte.
        let accents = Echo(&"é".repeat(41)).to_string();
        assert_eq!(accents, format!("{}… (41 characters)", "é".repeat(40)));
        assert_eq!(Echo(&"x".repeat(40)).to_string(), "x".repeat(40));
    }

    #[test]
    fn huge_and_tiny_values_are_scientific_and_round_trip() {
        for (v, text) in [
            (1e300, "1e300"),
            (-1e300, "-1e300"),
            (3e-30, "3e-30"),
            (1e16, "1e16"),
            (0.0, "0"),
            (2.5, "2.5"),
            (1000.0, "1000"),
            (1.5e15, "1500000000000000"),
            (1e-5, "0.00001"),
            (f64::INFINITY, "inf"),
        ] {
            let s = Num(v).to_string();
            assert_eq!(s, text);
            assert_eq!(s.parse::<f64>().unwrap(), v);
        }
        assert_eq!(Num(f64::MAX).to_string().parse::<f64>().unwrap(), f64::MAX);
        assert!(Num(f64::MAX).to_string().len() < 30);
        assert_eq!(Num::from(0.1f32).to_string(), "0.1");
        assert_eq!(Num::from(f32::MAX).to_string(), "3.4028235e38");
    }
}
