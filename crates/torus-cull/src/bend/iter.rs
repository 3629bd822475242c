//! A bend's crossings without allocation: iterated by reference, and paired into the
//! spans inside the solid ([`BendCrossings::spans`]), as the ring torus's are.

use super::{BendCrossing, BendCrossings, BendFace};
use crate::Precision;
use crate::geometry::{SolidCrossing, SolidCrossings, SolidSpans};

/// The outer torus: the face of a whole bend, and the filler of fixed-capacity arrays
/// ([`crate::Solid::Face`] asks a default of every face type).
impl Default for BendFace {
    fn default() -> BendFace {
        BendFace::Outer
    }
}

impl<'a, P: Precision> IntoIterator for &'a BendCrossings<P> {
    type Item = &'a BendCrossing<P>;
    type IntoIter = std::slice::Iter<'a, BendCrossing<P>>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

/// The interface's crossings: the same crossings, faces and range.
impl<P: Precision> From<BendCrossings<P>> for SolidCrossings<P, BendFace> {
    fn from(all: BendCrossings<P>) -> Self {
        let (t_min, t_max) = all.range();
        let mut out = SolidCrossings::new(t_min, t_max, all.starts_inside());
        for c in &all {
            out.push(SolidCrossing::new(c.t, c.normal, c.passage, c.face));
        }
        out
    }
}

impl<P: Precision> BendCrossings<P> {
    /// The crossings paired into the stretches of the range inside the solid, ascending
    /// (at most six: a bend crosses a line at most ten times). Touches open no span.
    ///
    /// ```
    /// use glam::Vec3;
    /// use torus_cull::Ray;
    /// use torus_cull::bend::PipeBend;
    /// // A bore of 0.5 in a tube of 1: straight down through the wall, the bore, the wall.
    /// let bend = PipeBend::canonical(4.0, 0.5, 1.0, -0.5, 1.0)?;
    /// let down = Ray::new(Vec3::new(4.0, 10.0, 0.0), Vec3::NEG_Y)?;
    /// let spans = bend.intersect_all(&down).spans();
    /// let ends: Vec<(f32, f32)> = spans.iter().map(|s| (s.t_enter, s.t_exit)).collect();
    /// assert_eq!(ends, [(9.0, 9.5), (10.5, 11.0)]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn spans(&self) -> SolidSpans<P, BendFace> {
        SolidCrossings::from(*self).spans()
    }
}
