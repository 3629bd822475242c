//! One φ for every shape (docs/math.md §1): φ = 0 on the frame's +x axis, growing
//! right-handed about the axis. A torus's `point_at` at φ lies inside a pipe bend's
//! segment exactly when φ is in `[start_phi, start_phi + delta_phi]`, for the canonical
//! frame and for a posed one, and `surface_coords` gives the φ back.

use glam::DVec3;
use std::f64::consts::{FRAC_PI_2, PI};
use torus_cull::Torus;
use torus_cull::bend::PipeBend;

/// Points on the tube's core (θ = 0 pushed half a tube inward, so they sit inside the
/// solid of a whole ring) at φ across the circle; the bend covers `[π/4, π/4 + π/2]`.
fn check(center: DVec3, axis: DVec3) {
    let (big, r) = (5.0, 1.0);
    let torus = Torus::new_f64(center, axis, big, r).unwrap();
    // The bend's φ = 0 along the torus frame's +x axis (the torus at φ = 0).
    let phi_zero = torus.point_at(0.0, 0.0) - center;
    let bend = PipeBend::new_f64(center, axis, phi_zero, big, 0.0, r, PI / 4.0, FRAC_PI_2).unwrap();
    let mut inside_count = 0;
    for k in 0..64 {
        let phi = -PI + (k as f64 + 0.5) * (2.0 * PI / 64.0);
        let on_surface = torus.point_at(0.0, phi);
        let (_, back) = torus.surface_coords(on_surface).unwrap();
        assert!((back - phi).abs() < 1e-12, "φ {phi} came back as {back}");
        // A quarter of the way from the outer equator to the inner: ρ = R + r/2, inside.
        let inward = on_surface + (torus.point_at(PI, phi) - on_surface) * 0.25;
        let in_segment = (PI / 4.0..=3.0 * PI / 4.0).contains(&phi);
        assert_eq!(
            bend.contains(inward),
            in_segment,
            "φ {phi}: the bend's segment and the torus's φ disagree"
        );
        inside_count += usize::from(in_segment);
    }
    assert_eq!(inside_count, 16);
}

#[test]
fn the_torus_and_the_bend_share_one_phi() {
    check(DVec3::ZERO, DVec3::Y);
    check(DVec3::new(1.0, -2.0, 3.0), DVec3::Z);
    check(DVec3::new(-4.0, 0.5, 2.0), DVec3::new(0.3, -1.0, 0.7));
}
