//! The worker side of the count channel: each record's work as one call of
//! [`count_region`], the one function callgrind collects in and dumps after.
//!
//! The parent runs this process under `valgrind --tool=callgrind --collect-atstart=no
//! --toggle-collect=*count_region --dump-after=*count_region`, so callgrind counts only
//! what runs inside a region (everything it calls included) and writes one dump per
//! region, in call order. Setting a region up (generating its rays, the torus-frame
//! lines, the oracle's solver cases, warming the wavefront's buffers) happens outside, so
//! a record counts the path alone, as the paired timings time it.

use std::hint::black_box;
use std::io::Write;
use torus_cull::batch::{BatchCull, Dispatch, KeepMask, Lines, Quartics, Wavefront, cull_batch};
use torus_cull::{Cull, CullKind, CullVisitor, Hit, LocalLine, Named, Ray, Torus};

/// The one region function: runs `work` once. Its name is what callgrind's
/// `--toggle-collect` and `--dump-after` match ([`REGION_PATTERN`]); it is not generic, so
/// there is exactly one symbol of that name, and `#[inline(never)]`, so it exists.
#[inline(never)]
pub fn count_region(work: &mut dyn FnMut()) {
    work();
}

/// callgrind's pattern for [`count_region`]'s symbol (demangled, the hash dropped).
pub const REGION_PATTERN: &str = "*count_region";

/// Where the worker announces each region before running it: one line per region on
/// stdout, `record <group> <case> <nu> <cull> <metric> <rays>`, in the order of the dumps.
pub struct Announcer<W: Write> {
    out: W,
}

impl<W: Write> Announcer<W> {
    /// Announces to `out`.
    pub fn new(out: W) -> Announcer<W> {
        Announcer { out }
    }

    /// Any line the parent reads before the records (`isa <name>`).
    pub fn line(&mut self, text: &str) -> std::io::Result<()> {
        writeln!(self.out, "{text}")?;
        self.out.flush()
    }

    /// Announces one region, then runs it.
    pub fn region(
        &mut self,
        key: (&str, &str, f64, &str, &str),
        rays: usize,
        work: &mut dyn FnMut(),
    ) -> std::io::Result<()> {
        let (group, case, nu, cull, metric) = key;
        self.line(&format!(
            "record {group} {case} {nu} {cull} {metric} {rays}"
        ))?;
        count_region(work);
        Ok(())
    }
}

/// One torus and its rays in every form a ring region needs, made outside the regions.
pub struct RingSet<'a> {
    /// The torus.
    pub torus: &'a Torus,
    /// The world rays.
    pub rays: &'a [Ray],
    /// The rays in the torus frame.
    pub lines: Vec<LocalLine>,
    /// The lines as structure of arrays (the SIMD cull's input).
    pub soa: Lines,
}

impl<'a> RingSet<'a> {
    /// `rays` of `torus` in every form.
    pub fn new(torus: &'a Torus, rays: &'a [Ray]) -> RingSet<'a> {
        let lines: Vec<LocalLine> = rays.iter().map(|r| torus.line_to_local(r)).collect();
        let soa = Lines::from_local(&lines);
        RingSet {
            torus,
            rays,
            lines,
            soa,
        }
    }
}

/// The scalar ring metrics: what [`ScalarPass`] runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scalar {
    /// [`torus_cull::intersect_culled`] on every world ray.
    Total,
    /// `Cull::keeps` on every torus-frame line.
    Cull,
}

/// One scalar region of one cull: the loop is compiled per cull (through
/// [`CullKind::visit`]) and the `match` sits outside the region.
pub struct ScalarPass<'s, 'a, W: Write> {
    /// The metric.
    pub metric: Scalar,
    /// The rays.
    pub set: &'s RingSet<'a>,
    /// Where to announce.
    pub announcer: &'s mut Announcer<W>,
    /// The record's key.
    pub key: (&'s str, &'s str, f64, &'s str, &'s str),
}

impl<W: Write> CullVisitor for ScalarPass<'_, '_, W> {
    type Output = std::io::Result<()>;

    fn visit<C: Cull>(self, cull: C) -> std::io::Result<()> {
        let RingSet {
            torus, rays, lines, ..
        } = self.set;
        let bounds = torus.bounds();
        match self.metric {
            Scalar::Total => self.announcer.region(self.key, rays.len(), &mut || {
                for ray in black_box(*rays) {
                    black_box(torus_cull::intersect_culled(&cull, torus, ray));
                }
            }),
            Scalar::Cull => self.announcer.region(self.key, lines.len(), &mut || {
                for line in black_box(lines.as_slice()) {
                    black_box(cull.keeps(bounds, line.origin, line.dir));
                }
            }),
        }
    }
}

/// The wavefront metrics, at the dispatch level.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Batch {
    /// [`Wavefront::intersect`]: the SIMD cull, compaction, the f64 lane solver.
    Total,
    /// [`cull_batch`] alone on the structure-of-arrays lines.
    Cull,
    /// [`Wavefront::intersect_f32`]: the certified f32 path, escalations to f64 included.
    F32Total,
}

/// The wavefront's buffers, reused from region to region as a renderer reuses them.
#[derive(Default)]
pub struct BatchBuffers {
    wavefront: Wavefront,
    hits: Vec<Option<Hit>>,
    keep: KeepMask,
}

/// Runs one batch region of `cull`: one call over the whole set. One untimed call first
/// grows the buffers, so that the region counts the pass and not the allocator's first
/// growth.
pub fn batch_region<W: Write>(
    (dispatch, metric, cull): (&Dispatch, Batch, BatchCull),
    set: &RingSet<'_>,
    buffers: &mut BatchBuffers,
    announcer: &mut Announcer<W>,
    key: (&str, &str, f64, &str, &str),
) -> std::io::Result<()> {
    let BatchBuffers {
        wavefront,
        hits,
        keep,
    } = buffers;
    let (torus, rays) = (set.torus, set.rays);
    let mut pass = || match metric {
        Batch::Total => {
            wavefront.intersect(dispatch, cull, torus, black_box(rays), hits);
            black_box(&hits);
        }
        Batch::F32Total => {
            wavefront.intersect_f32(dispatch, cull, torus, black_box(rays), hits);
            black_box(&hits);
        }
        Batch::Cull => {
            cull_batch(dispatch, cull, torus.bounds(), black_box(&set.soa), keep);
            black_box(&keep);
        }
    };
    pass();
    announcer.region(key, rays.len(), &mut pass)
}

/// A solver's nearest root u ≥ lo of the depressed monic quartic `[c2, c1, c0]`.
pub type Solve = fn(&[f64; 3], f64) -> Option<f64>;

/// The BVH regions of one cull on one scene: closest hit per camera ray, any hit per
/// shadow ray (spawned from the camera rays' hits), as `time bvh` times them.
pub struct BvhPass<'s, W: Write> {
    /// The scene.
    pub scene: &'s crate::scene::Scene,
    /// The camera rays (closest hit).
    pub camera: &'s [Ray],
    /// The shadow rays (any hit).
    pub shadow: &'s [crate::scene::rays::Spawned],
    /// Where to announce.
    pub announcer: &'s mut Announcer<W>,
    /// The scene's name and ν.
    pub unit: (&'s str, f64),
}

impl<W: Write> CullVisitor for BvhPass<'_, W> {
    type Output = std::io::Result<()>;

    fn visit<C: Cull>(self, cull: C) -> std::io::Result<()> {
        let BvhPass {
            scene,
            camera,
            shadow,
            announcer,
            unit: (name, nu),
        } = self;
        let mut stats = crate::scene::TraceStats::default();
        let key = ("bvh", name, nu, cull.name(), "bvh_closest");
        announcer.region(key, camera.len(), &mut || {
            for ray in black_box(camera) {
                black_box(scene.trace(&cull, ray, &mut stats));
            }
        })?;
        let key = ("bvh", name, nu, cull.name(), "bvh_anyhit");
        announcer.region(key, shadow.len(), &mut || {
            for s in black_box(shadow) {
                black_box(scene.occluded_spawned(&cull, s, &mut stats));
            }
        })
    }
}

/// The quartic solvers of the lab's solver records, ours only (the peer crates are the
/// bench's dev-dependencies): each one's nearest root u ≥ the origin's.
pub const SOLVERS: [(&str, Solve); 3] = [
    ("torus_cull", |c, lo| {
        torus_cull::quartic::nearest_root_depressed(c[0], c[1], c[2], lo, f64::INFINITY)
    }),
    ("torus_cull_first", |c, lo| {
        torus_cull::quartic::first_root_depressed(c[0], c[1], c[2], lo, f64::INFINITY)
    }),
    ("torus_cull_all", |c, lo| {
        torus_cull::quartic::solve_depressed_monic(c[0], c[1], c[2])
            .as_slice()
            .iter()
            .copied()
            .filter(|&u| u >= lo)
            .min_by(f64::total_cmp)
    }),
];

/// The batch solver's name in the solver records.
pub const BATCH_SOLVER: &str = "torus_cull_batch";

/// The solver regions of one line family: each of [`SOLVERS`] on every quartic, then the
/// batch solver ([`torus_cull::batch::nearest_roots`]) on all of them at once.
pub fn solver_regions<W: Write>(
    family: &str,
    cases: &[([f64; 3], f64)],
    dispatch: &Dispatch,
    announcer: &mut Announcer<W>,
) -> std::io::Result<()> {
    for (name, solve) in SOLVERS {
        let key = ("solver", family, 0.0, name, "solve");
        announcer.region(key, cases.len(), &mut || {
            for (c, lo) in black_box(cases) {
                black_box(solve(c, *lo));
            }
        })?;
    }
    let mut quartics = Quartics::new();
    for (c, lo) in cases {
        quartics.push(c[0], c[1], c[2], *lo, f64::INFINITY);
    }
    let mut roots = Vec::new();
    torus_cull::batch::nearest_roots(dispatch, &quartics, &mut roots);
    let key = ("solver", family, 0.0, BATCH_SOLVER, "solve");
    announcer.region(key, cases.len(), &mut || {
        torus_cull::batch::nearest_roots(dispatch, black_box(&quartics), &mut roots);
        black_box(&roots);
    })
}

/// The name of `cull` as records write it.
pub fn cull_name(cull: CullKind) -> &'static str {
    cull.name()
}
