//! The timed loops: one cull, one metric, one pass over a batch.
//!
//! [`CullKind::visit`] hands the concrete cull type to [`time_pass`]'s loop, so each loop
//! is compiled per cull and nothing is dispatched per ray; the one `match` per pass sits
//! outside the timed region.

use crate::{Cull, CullBounds, CullKind, CullVisitor, LocalLine, Ray, Torus, intersect_culled};
use std::fmt;
use std::hint::black_box;
use std::time::{Duration, Instant};

/// What a contender's timing covers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Metric {
    /// What a renderer pays per ray: world ray → torus frame, the cull, and the exact
    /// intersection when the cull keeps the ray ([`intersect_culled`]).
    TotalNs,
    /// The cull alone on torus-frame lines.
    CullNs,
}

impl Metric {
    /// Both, in table order.
    pub const ALL: [Metric; 2] = [Metric::TotalNs, Metric::CullNs];

    /// The stable name used in results: `total_ns` or `cull_ns`.
    pub fn name(self) -> &'static str {
        match self {
            Metric::TotalNs => "total_ns",
            Metric::CullNs => "cull_ns",
        }
    }
}

impl fmt::Display for Metric {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// One torus and its batch, in both forms the metrics need.
#[derive(Debug, Clone)]
pub struct Workset<'a> {
    torus: &'a Torus,
    bounds: CullBounds,
    rays: &'a [Ray],
    lines: Vec<LocalLine>,
}

impl<'a> Workset<'a> {
    /// The batch `rays` of `torus`; the torus-frame lines are made here, outside any timing.
    pub fn new(torus: &'a Torus, rays: &'a [Ray]) -> Workset<'a> {
        Workset {
            torus,
            bounds: CullBounds::of(torus),
            rays,
            lines: rays.iter().map(|r| torus.line_to_local(r)).collect(),
        }
    }

    /// Rays in the batch.
    pub fn len(&self) -> usize {
        self.rays.len()
    }

    /// Whether the batch is empty.
    pub fn is_empty(&self) -> bool {
        self.rays.is_empty()
    }
}

/// Time `reps` passes of `cull` over the batch, measuring `metric`.
pub fn time_pass(cull: CullKind, metric: Metric, set: &Workset<'_>, reps: usize) -> Duration {
    cull.visit(Pass { metric, set, reps })
}

struct Pass<'s, 'a> {
    metric: Metric,
    set: &'s Workset<'a>,
    reps: usize,
}

impl CullVisitor for Pass<'_, '_> {
    type Output = Duration;

    #[inline(never)]
    fn visit<C: Cull>(self, cull: C) -> Duration {
        let Workset {
            torus,
            bounds,
            rays,
            lines,
        } = self.set;
        let start = Instant::now();
        match self.metric {
            Metric::TotalNs => {
                for _ in 0..self.reps {
                    // Opaque per pass, so no work is hoisted out of the repetitions.
                    for ray in black_box(*rays) {
                        black_box(intersect_culled(&cull, torus, bounds, ray));
                    }
                }
            }
            Metric::CullNs => {
                for _ in 0..self.reps {
                    for line in black_box(lines.as_slice()) {
                        black_box(cull.keeps(bounds, line.origin, line.dir));
                    }
                }
            }
        }
        start.elapsed()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::workload::{Case, Pose, generate};

    #[test]
    fn every_timed_cull_runs_both_metrics() {
        let batch = generate(Case::Uniform, 4.0, 64, 1, Pose::Random).unwrap();
        let set = Workset::new(&batch.torus, &batch.rays);
        assert_eq!(set.len(), 64);
        for cull in CullKind::TIMED {
            for metric in Metric::ALL {
                let one = time_pass(cull, metric, &set, 1);
                assert!(one > Duration::ZERO, "{cull} {metric}");
            }
        }
        assert_eq!(Metric::TotalNs.to_string(), "total_ns");
        assert_eq!(Metric::CullNs.to_string(), "cull_ns");
    }
}
