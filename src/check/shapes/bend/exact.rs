//! The exact intersection of a pipe bend against the bend oracle, ray by ray: the one
//! judge of `torus-cull bend` and of the bend oracle tests.
//!
//! A literal ray ([`compare`]): `intersect` against the oracle's first crossing, and
//! `intersect_all` against its crossings one by one (a count that differs is one missed or
//! invented); a face counts as right when it is the oracle's or any face within
//! [`TOL`]·S of the oracle's point (a cap's edge); t within `TOL`·S, the passage, the
//! normal within 10⁻⁶. Rows whose answer the input does not determine are ambiguous and
//! not judged: the oracle's band, two crossings closer than `TOL`·S, a tangency within it,
//! a crossing within it of the range's ends. A spawned ray ([`compare_spawned`]): both
//! against the oracle's on-surface rule's first crossing.

use super::rays::Spec;
use crate::check_counts::add_counts;
use crate::oracle::bend::{BendQuery, Face, Passage as OraclePassage};
use crate::oracle::{OracleClass, OracleLabel};
use torus_cull::bend::{BendFace, PipeBend};
use torus_cull::{DRay, Passage};

/// The expected answers are held to this × S.
pub const TOL: f64 = 1e-9;

/// The oracle's name for the library's face.
pub fn face(f: BendFace) -> Face {
    match f {
        BendFace::Outer => Face::Outer,
        BendFace::Inner => Face::Inner,
        BendFace::StartCap => Face::StartCap,
        BendFace::EndCap => Face::EndCap,
    }
}

/// The oracle's name for the library's passage.
pub fn passage(p: Passage) -> OraclePassage {
    match p {
        Passage::Enter => OraclePassage::Entering,
        Passage::Exit => OraclePassage::Leaving,
        Passage::Touch => OraclePassage::Touching,
    }
}

/// Counts of a comparison with the oracle.
#[derive(Debug, Default, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Tally {
    /// Rays compared or found ambiguous.
    pub rays: u64,
    /// Judged rays the oracle hits.
    pub hits: u64,
    /// Judged rays the oracle misses.
    pub misses: u64,
    /// Rays not judged (module docs).
    pub ambiguous: u64,
    /// `intersect`: the oracle has a crossing in range, the library none.
    pub missed: u64,
    /// `intersect`: a hit the oracle has not.
    pub invented: u64,
    /// `intersect`: the hit's face is none of the faces through the oracle's point.
    pub wrong_face: u64,
    /// `intersect`: the right face, but t, the side or the normal off.
    pub wrong_value: u64,
    /// `intersect_all`: fewer crossings than the oracle's.
    pub all_missed: u64,
    /// `intersect_all`: more crossings than the oracle's.
    pub all_invented: u64,
    /// `intersect_all`: a crossing of a wrong face.
    pub all_wrong_face: u64,
    /// `intersect_all`: a crossing's t or passage off, or its `starts_inside`.
    pub all_wrong_value: u64,
    /// The largest |t − t_oracle|·|d|/S of `intersect`'s hits.
    pub max_t_error_rel: f64,
}

impl Tally {
    /// Every disagreement.
    pub fn bad(&self) -> u64 {
        self.missed
            + self.invented
            + self.wrong_face
            + self.wrong_value
            + self.all_missed
            + self.all_invented
            + self.all_wrong_face
            + self.all_wrong_value
    }

    /// Adds `o`'s counts (the larger t error).
    pub fn add(&mut self, o: &Tally) {
        add_counts!(self, o;
            rays, hits, misses, ambiguous, missed, invented, wrong_face, wrong_value,
            all_missed, all_invented, all_wrong_face, all_wrong_value);
        self.max_t_error_rel = self.max_t_error_rel.max(o.max_t_error_rel);
    }
}

/// Compares `intersect` and `intersect_all` on the literal `ray` with the oracle, whose
/// label of it is `label` (`spec.query(ray).classify()`). Returns the per-ray tally and,
/// on a disagreement, a description.
pub fn compare(
    spec: &Spec,
    bend: &PipeBend,
    ray: &DRay,
    label: &OracleLabel,
) -> (Tally, Option<String>) {
    let q = spec.query(ray);
    let size = spec.size();
    let tol = TOL * size;
    let len = ray.dir().length();
    let mut t = Tally {
        rays: 1,
        ..Tally::default()
    };
    // Crossings closer than the tolerance (a corner clipped by less) or within it of
    // the range's ends are not determined by the input.
    // The whole line's crossings, walked once: the closest pair among them is
    // `BendQuery::closest_crossings`, those in range are `BendQuery::crossings`.
    let line = q.over(f64::NEG_INFINITY, f64::INFINITY).crossings();
    let closest = line
        .windows(2)
        .map(|w| (w[1].0 - w[0].0) * len)
        .fold(f64::INFINITY, f64::min);
    let ambiguous = label.class == OracleClass::Ambiguous
        || closest <= tol
        || line.iter().any(|c| {
            (c.0 - ray.t_min()).abs() * len <= tol || (c.0 - ray.t_max()).abs() * len <= tol
        })
        || q.tangency(tol) <= tol;
    if ambiguous {
        t.ambiguous = 1;
        return (t, None);
    }
    if label.class == OracleClass::Hit {
        t.hits = 1;
    } else {
        t.misses = 1;
    }
    let want: Vec<_> = line
        .into_iter()
        .filter(|c| c.0 >= ray.t_min() && c.0 <= ray.t_max())
        .collect();
    let all = bend.intersect_all(ray);
    let got = all.crossings();
    let first = bend.intersect(ray);
    let mut why = Vec::new();
    match (want.first(), first) {
        (None, Some(h)) => {
            t.invented += 1;
            why.push(format!("intersect invented {h:?}"));
        }
        (Some(w), None) => {
            t.missed += 1;
            why.push(format!("intersect missed {w:?}"));
        }
        (Some(w), Some(h)) => {
            let p = ray.origin() + ray.dir() * w.0;
            let faces = q.faces_at(p, tol);
            t.max_t_error_rel = (h.t - w.0).abs() * len / size;
            if face(h.face) != w.2 && !faces.contains(&face(h.face)) {
                t.wrong_face += 1;
                why.push(format!(
                    "intersect face {:?}, oracle {w:?} {faces:?}",
                    h.face
                ));
            } else {
                let n = q.normal(face(h.face), p);
                let ok = (h.t - w.0).abs() * len <= tol
                    && h.front_face == (w.1 == OraclePassage::Entering)
                    && (h.normal - n).length() <= 1e-6;
                if !ok {
                    t.wrong_value += 1;
                    why.push(format!("intersect {h:?}, oracle {w:?}, normal {n}"));
                }
            }
        }
        (None, None) => {}
    }
    if got.len() != want.len() {
        if got.len() > want.len() {
            t.all_invented += 1;
        } else {
            t.all_missed += 1;
        }
        why.push(format!("intersect_all {got:?}, oracle {want:?}"));
    } else {
        for (g, w) in got.iter().zip(&want) {
            let p = ray.origin() + ray.dir() * w.0;
            let faces = q.faces_at(p, tol);
            if face(g.face) != w.2 && !faces.contains(&face(g.face)) {
                t.all_wrong_face += 1;
                why.push(format!("intersect_all face {g:?}, oracle {w:?} {faces:?}"));
            } else if (g.t - w.0).abs() * len > tol || passage(g.passage) != w.1 {
                t.all_wrong_value += 1;
                why.push(format!("intersect_all {g:?}, oracle {w:?}"));
            }
        }
        if all.starts_inside() != q.starts_inside() {
            t.all_wrong_value += 1;
            why.push(format!("starts_inside {}", all.starts_inside()));
        }
    }
    let why = (!why.is_empty()).then(|| format!("{spec:?}\n{ray:?}\n{}", why.join("\n")));
    (t, why)
}

/// What the oracle's on-surface rule expects of a ray from a face point: `Some(first)`
/// (its first crossing past the origin's own, or `None`), `None` where undetermined.
pub fn from_surface_reference(
    spec: &Spec,
    ray: &DRay,
) -> Option<Option<(f64, OraclePassage, Face)>> {
    let q = spec.query(ray);
    match q.classify_from_surface().class {
        OracleClass::Ambiguous => None,
        OracleClass::Miss => Some(None),
        OracleClass::Hit => Some(Some(q.first_crossing_from_surface()?)),
    }
}

/// Compares `intersect` and `intersect_all`'s first crossing on a ray spawned from a
/// face with the oracle's on-surface rule (t within [`TOL`]·S, the face or one through
/// the oracle's point, the side); ambiguous where the rule is undetermined. `label` is
/// the rule's (`spec.query(ray).classify_from_surface()`).
pub fn compare_spawned(
    spec: &Spec,
    bend: &PipeBend,
    ray: &DRay,
    label: &OracleLabel,
) -> (Tally, Option<String>) {
    let mut t = Tally {
        rays: 1,
        ..Tally::default()
    };
    let want = match label.class {
        OracleClass::Ambiguous => None,
        OracleClass::Miss => Some(None),
        OracleClass::Hit => spec.query(ray).first_crossing_from_surface().map(Some),
    };
    let Some(want) = want else {
        t.ambiguous = 1;
        return (t, None);
    };
    if want.is_some() {
        t.hits = 1;
    } else {
        t.misses = 1;
    }
    let size = spec.size();
    let tol = TOL * size;
    let len = ray.dir().length();
    let got = bend.intersect(ray);
    let all = bend.intersect_all(ray);
    let got_all = all.crossings().first().copied();
    let mut why = Vec::new();
    let moved: BendQuery = spec
        .query(ray)
        .on_surface()
        .map_or(spec.query(ray), |q| q.0);
    // (missed, invented, wrong face, wrong value) of one answer (t, face, entering).
    let judge = |answer: Option<(f64, BendFace, bool)>| -> [bool; 4] {
        match (want, answer) {
            (None, None) => [false; 4],
            (Some(_), None) => [true, false, false, false],
            (None, Some(_)) => [false, true, false, false],
            (Some((tw, pw, fw)), Some((tg, fg, entering))) => {
                let q = &moved;
                let point = q.origin + q.dir * tw;
                let face_ok = face(fg) == fw || q.faces_at(point, tol).contains(&face(fg));
                let value_ok =
                    (tg - tw).abs() * len <= tol && entering == (pw == OraclePassage::Entering);
                [false, false, !face_ok, face_ok && !value_ok]
            }
        }
    };
    let one = judge(got.map(|h| (h.t, h.face, h.front_face)));
    if let (Some(h), Some((tw, _, _))) = (got, want) {
        t.max_t_error_rel = (h.t - tw).abs() * len / size;
    }
    [t.missed, t.invented, t.wrong_face, t.wrong_value] = one.map(u64::from);
    let first = judge(got_all.map(|c| (c.t, c.face, c.passage == Passage::Enter)));
    [
        t.all_missed,
        t.all_invented,
        t.all_wrong_face,
        t.all_wrong_value,
    ] = first.map(u64::from);
    if t.bad() > 0 {
        why.push(format!(
            "spawned: library {got:?}, all's first {got_all:?}, oracle {want:?}"
        ));
    }
    let why = (!why.is_empty()).then(|| format!("{spec:?}\n{ray:?}\n{}", why.join("\n")));
    (t, why)
}
