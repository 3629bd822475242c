//! `run`'s sweep of the other shapes: every torus-family member and pipe bend of a
//! workload's `shapes` key, each cull's rejections counted against the shape's own
//! oracle (the family oracle, `oracle::family`, through [`crate::family_label`]; the bend
//! oracle, `oracle::bend`), as the ring's are in [`crate::measure`]. Never timed.
//!
//! **Rays.** The literal ray kinds of the shape's check (`check::shapes::family::rays`: uniform,
//! grazing, axis/hole; `check::shapes::bend::rays`: random, cut-away arc, pipe axis, hole, caps'
//! edges, bore tangent), in turn, `shapes.rays` per member, each member in a random pose
//! drawn from the workload's seed. Rays spawned from the surface are the checks' matter:
//! the line of such a ray passes through its own surface point, which no line cull can
//! reject, so they would only dilute what a cull saves on the rays a renderer casts.
//!
//! **Culls.** Each of `run`'s culls, on the member (a family member's cull is applied to
//! its circular image; a cull that does not accept the member's shape is declined and
//! keeps every ray, and its record says so: `accepts: false`); for a bend, each on the
//! outer torus, then the segment's wedge alone (`wedge`, `PipeBend::wedge_cull(NoCull)`)
//! and behind each cull (`wedge+<cull>`), as `bend` and `time bend` price them.

mod bend;
mod family;

use crate::lab_shape::{self, LabShape};
use crate::measure::CountedCull;
use crate::oracle::{OracleClass, OracleLabel};
use crate::results::RejectionRecord;
use crate::results::shapes::{MIXED_CASE, ShapeRecord};
use crate::workload::shapes_spec::ShapesSpec;
use glam::DVec3;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use torus_cull::DRay;

pub use bend::refuse_bends;

/// A ray a cull rejected although the shape's oracle calls it a hit, with what it takes
/// to replay it.
#[derive(Debug, Clone)]
pub struct ShapeFalseReject {
    /// The member (`spindle nu=0.5 b/a=4`).
    pub member: String,
    /// Its pose and radii, in full.
    pub pose: String,
    /// The cull at fault (`skala`, `wedge+skala`).
    pub cull: String,
    /// The ray's index among the member's rays.
    pub index: usize,
    /// The ray's f64 origin.
    pub origin: DVec3,
    /// Its f64 direction.
    pub dir: DVec3,
    /// The oracle's margin.
    pub margin: f64,
}

/// One member's (or one bend pose's) rays and counts while they are drawn.
#[derive(Debug, Clone, Default)]
pub struct Tally {
    /// Rays labelled.
    pub rays: u64,
    /// The oracle's hits.
    pub hits: u64,
    /// Its misses.
    pub misses: u64,
    /// Its ambiguous rays.
    pub ambiguous: u64,
    /// Per cull form: rejected, false rejects.
    pub rejected: Vec<(u64, u64)>,
}

impl Tally {
    fn new(forms: usize) -> Tally {
        Tally {
            rejected: vec![(0, 0); forms],
            ..Tally::default()
        }
    }

    /// Counts the oracle's labels of a batch.
    fn label(&mut self, labels: &[OracleLabel]) {
        for l in labels {
            self.rays += 1;
            match l.class {
                OracleClass::Hit => self.hits += 1,
                OracleClass::Miss => self.misses += 1,
                OracleClass::Ambiguous => self.ambiguous += 1,
            }
        }
    }

    /// Counts cull form `form`'s verdicts (`true` keeps) on the labelled batch; the
    /// indices of the oracle hits it rejected.
    fn verdicts(&mut self, form: usize, labels: &[OracleLabel], kept: &[bool]) -> Vec<usize> {
        let mut bad = Vec::new();
        for (i, (l, &keep)) in labels.iter().zip(kept).enumerate() {
            if !keep {
                self.rejected[form].0 += 1;
                if l.class == OracleClass::Hit {
                    self.rejected[form].1 += 1;
                    bad.push(i);
                }
            }
        }
        bad
    }

    fn add(&mut self, o: &Tally) {
        self.rays += o.rays;
        self.hits += o.hits;
        self.misses += o.misses;
        self.ambiguous += o.ambiguous;
        for (a, b) in self.rejected.iter_mut().zip(&o.rejected) {
            a.0 += b.0;
            a.1 += b.1;
        }
    }

    /// The record of form `form`, named `cull`, with the member's parameters `shape`
    /// (its counts filled in here).
    fn record(
        &self,
        form: usize,
        cull: &str,
        nu: f64,
        accepts: bool,
        shape: &Params,
    ) -> ShapeRecord {
        let (rejected, false_rejects) = self.rejected[form];
        ShapeRecord {
            shape: shape.shape.clone(),
            aspect: shape.aspect,
            bore: shape.bore,
            segment_deg: shape.segment_deg,
            accepts,
            counts: RejectionRecord {
                case: MIXED_CASE.into(),
                nu,
                cull: cull.into(),
                rays: self.rays,
                hits: self.hits,
                misses: self.misses,
                ambiguous: self.ambiguous,
                rejected,
                false_rejects,
                rejection_rate: if self.rays > 0 {
                    rejected as f64 / self.rays as f64
                } else {
                    0.0
                },
                // A declined cull culls nothing: it claims no capture.
                miss_capture: (accepts && self.misses > 0)
                    .then(|| rejected as f64 / self.misses as f64),
            },
        }
    }
}

/// A member's parameters as its records carry them ([`ShapeRecord`]'s fields of the same
/// names): `shape` (`ring`, `elliptic`, `horn`, `spindle`, `bend`, or a test's own),
/// `aspect` b/a, `bore` r_min/r_max, `segment_deg` Δφ in degrees.
#[derive(Debug, Clone, Default)]
pub struct Params {
    shape: String,
    aspect: Option<f64>,
    bore: Option<f64>,
    segment_deg: Option<f64>,
}

impl Params {
    /// A shape's name with none of the family's and the bends' parameters (a shape of
    /// another kind, a test's own).
    pub fn named(shape: &str) -> Params {
        Params {
            shape: shape.into(),
            ..Params::default()
        }
    }
}

/// Rays of every member of `spec`: what the progress bar counts.
pub fn rays(spec: &ShapesSpec) -> u64 {
    (spec.family.len() + spec.bends.len()) as u64 * spec.rays as u64
}

/// The shape records of every member of `spec` over `culls` (family members first, then
/// bends, each in `spec`'s order, culls in `culls`' order; a bend's `wedge` forms after
/// its culls), with any false rejects, on `threads` threads; `progress` is called with
/// each finished unit's rays.
///
/// # Errors
///
/// A member the library refuses or a ray the oracle cannot answer, named.
pub fn sweep(
    spec: &ShapesSpec,
    culls: &[CountedCull],
    seed: u64,
    threads: usize,
    progress: &(dyn Fn(u64) + Sync),
) -> Result<(Vec<ShapeRecord>, Vec<ShapeFalseReject>), String> {
    let family_units = spec.family.len();
    let bend_units = bend::units(spec);
    let units = family_units + bend_units.len();
    let run = |i: usize| {
        if i < family_units {
            family::member(spec.family[i], i, spec.rays, seed, culls)
        } else {
            bend::pose(&bend_units[i - family_units], spec, seed, culls)
        }
    };
    let done = parallel(units, threads, &|i| {
        let out = run(i);
        if let Ok(unit) = &out {
            progress(unit.tally.rays);
        }
        out
    });
    let mut records = Vec::new();
    let mut false_rejects = Vec::new();
    let mut done = done.into_iter();
    for _ in 0..family_units {
        let unit = done.next().expect("every unit ran")?;
        records.extend(unit.records());
        false_rejects.extend(unit.false_rejects);
    }
    // A bend's poses are summed into one record per form.
    let mut class: Option<(usize, Unit)> = None;
    for unit in &bend_units {
        let u = done.next().expect("every unit ran")?;
        class = match class {
            Some((c, mut acc)) if c == unit.class => {
                acc.tally.add(&u.tally);
                acc.false_rejects.extend(u.false_rejects);
                Some((c, acc))
            }
            other => {
                if let Some((_, acc)) = other {
                    records.extend(acc.records());
                    false_rejects.extend(acc.false_rejects);
                }
                Some((unit.class, u))
            }
        };
    }
    if let Some((_, acc)) = class {
        records.extend(acc.records());
        false_rejects.extend(acc.false_rejects);
    }
    Ok((records, false_rejects))
}

/// One unit's tally and the names of its cull forms: a member (or one bend pose) swept.
pub struct Unit {
    /// The member's ν.
    pub nu: f64,
    /// Its parameters.
    pub params: Params,
    /// Per form: its name and whether it accepts the shape.
    pub forms: Vec<(String, bool)>,
    /// Its counts.
    pub tally: Tally,
    /// The rays a form rejected although the oracle calls them hits.
    pub false_rejects: Vec<ShapeFalseReject>,
}

/// What a swept shape's false rejects are reported with: the member's words, its pose
/// and the first index of its rays.
#[derive(Debug, Clone)]
pub struct Member {
    /// The member (`spindle nu=0.5 b/a=4`).
    pub label: String,
    /// Its pose and radii, in full.
    pub pose: String,
    /// The index of its first ray among the member's.
    pub first: usize,
}

/// Sweeps `shape` over `rays` with `culls`, through the interface alone: each ray
/// labelled by the shape's oracle ([`LabShape::label`]), each cull form's verdicts
/// ([`lab_shape::forms`]: the culls, then the shape's guard alone and behind each cull)
/// from [`torus_cull::Solid::kept_by`]; `nu` and `params` go into the records. Every
/// shape of `run`'s sweep goes through here, and a test's own shape can.
///
/// # Errors
///
/// A ray the oracle cannot answer, named with the member and the ray's index.
pub fn sweep_shape<S: LabShape>(
    shape: &S,
    rays: &[DRay],
    culls: &[CountedCull],
    (member, nu, params): (&Member, f64, Params),
) -> Result<Unit, String> {
    let labels = lab_shape::labels(shape, rays, (&member.label, member.first))?;
    let forms = lab_shape::forms(shape, culls);
    let mut tally = Tally::new(forms.len());
    tally.label(&labels);
    let mut false_rejects = Vec::new();
    for (j, form) in forms.iter().enumerate() {
        let kept = form.kept(shape, rays);
        for i in tally.verdicts(j, &labels, &kept) {
            false_rejects.push(ShapeFalseReject {
                member: member.label.clone(),
                pose: member.pose.clone(),
                cull: form.name.clone(),
                index: member.first + i,
                origin: rays[i].origin(),
                dir: rays[i].dir(),
                margin: labels[i].margin,
            });
        }
    }
    Ok(Unit {
        nu,
        params,
        forms: forms.into_iter().map(|f| (f.name, f.accepts)).collect(),
        tally,
        false_rejects,
    })
}

impl Unit {
    /// The unit's records, one per cull form.
    pub fn records(&self) -> impl Iterator<Item = ShapeRecord> + '_ {
        self.forms
            .iter()
            .enumerate()
            .map(|(j, (cull, accepts))| self.tally.record(j, cull, self.nu, *accepts, &self.params))
    }
}

/// `f(i)` for every `i < n`, on `threads` threads, in order of `i`.
fn parallel<T: Send>(n: usize, threads: usize, f: &(dyn Fn(usize) -> T + Sync)) -> Vec<T> {
    let next = AtomicUsize::new(0);
    let out: Mutex<Vec<Option<T>>> = Mutex::new((0..n).map(|_| None).collect());
    std::thread::scope(|s| {
        for _ in 0..threads.max(1) {
            s.spawn(|| {
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    if i >= n {
                        break;
                    }
                    let r = f(i);
                    out.lock().unwrap()[i] = Some(r);
                }
            });
        }
    });
    out.into_inner()
        .unwrap()
        .into_iter()
        .map(|r| r.expect("every unit ran"))
        .collect()
}
