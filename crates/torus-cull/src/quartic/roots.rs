//! The solver's answer: up to four real roots in a fixed array, no allocation.

use crate::num::fixed_list;

/// Up to four real roots, sorted ascending. A double root is reported twice.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct RealRoots {
    pub(super) roots: [f64; 4],
    pub(super) len: usize,
}

fixed_list! {
    /// The roots, ascending (0 to 4, with multiplicity).
    impl[] RealRoots, roots: [f64], "roots"
}

impl RealRoots {
    #[inline]
    pub(super) fn push(&mut self, x: f64) {
        // A quartic has at most four roots; each of the two factors pushes at most two.
        debug_assert!(self.len < 4);
        if self.len < 4 {
            self.roots[self.len] = x;
            self.len += 1;
        }
    }

    /// Ascending, by a sorting network on four slots (the empty ones padded with +∞, which
    /// every finite root sorts before): five compare-exchanges, each a select rather than
    /// a branch, since the order of the roots is a coin toss from ray to ray. A NaN is
    /// never exchanged (every comparison with it is false), as in an insertion sort.
    #[inline]
    pub(super) fn sort(&mut self) {
        let n = self.len;
        let mut a = self.roots;
        for (i, x) in a.iter_mut().enumerate() {
            if i >= n {
                *x = f64::INFINITY;
            }
        }
        #[inline(always)]
        fn exchange(a: &mut [f64; 4], i: usize, j: usize) {
            let (x, y) = (a[i], a[j]);
            let swap = y < x;
            a[i] = if swap { y } else { x };
            a[j] = if swap { x } else { y };
        }
        exchange(&mut a, 0, 1);
        exchange(&mut a, 2, 3);
        exchange(&mut a, 0, 2);
        exchange(&mut a, 1, 3);
        exchange(&mut a, 1, 2);
        for (i, x) in a.iter_mut().enumerate() {
            if i >= n {
                *x = 0.0;
            }
        }
        self.roots = a;
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
