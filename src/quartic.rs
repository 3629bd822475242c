//! Real roots of a quartic, the core of the exact intersection.

/// Up to four real roots, sorted ascending. A double root is reported twice.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct RealRoots {
    roots: [f64; 4],
    len: usize,
}

impl RealRoots {
    /// The roots, ascending.
    pub fn as_slice(&self) -> &[f64] {
        &self.roots[..self.len]
    }
}

/// All real roots of `c[0]·t⁴ + c[1]·t³ + c[2]·t² + c[3]·t + c[4]`, `c[0] ≠ 0`, sorted.
pub fn solve_quartic(_c: [f64; 5]) -> RealRoots {
    todo!("quartic helper")
}
