//! Pipe bends for the oracle tests: one bend's parameters as both the library's
//! `PipeBend` and the oracle's `BendQuery`, random poses and rays, and the comparison of
//! the exact intersection with the oracle.

use glam::DVec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use std::f64::consts::TAU;
use torus_cull::DRay;
use torus_cull::bend::{BendFace, PipeBend};
use torus_cull::{NoCull, Passage};
use torus_cull_lab::oracle::bend::{BendQuery, Face, Passage as OraclePassage};
use torus_cull_lab::oracle::{AMBIGUITY_REL, OracleClass};

/// A bend's parameters (the library's argument order).
#[derive(Debug, Clone, Copy)]
pub struct Spec {
    pub center: DVec3,
    pub axis: DVec3,
    pub phi_zero: DVec3,
    pub major: f64,
    pub bore: f64,
    pub tube: f64,
    pub start: f64,
    pub delta: f64,
}

impl Spec {
    pub fn canonical(major: f64, bore: f64, tube: f64, start: f64, delta: f64) -> Spec {
        Spec {
            center: DVec3::ZERO,
            axis: DVec3::Y,
            phi_zero: DVec3::X,
            major,
            bore,
            tube,
            start,
            delta,
        }
    }

    /// The same bend at a random pose.
    pub fn posed(self, rng: &mut Pcg64) -> Spec {
        let size = self.size();
        Spec {
            center: unit(rng) * size * rng.random_range(0.0..3.0),
            axis: unit(rng),
            phi_zero: unit(rng),
            start: rng.random_range(-TAU..TAU),
            ..self
        }
    }

    pub fn size(&self) -> f64 {
        self.major + self.tube
    }

    pub fn bend(&self) -> PipeBend {
        PipeBend::new_f64(
            self.center,
            self.axis,
            self.phi_zero,
            self.major,
            self.bore,
            self.tube,
            self.start,
            self.delta,
        )
        .unwrap_or_else(|e| panic!("{self:?}: {e}"))
    }

    /// The oracle's question for `ray` (its origin, direction and range).
    pub fn query(&self, ray: &DRay) -> BendQuery {
        BendQuery::new(
            (self.center, self.axis, self.phi_zero),
            (self.major, self.bore, self.tube),
            (self.start, self.delta),
            ray.origin(),
            ray.dir(),
            (ray.t_min(), ray.t_max()),
        )
    }

    /// The world point of local (φ, ψ, D): φ about the axis, ψ around the tube from the
    /// equator outward toward the axis, D from the core circle.
    pub fn point(&self, phi: f64, psi: f64, d: f64) -> DVec3 {
        let (e0, e1, a) = self.frame();
        let rho = self.major + d * psi.cos();
        self.center + (e0 * phi.cos() + e1 * phi.sin()) * rho + a * (d * psi.sin())
    }

    /// (e0, e1, â): φ = 0, φ = π/2, the axis.
    pub fn frame(&self) -> (DVec3, DVec3, DVec3) {
        let a = self.axis.normalize();
        let e0 = (self.phi_zero - a * self.phi_zero.dot(a)).normalize();
        (e0, a.cross(e0), a)
    }

    /// A random ray: aimed at a point of the tube's neighbourhood (at any φ half of the
    /// time, in the segment else) from up to 3·S away; one in ten starts at that point.
    pub fn random_ray(&self, rng: &mut Pcg64) -> DRay {
        let phi = if rng.random_bool(0.5) {
            rng.random_range(0.0..TAU)
        } else {
            self.start + rng.random_range(0.0..self.delta)
        };
        let aim = self.point(
            phi,
            rng.random_range(0.0..TAU),
            self.tube * rng.random_range(0.0f64..1.69).sqrt(),
        );
        if rng.random_bool(0.1) {
            return DRay::new(aim, unit(rng)).unwrap();
        }
        let origin = aim + unit(rng) * self.size() * rng.random_range(0.05..3.0);
        let k = rng.random_range(0.1..10.0);
        if rng.random_bool(0.2) {
            // A finite range, ending anywhere up to twice past the aim point.
            let t_max = rng.random_range(0.0..2.0) / k;
            return DRay::with_range(origin, (aim - origin) * k, 0.0, t_max).unwrap();
        }
        DRay::new(origin, (aim - origin) * k).unwrap()
    }
}

pub fn unit(rng: &mut Pcg64) -> DVec3 {
    loop {
        let v = DVec3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        let l = v.length();
        if l > 0.1 && l <= 1.0 {
            return v / l;
        }
    }
}

pub fn rng(seed: u64) -> Pcg64 {
    Pcg64::seed_from_u64(seed)
}

pub fn face(f: BendFace) -> Face {
    match f {
        BendFace::Outer => Face::Outer,
        BendFace::Inner => Face::Inner,
        BendFace::StartCap => Face::StartCap,
        BendFace::EndCap => Face::EndCap,
    }
}

pub fn passage(p: Passage) -> OraclePassage {
    match p {
        Passage::Enter => OraclePassage::Entering,
        Passage::Exit => OraclePassage::Leaving,
        Passage::Touch => OraclePassage::Touching,
    }
}

/// Counts of a comparison with the oracle.
#[derive(Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct Tally {
    pub rays: usize,
    pub hits: usize,
    pub misses: usize,
    pub ambiguous: usize,
    /// The oracle has a crossing in range, the library none.
    pub missed: usize,
    /// The library has a crossing the oracle has not.
    pub invented: usize,
    /// A crossing's face is none of the faces through the oracle's point.
    pub wrong_face: usize,
    /// Same crossings, but a t, a passage or a normal off.
    pub wrong_value: usize,
}

impl Tally {
    pub fn bad(&self) -> usize {
        self.missed + self.invented + self.wrong_face + self.wrong_value
    }

    pub fn add(&mut self, o: &Tally) {
        self.rays += o.rays;
        self.hits += o.hits;
        self.misses += o.misses;
        self.ambiguous += o.ambiguous;
        self.missed += o.missed;
        self.invented += o.invented;
        self.wrong_face += o.wrong_face;
        self.wrong_value += o.wrong_value;
    }
}

/// The expected answers are held to this × S.
pub const TOL: f64 = 1e-9;

/// Compares `intersect` and `intersect_all` on `ray` with the oracle. Returns the
/// per-ray tally and, on a disagreement, a description.
pub fn compare(spec: &Spec, bend: &PipeBend, ray: &DRay) -> (Tally, Option<String>) {
    let q = spec.query(ray);
    let size = spec.size();
    let tol = TOL * size;
    let len = ray.dir().length();
    let label = q.classify();
    let mut t = Tally {
        rays: 1,
        ..Tally::default()
    };
    // Crossings closer than the tolerance (a corner clipped by less) or within it of
    // the range's start are not determined by the input.
    let ambiguous = label.class == OracleClass::Ambiguous
        || q.closest_crossings() <= tol
        || q.tangency(tol) <= tol
        || q.over(f64::NEG_INFINITY, f64::INFINITY)
            .crossings()
            .iter()
            .any(|c| {
                (c.0 - ray.t_min()).abs() * len <= tol || (c.0 - ray.t_max()).abs() * len <= tol
            });
    if ambiguous {
        t.ambiguous = 1;
        return (t, None);
    }
    if label.class == OracleClass::Hit {
        t.hits = 1;
    } else {
        t.misses = 1;
    }
    let want = q.crossings();
    let got = bend.intersect_all(ray).as_slice();
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
            t.invented += 1;
        } else {
            t.missed += 1;
        }
        why.push(format!("intersect_all {got:?}, oracle {want:?}"));
    } else {
        for (g, w) in got.iter().zip(&want) {
            let p = ray.origin() + ray.dir() * w.0;
            let faces = q.faces_at(p, tol);
            if face(g.face) != w.2 && !faces.contains(&face(g.face)) {
                t.wrong_face += 1;
                why.push(format!("intersect_all face {g:?}, oracle {w:?} {faces:?}"));
            } else if (g.t - w.0).abs() * len > tol || passage(g.passage) != w.1 {
                t.wrong_value += 1;
                why.push(format!("intersect_all {g:?}, oracle {w:?}"));
            }
        }
        let all = bend.intersect_all(ray);
        if all.starts_inside() != q.starts_inside() {
            t.wrong_value += 1;
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

/// The wedge alone, for capture counts.
pub fn wedge_alone_keeps(bend: &PipeBend, ray: &DRay) -> bool {
    bend.kept_by(&bend.wedge_cull(NoCull), ray)
}

/// The ambiguity band, for reference.
pub fn band(spec: &Spec) -> f64 {
    AMBIGUITY_REL * spec.size()
}
