//! What the lab asks of a shape beyond the library's [`Solid`]: its oracle, the culls it
//! accepts, and the guard it may put in front of every cull (a segment's wedge). The
//! lab's cull columns (`eval`), `run`'s shape sweep and the check's cull counts are
//! written once against it ([`forms`], [`Form::kept`]); each shape's impl lives in its own
//! folder (`check/shapes/<shape>/`), and a test's shape implements it in the test.
//!
//! **Why a trait of its own, over an associated [`Solid`].** The library's shapes answer
//! the geometry; the oracle that judges them is the lab's, and a shape's oracle may need
//! more than the library keeps (a posed segment's φ = 0 direction). So a lab shape *has* a
//! solid ([`LabShape::solid`]) rather than being one, and a wrapper carries the rest.
//!
//! **Monomorphic.** A form's verdicts over a batch of rays go through
//! [`torus_cull::CullVisitor`]: one loop per concrete cull, no `dyn` in the loop.

use crate::measure::CountedCull;
use crate::oracle::OracleLabel;
use torus_cull::{Cull, CullKind, CullVisitor, DRay, Named, Precision, Ray, Solid};

/// A shape the lab counts against its oracle.
pub trait LabShape: Sync {
    /// The library's solid the culls and the exact paths answer for.
    type Solid: Solid;

    /// The solid.
    fn solid(&self) -> &Self::Solid;

    /// The oracle's label of `ray` over its range: the literal ray's, or by the
    /// on-surface rule for a ray marked as starting on the surface.
    ///
    /// # Errors
    ///
    /// A line the oracle cannot answer, described.
    fn label(&self, ray: &DRay) -> Result<OracleLabel, String>;

    /// The shape's size, the unit of its margins (R + r for a torus, R + max(a, b) for
    /// a family member, R + r_max for a tube with a bore).
    fn size(&self) -> f64;

    /// Whether `cull` is proved conservative for this shape; a declined cull keeps every
    /// ray ([`Solid::kept_by`] says so) and its records say `accepts: false`.
    fn accepts<C: Cull + ?Sized>(&self, cull: &C) -> bool {
        let _ = cull;
        true
    }

    /// The name of the shape's own test in front of every cull (`wedge` for a segment of
    /// a torus), or `None`.
    fn guard(&self) -> Option<&'static str> {
        None
    }

    /// Whether the guard, then `cull`, keep each ray of `rays`; `false` only where the
    /// ray provably misses. A batch, so that the guarded cull is built once. Without a
    /// guard, [`Solid::kept_by`]'s.
    fn guarded_kept<C: Cull, P: Precision>(&self, cull: C, rays: &[Ray<P>]) -> Vec<bool> {
        let solid = self.solid();
        rays.iter().map(|r| solid.kept_by(&cull, r)).collect()
    }
}

/// The oracle's labels of `rays` ([`LabShape::label`]); an error names `what` and the
/// ray's index counted from `first`.
///
/// # Errors
///
/// The first ray the oracle cannot answer.
pub fn labels<S: LabShape>(
    shape: &S,
    rays: &[DRay],
    (what, first): (&str, usize),
) -> Result<Vec<OracleLabel>, String> {
    rays.iter()
        .enumerate()
        .map(|(i, ray)| {
            shape
                .label(ray)
                .map_err(|e| format!("{what}, ray {}: {e}", first + i))
        })
        .collect()
}

/// One column of cull verdicts: a cull, alone or behind the shape's guard.
#[derive(Debug, Clone)]
pub struct Form {
    /// `skala`, `wedge`, `wedge+skala`.
    pub name: String,
    /// The cull.
    pub cull: CountedCull,
    /// Behind the shape's guard.
    pub guarded: bool,
    /// Whether the shape accepts the cull (a guard always counts: it is the shape's own).
    pub accepts: bool,
}

/// The forms of `culls` on `shape`: each cull alone, in order; then, for a shape with a
/// guard, the guard alone (named as the guard: the guard behind `none`) and behind each
/// other cull (`<guard>+<cull>`), in order.
pub fn forms<S: LabShape>(shape: &S, culls: &[CountedCull]) -> Vec<Form> {
    let none = CountedCull::Timed(CullKind::NoCull);
    let mut all: Vec<Form> = culls
        .iter()
        .map(|&cull| Form {
            name: cull.name().to_string(),
            cull,
            guarded: false,
            accepts: cull.visit(Accepts(shape)),
        })
        .collect();
    if let Some(guard) = shape.guard() {
        all.push(Form {
            name: guard.to_string(),
            cull: none,
            guarded: true,
            accepts: true,
        });
        all.extend(culls.iter().filter(|&&c| c != none).map(|&cull| Form {
            name: format!("{guard}+{}", cull.name()),
            cull,
            guarded: true,
            accepts: true,
        }));
    }
    all
}

impl Form {
    /// The form's verdict on each ray of `rays` (true keeps), in one loop monomorphic in
    /// the cull.
    pub fn kept<S: LabShape, P: Precision>(&self, shape: &S, rays: &[Ray<P>]) -> Vec<bool> {
        self.cull.visit(Kept {
            shape,
            rays,
            guarded: self.guarded,
        })
    }
}

/// [`Form::kept`]'s visit.
struct Kept<'a, S, P: Precision> {
    shape: &'a S,
    rays: &'a [Ray<P>],
    guarded: bool,
}

impl<S: LabShape, P: Precision> CullVisitor for Kept<'_, S, P> {
    type Output = Vec<bool>;
    fn visit<C: Cull>(self, cull: C) -> Vec<bool> {
        if self.guarded {
            self.shape.guarded_kept(cull, self.rays)
        } else {
            let solid = self.shape.solid();
            self.rays.iter().map(|r| solid.kept_by(&cull, r)).collect()
        }
    }
}

/// [`LabShape::accepts`] of a concrete cull.
struct Accepts<'a, S>(&'a S);

impl<S: LabShape> CullVisitor for Accepts<'_, S> {
    type Output = bool;
    fn visit<C: Cull>(self, cull: C) -> bool {
        self.0.accepts(&cull)
    }
}
