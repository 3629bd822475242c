//! The solver's answer: up to four real roots in a fixed array, no allocation.

/// Up to four real roots, sorted ascending. A double root is reported twice.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct RealRoots {
    pub(super) roots: [f64; 4],
    pub(super) len: usize,
}

impl RealRoots {
    /// The roots, ascending.
    #[inline]
    pub fn as_slice(&self) -> &[f64] {
        &self.roots[..self.len]
    }

    /// How many real roots (with multiplicity), 0 to 4.
    #[inline]
    pub fn len(&self) -> usize {
        self.len
    }

    /// No real root.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    #[inline]
    pub(super) fn push(&mut self, x: f64) {
        // A quartic has at most four roots; each of the two factors pushes at most two.
        debug_assert!(self.len < 4);
        if self.len < 4 {
            self.roots[self.len] = x;
            self.len += 1;
        }
    }

    /// Insertion sort: at most four elements.
    #[inline]
    pub(super) fn sort(&mut self) {
        for i in 1..self.len {
            let mut j = i;
            while j > 0 && self.roots[j - 1] > self.roots[j] {
                self.roots.swap(j - 1, j);
                j -= 1;
            }
        }
    }

    /// Applies an increasing map to every root (order is kept), e.g. a change of variable.
    #[inline]
    pub(crate) fn map_increasing(mut self, f: impl Fn(f64) -> f64) -> RealRoots {
        for x in &mut self.roots[..self.len] {
            *x = f(*x);
        }
        self
    }
}
