//! `torus-cull check`: every cull and intersector of one shape against the oracle, class
//! by class, at one precision (`f64`: the culls and the exact intersection; `f32`: the f32
//! paths). One pipeline for every shape: this module draws the jobs on threads, sums their
//! records per class ([`record::ClassRecord::add`]) and writes one file kind
//! ([`record::CheckFile`]); what a shape brings (its classes, its ray kinds, its oracle's
//! label, its culls and intersectors) lives in its own folder under [`shapes`], behind
//! [`CheckShape`]. Nothing here names a shape.
//!
//! The counts do not depend on the threads: each job draws from its own seed (the class's
//! index and the job's), and every count is a sum.

pub mod record;
pub mod shapes;
pub mod solid;
pub mod table;

use record::{CheckFile, ClassRecord, SCHEMA_VERSION, TOOL};
use std::fmt::Write as _;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

/// What the generic check asks of a shape. A shape's classes are fixed when it is built
/// (from its flags); `index` below is the class's place among them, which seeds its rays,
/// so that a subset of the classes draws the same rays as the whole.
pub trait CheckShape: Sync {
    /// What the shape is, for the file and the charts.
    fn about(&self) -> About;
    /// The classes' labels, in order.
    fn labels(&self) -> Vec<String>;
    /// Jobs per class for `rays` rays per class.
    fn jobs(&self, rays: usize) -> usize;
    /// One job: its record (with the class's label, parameters and words) and up to a
    /// few disagreements described for the console.
    ///
    /// # Errors
    ///
    /// A class the shape cannot build or a ray the oracle cannot label, named.
    fn check_job(&self, job: Job) -> Result<(ClassRecord, Vec<String>), String>;
    /// After every class is counted, on one thread: the timings, where the shape has any.
    fn after(&self, _job: Job, _record: &mut ClassRecord) {}
}

/// One job of a check: the `job`-th of class `index`, of `rays` rays per class drawn
/// from `seed`.
#[derive(Debug, Clone, Copy)]
pub struct Job {
    /// The class's place among the shape's classes.
    pub index: usize,
    /// The job's place in its class.
    pub job: usize,
    /// Rays per class.
    pub rays: usize,
    /// The check's seed.
    pub seed: u64,
}

/// What a shape is, for the file and the charts.
#[derive(Debug, Clone)]
pub struct About {
    /// The shape's name (`--shape`).
    pub name: &'static str,
    /// `f64` or `f32`.
    pub precision: &'static str,
    /// Which oracle labels the rays, in the file.
    pub oracle: &'static str,
    /// The tolerances and thresholds of the counts, in the file.
    pub constants: Vec<(&'static str, f64)>,
    /// What the charts put on x (a key of the classes' `params`), its axis title, and the
    /// parameters whose values make one chart's group.
    pub chart: (&'static str, &'static str, &'static [&'static str]),
    /// What the file's workload hash is over, besides the rays, the seed and the labels.
    pub spec: String,
}

/// Disagreements kept per class for the console.
const SHOWN: usize = 3;

/// A class's sum so far, and its first disagreements.
type Slot = Mutex<Option<(ClassRecord, Vec<String>)>>;

/// The outcome of [`check`]: the records, and per class its first disagreements.
pub struct Checked {
    /// One record per class checked.
    pub records: Vec<ClassRecord>,
    /// (class label, description) of the first disagreements.
    pub disagreements: Vec<(String, String)>,
}

/// The classes `selected` (indices into the shape's labels) of `shape`, `rays` rays each,
/// on `threads` threads; `progress(done, all)` in jobs.
///
/// # Errors
///
/// The first job that failed (a class the shape refuses, a ray the oracle cannot label).
pub fn check(
    shape: &dyn CheckShape,
    selected: &[usize],
    (rays, seed): (usize, u64),
    threads: usize,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Checked, String> {
    let per_class = shape.jobs(rays);
    let jobs: Vec<(usize, usize)> = (0..selected.len())
        .flat_map(|c| (0..per_class).map(move |j| (c, j)))
        .collect();
    let classes: Vec<Slot> = selected.iter().map(|_| Mutex::new(None)).collect();
    let failed: Mutex<Option<String>> = Mutex::new(None);
    let (next, done) = (AtomicUsize::new(0), AtomicUsize::new(0));
    std::thread::scope(|s| {
        for _ in 0..threads.max(1) {
            s.spawn(|| {
                while let Some(&(c, j)) = jobs.get(next.fetch_add(1, Ordering::Relaxed)) {
                    let job = Job {
                        index: selected[c],
                        job: j,
                        rays,
                        seed,
                    };
                    match shape.check_job(job) {
                        Ok((record, why)) => {
                            let mut slot = classes[c].lock().expect("no worker panicked");
                            match slot.as_mut() {
                                None => *slot = Some((record, why)),
                                Some((sum, shown)) => {
                                    sum.add(&record);
                                    let room = SHOWN.saturating_sub(shown.len());
                                    shown.extend(why.into_iter().take(room));
                                }
                            }
                        }
                        Err(e) => {
                            failed.lock().expect("no worker panicked").get_or_insert(e);
                        }
                    }
                    progress(done.fetch_add(1, Ordering::Relaxed) + 1, jobs.len());
                }
            });
        }
    });
    if let Some(e) = failed.into_inner().expect("no worker panicked") {
        return Err(e);
    }
    let mut records = Vec::with_capacity(selected.len());
    let mut disagreements = Vec::new();
    for (&index, slot) in selected.iter().zip(classes) {
        let (mut record, why) = slot
            .into_inner()
            .expect("no worker panicked")
            .ok_or_else(|| format!("class {index}: no job ran (0 rays?)"))?;
        record.finish();
        let job = Job {
            index,
            job: 0,
            rays,
            seed,
        };
        shape.after(job, &mut record);
        disagreements.extend(why.into_iter().map(|w| (record.label.clone(), w)));
        records.push(record);
    }
    Ok(Checked {
        records,
        disagreements,
    })
}

impl CheckFile {
    /// The file of `records`, checked on `shape` with `rays` per class from `seed`.
    pub fn new(shape: &dyn CheckShape, records: Vec<ClassRecord>, rays: usize, seed: u64) -> Self {
        let about = shape.about();
        let (name, precision) = (about.name, about.precision);
        let mut spec = format!(
            "{TOOL} v{SCHEMA_VERSION} {name} {precision} rays {rays} seed {seed} {}",
            about.spec
        );
        for r in &records {
            let _ = write!(spec, " [{}]", r.label);
        }
        let workload_name = format!("{TOOL}-{name}-{precision}");
        let workload = crate::workload::spec::Workload::drawn(&workload_name, seed, rays, &spec);
        let meta = crate::results::Results::new(&workload, TOOL).meta;
        let (x, title, group_by) = about.chart;
        CheckFile {
            schema_version: SCHEMA_VERSION,
            meta,
            shape: name.into(),
            precision: precision.into(),
            rays_per_class: rays as u64,
            seed,
            oracle: about.oracle.into(),
            constants: about
                .constants
                .into_iter()
                .map(|(k, v)| (k.into(), v))
                .collect(),
            chart: record::ChartAxes {
                x: x.into(),
                x_title: title.into(),
                group_by: group_by.iter().map(|g| (*g).into()).collect(),
            },
            classes: records,
        }
    }
}
