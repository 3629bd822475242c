//! Every crossing of a ray with a [`crate::Solid`], and the spans inside it: fixed
//! capacity, no allocation, iterated by reference (`for c in &crossings`) or as slices.
//!
//! A pipe bend crosses a line at most ten times (two tori, four each, and two caps), so
//! [`SolidCrossings`] holds ten; spans alternate with crossings, so at most six (a range
//! that starts inside, then five more entries), which [`SolidSpans`] holds.

use super::ray::Precision;
use super::ray::sealed::Scalar;

/// How a ray meets the surface at a crossing.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Passage {
    /// The ray enters the solid: a span starts here.
    Enter,
    /// The ray leaves the solid: a span ends here.
    Exit,
    /// The ray touches the surface (a double root: a tangent) and stays on the side it was
    /// on. Reported once, not as a span of zero length.
    Touch,
}

/// The most crossings a [`SolidCrossings`] holds: a pipe bend's ten.
pub const MAX_CROSSINGS: usize = 10;

/// The most spans a [`SolidSpans`] holds.
pub const MAX_SPANS: usize = 6;

/// One crossing of a ray with a solid's boundary, in the ray's precision.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct SolidCrossing<P: Precision, F> {
    /// Ray parameter, in units of the ray's direction.
    pub t: P::Float,
    /// The face's unit outward normal, world space.
    pub normal: P,
    /// Entering, leaving, or a tangent touch.
    pub passage: Passage,
    /// Which face.
    pub face: F,
}

impl<P: Precision, F> SolidCrossing<P, F> {
    /// A crossing from its fields.
    #[must_use]
    pub const fn new(t: P::Float, normal: P, passage: Passage, face: F) -> Self {
        SolidCrossing {
            t,
            normal,
            passage,
            face,
        }
    }
}

/// A stretch `[t_enter, t_exit]` of the ray's range inside the solid. `enter` is `None`
/// where the range starts inside (`t_enter = t_min`), `exit` where it ends inside
/// (`t_exit = t_max`).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct SolidSpan<P: Precision, F> {
    /// Where the span starts.
    pub t_enter: P::Float,
    /// Where the span ends.
    pub t_exit: P::Float,
    /// The crossing that opens the span, unless it opens at `t_min`.
    pub enter: Option<SolidCrossing<P, F>>,
    /// The crossing that closes the span, unless it runs to `t_max`.
    pub exit: Option<SolidCrossing<P, F>>,
}

/// Every crossing in `[t_min, t_max]`, ascending in `t`, and the ray's side at `t_min`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[must_use]
pub struct SolidCrossings<P: Precision, F> {
    crossings: [SolidCrossing<P, F>; MAX_CROSSINGS],
    len: usize,
    starts_inside: bool,
    t_min: P::Float,
    t_max: P::Float,
}

/// The spans of a [`SolidCrossings`], ascending.
#[derive(Debug, Clone, Copy, PartialEq)]
#[must_use]
pub struct SolidSpans<P: Precision, F> {
    spans: [SolidSpan<P, F>; MAX_SPANS],
    len: usize,
}

impl<P: Precision, F: Copy + Default> SolidCrossings<P, F> {
    /// No crossing yet over `[t_min, t_max]`; `starts_inside` the side at `t_min`.
    pub fn new(t_min: P::Float, t_max: P::Float, starts_inside: bool) -> Self {
        SolidCrossings {
            crossings: [SolidCrossing::new(
                <P::Float as Scalar>::ZERO,
                P::ZERO,
                Passage::Touch,
                F::default(),
            ); MAX_CROSSINGS],
            len: 0,
            starts_inside,
            t_min,
            t_max,
        }
    }

    /// Appends a crossing (the caller keeps them ascending); `false`, and nothing
    /// appended, when [`MAX_CROSSINGS`] are held.
    pub fn push(&mut self, crossing: SolidCrossing<P, F>) -> bool {
        let Some(slot) = self.crossings.get_mut(self.len) else {
            return false;
        };
        *slot = crossing;
        self.len += 1;
        true
    }

    /// The crossings paired into the stretches of the range inside the solid, ascending
    /// (the ring torus's `Crossings::spans`, over any face type). Touches open no span.
    pub fn spans(&self) -> SolidSpans<P, F> {
        let empty = SolidSpan {
            t_enter: <P::Float as Scalar>::ZERO,
            t_exit: <P::Float as Scalar>::ZERO,
            enter: None,
            exit: None,
        };
        let mut out = SolidSpans {
            spans: [empty; MAX_SPANS],
            len: 0,
        };
        let push = |out: &mut SolidSpans<P, F>, (t_enter, enter), t_exit, exit| {
            if let Some(slot) = out.spans.get_mut(out.len) {
                *slot = SolidSpan {
                    t_enter,
                    t_exit,
                    enter,
                    exit,
                };
                out.len += 1;
            }
        };
        let mut open = self.starts_inside.then_some((self.t_min, None));
        for &c in self.as_slice() {
            match c.passage {
                Passage::Enter => open = Some((c.t, Some(c))),
                // Alternation makes `open` set here; a missing one can only be the range's
                // start.
                Passage::Exit => push(
                    &mut out,
                    open.take().unwrap_or((self.t_min, None)),
                    c.t,
                    Some(c),
                ),
                Passage::Touch => {}
            }
        }
        if let Some(start) = open {
            push(&mut out, start, self.t_max, None);
        }
        out
    }
}

impl<P: Precision, F> SolidCrossings<P, F> {
    /// The crossings, ascending in `t`: entries and exits alternate (an entry first unless
    /// [`SolidCrossings::starts_inside`]), touches anywhere between them.
    #[inline]
    #[must_use]
    pub fn as_slice(&self) -> &[SolidCrossing<P, F>] {
        &self.crossings[..self.len]
    }

    /// The crossings by reference, ascending.
    #[inline]
    pub fn iter(&self) -> std::slice::Iter<'_, SolidCrossing<P, F>> {
        self.as_slice().iter()
    }

    /// How many crossings (a touch counts once).
    #[inline]
    #[must_use]
    pub fn len(&self) -> usize {
        self.len
    }

    /// No crossing in range (the ray may still lie wholly inside).
    #[inline]
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Whether the ray is inside the solid at `t_min` (for a ray from a surface point:
    /// just past its origin).
    #[inline]
    #[must_use]
    pub fn starts_inside(&self) -> bool {
        self.starts_inside
    }

    /// The ray's range `[t_min, t_max]` the crossings were found in.
    #[inline]
    #[must_use]
    pub fn range(&self) -> (P::Float, P::Float) {
        (self.t_min, self.t_max)
    }
}

impl<P: Precision, F> SolidSpans<P, F> {
    /// The spans, ascending.
    #[inline]
    #[must_use]
    pub fn as_slice(&self) -> &[SolidSpan<P, F>] {
        &self.spans[..self.len]
    }

    /// The spans by reference, ascending.
    #[inline]
    pub fn iter(&self) -> std::slice::Iter<'_, SolidSpan<P, F>> {
        self.as_slice().iter()
    }

    /// How many spans.
    #[inline]
    #[must_use]
    pub fn len(&self) -> usize {
        self.len
    }

    /// The range holds no point inside the solid (touches aside).
    #[inline]
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}

impl<'a, P: Precision, F> IntoIterator for &'a SolidCrossings<P, F> {
    type Item = &'a SolidCrossing<P, F>;
    type IntoIter = std::slice::Iter<'a, SolidCrossing<P, F>>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

impl<'a, P: Precision, F> IntoIterator for &'a SolidSpans<P, F> {
    type Item = &'a SolidSpan<P, F>;
    type IntoIter = std::slice::Iter<'a, SolidSpan<P, F>>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}
