//! The pipe-bend rays of `torus-cull bend` and of the bend oracle tests (one home for
//! both): one bend's parameters as the library's `PipeBend` and the oracle's `BendQuery`
//! ([`Spec`]), random poses, and the ray kinds ([`RayKind`]): random rays about the tube,
//! rays through the cut-away arc, along the pipe's axis through the caps and the hollow
//! core, through the hole, grazing the caps' edges, tangent to the bore, spawned from every
//! face. Deterministic from a Pcg64.

use crate::oracle::bend::BendQuery;
use glam::DVec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64;
use std::f64::consts::TAU;
use torus_cull::DRay;
use torus_cull::bend::{BendError, PipeBend};

/// A bend's parameters: the bend oracle's ([`crate::oracle::bend::Spec`], the part of its
/// question that is the bend); here, what the check's rays and poses make of them.
pub use crate::oracle::bend::Spec;

impl Spec {
    /// The bend in its canonical frame (centre 0, axis +y, φ = 0 along +x).
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

    /// The same bend at a random pose (centre, axis, φ = 0 and φ₀).
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

    /// S = R + r_max.
    pub fn size(&self) -> f64 {
        self.major + self.tube
    }

    /// The library's solid, or the library's reason for refusing these parameters.
    pub fn bend(&self) -> Result<PipeBend, BendError> {
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
    }

    /// The oracle's question for `ray` (its origin, direction and range).
    pub fn query(&self, ray: &DRay) -> BendQuery {
        BendQuery {
            bend: *self,
            origin: ray.origin(),
            dir: ray.dir(),
            t_min: ray.t_min(),
            t_max: ray.t_max(),
        }
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

    /// The unit direction of growing φ at φ (the pipe's axis there).
    pub fn growing(&self, phi: f64) -> DVec3 {
        let (e0, e1, _) = self.frame();
        e1 * phi.cos() - e0 * phi.sin()
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

    /// A point of the cut-away arc's tube (φ outside the segment by ≥ 0.05 rad; any φ
    /// for a segment of more than 2π − 0.1, which has no such arc), D < r_max.
    pub fn cut_away_point(&self, rng: &mut Pcg64) -> DVec3 {
        let gap = TAU - self.delta - 0.1;
        let phi = if gap > 0.0 {
            self.start + self.delta + 0.05 + rng.random_range(0.0..gap)
        } else {
            rng.random_range(0.0..TAU)
        };
        self.point(
            phi,
            rng.random_range(0.0..TAU),
            self.tube * rng.random_range(0.0..1.0),
        )
    }

    /// Along the axis through a point of the cut-away arc's tube ([`Spec::cut_away_point`]):
    /// a miss of the segment.
    pub fn cut_away_axial(&self, rng: &mut Pcg64) -> DRay {
        let (_, _, a) = self.frame();
        let p = self.cut_away_point(rng);
        DRay::new(p - a * (10.0 * self.size()), a).unwrap()
    }

    /// Through a point of the cut-away arc's tube, toward the centre's side from a random
    /// point 10·S away.
    pub fn cut_away_any(&self, rng: &mut Pcg64) -> DRay {
        let p = self.cut_away_point(rng);
        DRay::new(p - unit(rng) * (10.0 * self.size()), p - self.center).unwrap()
    }

    /// Along the pipe's axis at mid-segment, through both caps' planes, either way, at a
    /// random D < r_max from the core circle: through the material or the hollow core.
    pub fn pipe_axis(&self, rng: &mut Pcg64) -> DRay {
        let mid = self.start + 0.5 * self.delta;
        let p = self.point(
            mid,
            rng.random_range(0.0..TAU),
            self.tube * rng.random_range(0.0..1.0),
        );
        let g = self.growing(mid) * if rng.random_bool(0.5) { 1.0 } else { -1.0 };
        DRay::new(p - g * (10.0 * self.tube), g).unwrap()
    }

    /// Through the hole, along the axis, from a point of the mid-segment's direction at
    /// ρ < R − 0.1·r_max.
    pub fn hole(&self, rng: &mut Pcg64) -> DRay {
        let (e0, e1, a) = self.frame();
        let mid = self.start + 0.5 * self.delta;
        let reach = (self.major - 1.1 * self.tube).max(0.0) + 0.9 * self.tube;
        let p = self.center + (e0 * mid.cos() + e1 * mid.sin()) * rng.random_range(0.0..reach);
        DRay::new(p + a * (10.0 * self.size()), -a).unwrap()
    }

    /// Grazing a cap's edge (the outer circle, or the bore's for a bore half of the time),
    /// off the cap's plane by ±10⁻⁷…10⁻³·r_max (log-uniform, either side): along the
    /// edge's tangent, or along the axis.
    pub fn cap_edge(&self, rng: &mut Pcg64) -> DRay {
        let (_, _, a) = self.frame();
        let end = rng.random_bool(0.5);
        let phi = if end {
            self.start + self.delta
        } else {
            self.start
        };
        let e = 10f64.powf(rng.random_range(-7.0..-3.0)) * self.tube;
        let e = if rng.random_bool(0.5) { e } else { -e };
        let r = if self.bore > 0.0 && rng.random_bool(0.5) {
            self.bore
        } else {
            self.tube
        };
        let psi = rng.random_range(0.0..TAU);
        let p = self.point(phi, psi, r) + self.growing(phi) * e;
        if rng.random_bool(0.5) {
            let tangent = self.point(phi, psi + 1e-3, r) - self.point(phi, psi - 1e-3, r);
            let tangent = tangent.normalize();
            DRay::new(p - tangent * (10.0 * self.size()), tangent).unwrap()
        } else {
            DRay::new(p - a * (10.0 * self.size()), a).unwrap()
        }
    }

    /// Tangent to the bore (to the outer tube without one) inside the segment, offset
    /// along its normal by ±10⁻⁸…10⁻⁴·r_max, in a random tangent direction.
    pub fn bore_tangent(&self, rng: &mut Pcg64) -> DRay {
        let r = if self.bore > 0.0 {
            self.bore
        } else {
            self.tube
        };
        let phi = self.start + rng.random_range(0.0..self.delta);
        let psi = rng.random_range(0.0..TAU);
        let p0 = self.point(phi, psi, r);
        let n = (p0 - self.point(phi, psi, 0.0)).normalize();
        let t = unit(rng).reject_from_normalized(n).normalize();
        let e = 10f64.powf(rng.random_range(-8.0..-4.0)) * self.tube;
        let p = p0 + n * if rng.random_bool(0.5) { e } else { -e };
        DRay::new(p - t * (5.0 * self.tube), t).unwrap()
    }

    /// A ray spawned from a face ([`PipeBend::spawn`]) in a random direction: from a
    /// random crossing of a random ray, or (for a segment, a third of the time) from a
    /// random point of a cap, its edges included. `None` when the random ray crosses
    /// nothing.
    pub fn spawned(&self, bend: &PipeBend, rng: &mut Pcg64) -> Option<DRay> {
        if self.delta < TAU && rng.random_range(0..3) == 0 {
            let phi = if rng.random_bool(0.5) {
                self.start
            } else {
                self.start + self.delta
            };
            let psi = rng.random_range(0.0..TAU);
            let d = match rng.random_range(0..3) {
                0 => self.tube,
                1 => self.bore,
                _ => rng.random_range(self.bore..self.tube),
            };
            let any = DRay::new(self.point(phi, psi, d), DVec3::X).unwrap();
            return Some(bend.spawn(&any, 0.0, unit(rng)).unwrap());
        }
        let ray = self.random_ray(rng);
        let all = bend.intersect_all(&ray);
        let all = all.crossings();
        if all.is_empty() {
            return None;
        }
        let c = all[rng.random_range(0..all.len())];
        Some(bend.spawn(&ray, c.t, unit(rng)).unwrap())
    }
}

/// How a ray of `torus-cull bend` was drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum RayKind {
    /// [`Spec::random_ray`].
    Random,
    /// [`Spec::cut_away_axial`] and [`Spec::cut_away_any`], alternately by a coin.
    CutAway,
    /// [`Spec::pipe_axis`].
    PipeAxis,
    /// [`Spec::hole`].
    Hole,
    /// [`Spec::cap_edge`].
    CapEdge,
    /// [`Spec::bore_tangent`].
    BoreTangent,
    /// [`Spec::spawned`] (a random ray in its place when that crossed nothing).
    Spawned,
}

impl RayKind {
    /// Every kind, in the order rays cycle through them.
    pub const ALL: [RayKind; 7] = [
        RayKind::Random,
        RayKind::CutAway,
        RayKind::PipeAxis,
        RayKind::Hole,
        RayKind::CapEdge,
        RayKind::BoreTangent,
        RayKind::Spawned,
    ];

    /// The kind's name in the results.
    pub fn name(self) -> &'static str {
        match self {
            RayKind::Random => "random",
            RayKind::CutAway => "cut_away",
            RayKind::PipeAxis => "pipe_axis",
            RayKind::Hole => "hole",
            RayKind::CapEdge => "cap_edge",
            RayKind::BoreTangent => "bore_tangent",
            RayKind::Spawned => "spawned",
        }
    }
}

/// One ray of `kind` for `spec` (`bend` is its solid); `true` with it when the ray
/// starts on a face (spawned), to be labelled by the oracle's on-surface rule.
pub fn draw(spec: &Spec, bend: &PipeBend, kind: RayKind, rng: &mut Pcg64) -> (DRay, bool) {
    let ray = match kind {
        RayKind::Random => spec.random_ray(rng),
        RayKind::CutAway if rng.random_bool(0.5) => spec.cut_away_axial(rng),
        RayKind::CutAway => spec.cut_away_any(rng),
        RayKind::PipeAxis => spec.pipe_axis(rng),
        RayKind::Hole => spec.hole(rng),
        RayKind::CapEdge => spec.cap_edge(rng),
        RayKind::BoreTangent => spec.bore_tangent(rng),
        RayKind::Spawned => match spec.spawned(bend, rng) {
            Some(ray) => return (ray, true),
            None => spec.random_ray(rng),
        },
    };
    (ray, false)
}

/// A uniformly random unit vector (none shorter than 0.1 drawn).
pub fn unit(rng: &mut Pcg64) -> DVec3 {
    crate::random::ball_direction(rng, 0.01)
}

/// The generator every bend ray is drawn from.
pub fn rng(seed: u64) -> Pcg64 {
    Pcg64::seed_from_u64(seed)
}
