//! Every crossing of a ray with a [`crate::Solid`], and the spans inside it: fixed
//! capacity, no allocation, iterated by reference (`for c in &crossings`) or as slices.
//!
//! A pipe bend crosses a line at most ten times (two tori, four each, and two caps), so
//! [`SolidCrossings`] holds ten; spans alternate with crossings, so at most six (a range
//! that starts inside, then five more entries), which [`SolidSpans`] holds.

use super::ray::Precision;
use super::ray::sealed::Scalar;
use crate::num::fixed_list;

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

/// A stretch `[t_enter, t_exit]` of a ray's range inside a solid, `T` the ray's float and
/// `C` the solid's crossing type: one struct for the ring torus's [`crate::Span`] and every
/// solid's [`SolidSpan`], so that one pairing (`pair_spans`) builds both. `enter` is
/// `None` where the range starts inside (`t_enter = t_min`), `exit` where it ends inside
/// (`t_exit = t_max`, possibly +∞, or a crossing left out because its `t` overflows the
/// ray's float).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct SpanOf<T, C> {
    /// Where the span starts.
    pub t_enter: T,
    /// Where the span ends.
    pub t_exit: T,
    /// The crossing that opens the span, unless it opens at `t_min`.
    pub enter: Option<C>,
    /// The crossing that closes the span, unless it runs to `t_max`.
    pub exit: Option<C>,
}

/// A stretch of the ray's range inside a solid, with the faces of its crossings.
pub type SolidSpan<P, F> = SpanOf<<P as Precision>::Float, SolidCrossing<P, F>>;

impl<T: Scalar, C> SpanOf<T, C> {
    /// The filler of a span list's unused slots.
    pub(crate) const EMPTY: Self = SpanOf {
        t_enter: T::ZERO,
        t_exit: T::ZERO,
        enter: None,
        exit: None,
    };
}

/// Pairs `crossings` (`(t, passage, crossing)`, ascending; entries and exits alternate, an
/// entry first unless the ray `starts_inside`) into the stretches of `[t_min, t_max]`
/// inside the solid, written to `out` in order; returns how many (those past `out`'s
/// length are dropped). A span opens at an entry, or at `t_min` for a ray that starts
/// inside, and closes at the next exit, or at `t_max`; touches open none. Entering and
/// leaving come from the roots' parity, not from `d·n` (`intersect/all.rs`), so the
/// alternation holds by construction.
pub(crate) fn pair_spans<T: Copy, C: Copy>(
    crossings: impl IntoIterator<Item = (T, Passage, C)>,
    starts_inside: bool,
    (t_min, t_max): (T, T),
    out: &mut [SpanOf<T, C>],
) -> usize {
    let mut len = 0;
    let mut push = |(t_enter, enter), t_exit, exit| {
        if let Some(slot) = out.get_mut(len) {
            *slot = SpanOf {
                t_enter,
                t_exit,
                enter,
                exit,
            };
            len += 1;
        }
    };
    let mut open = starts_inside.then_some((t_min, None));
    for (t, passage, c) in crossings {
        match passage {
            Passage::Enter => open = Some((t, Some(c))),
            // Alternation makes `open` set here; a missing one can only be the range's
            // start.
            Passage::Exit => push(open.take().unwrap_or((t_min, None)), t, Some(c)),
            Passage::Touch => {}
        }
    }
    if let Some(start) = open {
        push(start, t_max, None);
    }
    len
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
    /// (`pair_spans`, as the ring torus's `Crossings::spans`). Touches open no span.
    pub fn spans(&self) -> SolidSpans<P, F> {
        let mut spans = [SpanOf::EMPTY; MAX_SPANS];
        let crossings = self.iter().map(|&c| (c.t, c.passage, c));
        let len = pair_spans(crossings, self.starts_inside, self.range(), &mut spans);
        SolidSpans { spans, len }
    }
}

fixed_list! {
    /// The crossings, ascending in `t`: entries and exits alternate (an entry first unless
    /// [`SolidCrossings::starts_inside`]), touches anywhere between them (a touch counts
    /// once).
    impl[P: Precision, F] SolidCrossings<P, F>, crossings: [SolidCrossing<P, F>], "crossings"
}

fixed_list! {
    /// The spans, ascending.
    impl[P: Precision, F] SolidSpans<P, F>, spans: [SolidSpan<P, F>], "spans"
}

impl<P: Precision, F> SolidCrossings<P, F> {
    /// Whether the ray is inside the solid at `t_min` (for a ray from a surface point:
    /// just past its origin). No crossing in range with this true: the whole range lies
    /// inside.
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
