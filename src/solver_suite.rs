//! The solver suite: each line family's torus quartics with the oracle's reference roots,
//! and how a solver's nearest root is scored against them. `cargo bench` (speed and
//! accuracy per solver) and `tests/batch/batch_solve.rs` (the lane solver) use the same cases
//! and the same count.

use crate::oracle::{OracleClass, Query, classify_line, reference_roots};
use crate::workload::adversarial::{LineFamily, family_rays};
use crate::workload::{Case, GenerateError, Pose, generate};
use rand::SeedableRng;
use torus_cull::intersect::quartic_coefficients_local;
use torus_cull::{Ray, Torus};

/// A root counts as found when it is within this distance, × (R + r), of the reference.
pub const MATCH_TOLERANCE_REL: f64 = 1e-6;

/// The line families, each timed and scored on its own.
pub const FAMILIES: [&str; 4] = ["uniform", "hole_edge", "tangent", "tangent_limit"];

/// One line's quartic, with what it takes to map its roots u back to t and score them.
#[derive(Debug, Clone)]
pub struct SolverCase {
    /// `[c2, c1, c0]` of the depressed monic quartic in u (origin at the foot point, R = 1).
    pub c: [f64; 3],
    /// u of the ray's origin (t = 0): the solvers look for roots at or after it.
    pub u_origin: f64,
    major: f64,
    minor: f64,
    foot_offset: f64,
    inv_len: f64,
    len: f64,
    /// The oracle's roots at or after the origin, sorted.
    reference: Vec<f64>,
}

impl SolverCase {
    /// The case for one ray, or `None` when the oracle calls its line ambiguous (its
    /// tangent roots are not defined to better than the band).
    pub fn new(torus: &Torus, ray: &Ray) -> Option<SolverCase> {
        if classify_line(torus, ray).class == OracleClass::Ambiguous {
            return None;
        }
        let (major, minor) = (
            f64::from(torus.major_radius()),
            f64::from(torus.minor_radius()),
        );
        let (o, d) = torus.line_to_local_f64(ray);
        let len = d.length();
        let foot_offset = o.dot(d / len);
        let c = quartic_coefficients_local(major, minor, o, d);
        Some(SolverCase {
            c: [c[2], c[3], c[4]],
            u_origin: foot_offset / major,
            major,
            minor,
            foot_offset,
            inv_len: 1.0 / len,
            len,
            reference: reference_roots(&Query::ray(torus, ray).over(0.0, f64::INFINITY)),
        })
    }

    /// The ray parameter t of a root u.
    pub fn t_of_u(&self, u: f64) -> f64 {
        (u * self.major - self.foot_offset) * self.inv_len
    }
}

/// A family's cases, `per_nu` rays at each ν (minus the ambiguous ones): `uniform` from the
/// workload generator with `uniform_seed` and `pose`, the adversarial families from
/// [`family_rays`] seeded with `family_seed ^ ν.to_bits() ^ family.len()`.
pub fn family_cases(
    family: &str,
    nus: &[f64],
    per_nu: usize,
    (uniform_seed, pose): (u64, Pose),
    family_seed: u64,
) -> Result<Vec<SolverCase>, GenerateError> {
    let mut cases = Vec::new();
    for &nu in nus {
        if family == "uniform" {
            let b = generate(Case::Uniform, nu, per_nu, uniform_seed, pose)?;
            cases.extend(b.rays.iter().filter_map(|r| SolverCase::new(&b.torus, r)));
            continue;
        }
        let kind = match family {
            "hole_edge" => LineFamily::HoleEdge,
            "tangent" => LineFamily::Tangent,
            _ => LineFamily::TangentLimit,
        };
        let seed = family_seed ^ nu.to_bits() ^ family.len() as u64;
        let mut rng = rand_pcg::Pcg64::seed_from_u64(seed);
        let (torus, rays) = family_rays(kind, nu, per_nu, &mut rng);
        cases.extend(rays.iter().filter_map(|r| SolverCase::new(&torus, r)));
    }
    Ok(cases)
}

/// A solver's nearest roots t ≥ 0 against the references' first.
///
/// *Missed*: the reference has a root and the solver gives none within
/// [`MATCH_TOLERANCE_REL`]; *spurious*: the solver gives a root that matches no reference
/// root at or after the origin.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct NearestScore {
    /// Cases scored.
    pub sets: u64,
    /// Cases whose line has a reference root at or after the origin.
    pub reference: u64,
    /// Reference roots not found.
    pub missed: u64,
    /// Roots that match no reference root.
    pub spurious: u64,
    /// The largest |Δt|·|d|/(R + r) among the matched roots.
    pub max_rel_t_error: f64,
}

impl NearestScore {
    /// Scores one case's answer, `root` in u (`None`: no root in range).
    pub fn add(&mut self, case: &SolverCase, root: Option<f64>) {
        let tol = MATCH_TOLERANCE_REL * (case.major + case.minor) * case.inv_len;
        let found = root.map(|u| case.t_of_u(u));
        let want = case.reference.first().copied();
        self.sets += 1;
        self.reference += u64::from(want.is_some());
        match (found, want) {
            (Some(t), Some(r)) if (t - r).abs() <= tol => {
                let err = (t - r).abs() * case.len / (case.major + case.minor);
                self.max_rel_t_error = self.max_rel_t_error.max(err);
            }
            (Some(t), Some(r)) => {
                // A wrong nearest root: the true one was missed, and the returned one is
                // spurious unless it is some later reference root.
                self.missed += 1;
                let later = case.reference.iter().any(|&x| (t - x).abs() <= tol);
                self.spurious += u64::from(!later || t < r);
            }
            (Some(_), None) => self.spurious += 1,
            (None, Some(_)) => self.missed += 1,
            (None, None) => {}
        }
    }
}
