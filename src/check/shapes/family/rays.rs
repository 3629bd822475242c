//! The rays `torus-cull family` draws for one member: uniform, grazing, axis/hole and
//! spawned, deterministic from a seed (Pcg64). Every point is built in a frame of the
//! member's own (its f64 axis and any two unit vectors orthogonal to it: the member is
//! symmetric about its axis), not the library's rotation.

use glam::DVec3;
use rand::{Rng, RngExt};
use torus_cull::DRay;
use torus_cull::family::Toroid;

/// How a ray was drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum RayKind {
    /// From a random point of the sphere of radius 4·(R + max(a, b)) about the centre
    /// to a random point of the member's bounding box.
    Uniform,
    /// Tangent to the surface at a random point, offset along the normal by
    /// ±10⁻⁶…10⁻³·(R + max(a, b)) (log-uniform), from 4·(R + max(a, b)) back.
    Grazing,
    /// Near the axis, from ±4·(R + max(a, b)) along it, through the hole of a ring or
    /// the cusps of a horn or spindle.
    AxisHole,
    /// From a surface point ([`Toroid::spawn`] of a ray that hit there), in a random
    /// direction.
    Spawned,
}

impl RayKind {
    /// Every kind, in the order rays cycle through them.
    pub const ALL: [RayKind; 4] = [
        RayKind::Uniform,
        RayKind::Grazing,
        RayKind::AxisHole,
        RayKind::Spawned,
    ];

    /// The kind's name in the results.
    pub fn name(self) -> &'static str {
        match self {
            RayKind::Uniform => "uniform",
            RayKind::Grazing => "grazing",
            RayKind::AxisHole => "axis_hole",
            RayKind::Spawned => "spawned",
        }
    }
}

/// R + max(a, b).
pub fn size(toroid: &Toroid) -> f64 {
    toroid.major_radius_f64()
        + toroid
            .radial_semi_axis_f64()
            .max(toroid.axial_semi_axis_f64())
}

/// The member's frame: centre, and the unit vectors (x, y = axis, z).
struct Frame {
    center: DVec3,
    x: DVec3,
    y: DVec3,
    z: DVec3,
}

impl Frame {
    fn of(toroid: &Toroid) -> Frame {
        let y = toroid.axis_f64().normalize();
        let (x, z) = y.any_orthonormal_pair();
        Frame {
            center: toroid.center_f64(),
            x,
            y,
            z,
        }
    }

    /// A point given in the frame, in the world.
    fn point(&self, local: DVec3) -> DVec3 {
        self.center + self.vector(local)
    }

    /// A vector given in the frame, in the world.
    fn vector(&self, local: DVec3) -> DVec3 {
        self.x * local.x + self.y * local.y + self.z * local.z
    }
}

/// A uniformly random unit vector.
fn unit(rng: &mut impl Rng) -> DVec3 {
    crate::random::ball_direction(rng, 1e-6)
}

/// A random point of the surface (world) and its unit outward normal: a point
/// `(R + a cos θ, b sin θ)` of the tube's ellipse with ρ > 0 (the apple's arc for a horn
/// or spindle), turned by a random azimuth.
pub fn surface_point(toroid: &Toroid, rng: &mut impl Rng) -> (DVec3, DVec3) {
    let (major, a, b) = (
        toroid.major_radius_f64(),
        toroid.radial_semi_axis_f64(),
        toroid.axial_semi_axis_f64(),
    );
    let frame = Frame::of(toroid);
    let (rho, y, theta) = loop {
        let theta = rng.random_range(0.0..std::f64::consts::TAU);
        let rho = major + a * theta.cos();
        if rho > 1e-3 * a {
            break (rho, b * theta.sin(), theta);
        }
    };
    let phi = rng.random_range(0.0..std::f64::consts::TAU);
    let (s, c) = phi.sin_cos();
    // The gradient of ((ρ − R)/a)² + (y/b)² on the ellipse: (cos θ/a, sin θ/b).
    let (n_rho, n_y) = (theta.cos() / a, theta.sin() / b);
    let n_len = n_rho.hypot(n_y);
    let local = DVec3::new(rho * c, y, rho * s);
    let normal = DVec3::new(n_rho * c / n_len, n_y / n_len, n_rho * s / n_len);
    (frame.point(local), frame.vector(normal))
}

/// One ray of `kind` for the member.
pub fn draw(toroid: &Toroid, kind: RayKind, rng: &mut impl Rng) -> DRay {
    let size = size(toroid);
    let frame = Frame::of(toroid);
    let (major, a, b) = (
        toroid.major_radius_f64(),
        toroid.radial_semi_axis_f64(),
        toroid.axial_semi_axis_f64(),
    );
    match kind {
        RayKind::Uniform => {
            let origin = frame.center + unit(rng) * (4.0 * size);
            let reach = major + a;
            let target = frame.point(DVec3::new(
                rng.random_range(-reach..reach),
                rng.random_range(-b..b),
                rng.random_range(-reach..reach),
            ));
            DRay::new(origin, target - origin).expect("a finite ray")
        }
        RayKind::Grazing => {
            let (p, n) = surface_point(toroid, rng);
            let tangent = loop {
                let v = unit(rng);
                let t = v - n * v.dot(n);
                if t.length_squared() > 1e-6 {
                    break t.normalize();
                }
            };
            let sign = if rng.random_bool(0.5) { 1.0 } else { -1.0 };
            let offset = sign * 10f64.powf(rng.random_range(-6.0..-3.0)) * size;
            let through = p + n * offset;
            DRay::new(through - tangent * (4.0 * size), tangent).expect("a finite ray")
        }
        RayKind::AxisHole => {
            // Lateral offsets up to 1.2 × the hole's radius (R − a) and 0.02·a: through
            // the hole, onto its rim, and through the cusps of a horn or spindle.
            let h = 1.2 * (major - a).max(0.0) + 0.02 * a;
            let lateral = |rng: &mut dyn FnMut() -> f64| {
                let r = h * rng().sqrt();
                let phi = std::f64::consts::TAU * rng();
                (r * phi.cos(), r * phi.sin())
            };
            let side = if rng.random_bool(0.5) { 1.0 } else { -1.0 };
            let mut uniform = || rng.random::<f64>();
            let (ox, oz) = lateral(&mut uniform);
            let (tx, tz) = lateral(&mut uniform);
            let origin = frame.point(DVec3::new(ox, side * 4.0 * size, oz));
            let target = frame.point(DVec3::new(tx, 0.0, tz));
            DRay::new(origin, target - origin).expect("a finite ray")
        }
        RayKind::Spawned => {
            let (p, n) = surface_point(toroid, rng);
            // A primary ray that arrives at p from outside, then the secondary ray.
            let back = loop {
                let u = unit(rng);
                if u.dot(n) > 0.05 {
                    break u;
                }
            };
            let primary = DRay::new(p + back * (2.0 * size), -back).expect("a finite ray");
            toroid
                .spawn(&primary, 2.0 * size, unit(rng))
                .expect("a finite spawned ray")
        }
    }
}
