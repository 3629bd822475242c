//! The check's parts written against the shape interface alone: the cull counts every
//! shape's job shares ([`count_culls`]: [`torus_cull::Solid::kept_by`] ray by ray), and
//! [`SolidCheck`], any [`LabShape`] as a check's shape with nothing of its own but its
//! classes and how it draws a ray: a new shape is checked before it has a folder under
//! `shapes/` (docs/layout.md, "Adding a shape").

use super::record::{AnswerRecord, ClassRecord, CullRecord, KindRecord};
use super::{About, CheckShape, Job};
use crate::lab_shape::{self, LabShape};
use crate::measure::CountedCull;
use crate::oracle::OracleClass;
use rand::SeedableRng;
use rand_pcg::Pcg64;
use torus_cull::{Cull, CullKind, DRay, Solid};

/// Counts each cull of `culls` on `ray` into its record of `records` (in order): kept or
/// rejected, a rejected oracle hit (a false reject), a rejected far miss.
pub fn count_culls<S: Solid, C: Cull>(
    solid: &S,
    culls: &[C],
    records: &mut [CullRecord],
    ray: &DRay,
    (hit, far_miss): (bool, bool),
) {
    for (cull, record) in culls.iter().zip(records) {
        record.counts.count(solid.kept_by(cull, ray), hit, far_miss);
    }
}

/// The culls' margin η = `ETA_REL`·size, as the library's shapes' checks take it;
/// a miss counts for the capture when its margin exceeds `CAPTURE_ETAS`·η.
pub const ETA_REL: f64 = 1.0 / 4096.0;

/// See [`ETA_REL`].
pub const CAPTURE_ETAS: f64 = 1.25;

/// Any [`LabShape`] as a check's shape: its classes (a label and the posed shape each),
/// f64, every ray drawn by `draw(shape, index, rng)` from the class's own stream.
///
/// Per class: one kind of rays (`drawn`), one cull record per form of
/// [`CullKind::TIMED`] ([`lab_shape::forms`]: each cull, then the shape's guard alone
/// and behind each cull), and the exact intersection's answer ([`Solid::hit_f64`]):
/// `missed` (an oracle hit without a hit) and `invented` (an oracle miss with one), on
/// rows the oracle does not call ambiguous.
pub struct SolidCheck<S, F> {
    /// The shape's name (`--shape`).
    pub name: &'static str,
    /// The classes: label and shape.
    pub classes: Vec<(String, S)>,
    /// Draws ray `index` of a class from its stream.
    pub draw: F,
}

impl<S, F> CheckShape for SolidCheck<S, F>
where
    S: LabShape,
    F: Fn(&S, usize, &mut Pcg64) -> DRay + Sync,
{
    fn about(&self) -> About {
        About {
            name: self.name,
            precision: "f64",
            oracle: "the shape's own (LabShape::label)",
            constants: vec![("eta_rel", ETA_REL), ("capture_etas", CAPTURE_ETAS)],
            chart: ("class", "class", &[]),
            spec: String::new(),
        }
    }

    fn labels(&self) -> Vec<String> {
        self.classes
            .iter()
            .map(|(label, _)| label.clone())
            .collect()
    }

    fn jobs(&self, _rays: usize) -> usize {
        1
    }

    fn check_job(&self, job: Job) -> Result<(ClassRecord, Vec<String>), String> {
        let (name, shape) = &self.classes[job.index];
        let mut rng =
            Pcg64::seed_from_u64(job.seed ^ (job.index as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15));
        let rays: Vec<DRay> = (0..job.rays)
            .map(|i| (self.draw)(shape, i, &mut rng))
            .collect();
        let labels = lab_shape::labels(shape, &rays, (name, 0))?;
        let mut kinds = KindRecord::zeroed(["drawn"]);
        for l in &labels {
            kinds[0].count(l.class);
        }
        let far = CAPTURE_ETAS * ETA_REL * shape.size();
        let timed: Vec<CountedCull> = CullKind::TIMED.iter().map(|&c| c.into()).collect();
        let mut culls = Vec::new();
        for form in lab_shape::forms(shape, &timed) {
            let mut record = CullRecord::new(form.name.clone(), form.accepts);
            for ((kept, l), ray) in form.kept(shape, &rays).into_iter().zip(&labels).zip(&rays) {
                let far_miss =
                    !ray.starts_on_surface() && l.class == OracleClass::Miss && l.margin > far;
                record
                    .counts
                    .count(kept, l.class == OracleClass::Hit, far_miss);
            }
            culls.push(record);
        }
        let mut hit = AnswerRecord::new("hit", true, &["missed", "invented"]);
        for (ray, l) in rays.iter().zip(&labels) {
            if l.class == OracleClass::Ambiguous {
                continue;
            }
            let oracle_hit = l.class == OracleClass::Hit;
            let ours = shape.solid().hit_f64(ray).is_some();
            *hit.wrong.entry("missed".into()).or_default() += u64::from(oracle_hit && !ours);
            *hit.wrong.entry("invented".into()).or_default() += u64::from(!oracle_hit && ours);
        }
        let record = ClassRecord {
            label: name.clone(),
            params: [("class".into(), job.index as f64)].into(),
            words: Default::default(),
            rays: job.rays as u64,
            kinds,
            culls,
            captures: Vec::new(),
            answers: vec![hit],
            ns_per_ray: None,
        };
        Ok((record, Vec::new()))
    }
}
