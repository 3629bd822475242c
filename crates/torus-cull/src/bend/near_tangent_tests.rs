//! Rays spawned from a face within about 10⁻⁵ of tangent to a torus face: the five that
//! `torus-cull bend` reported against the bend oracle (results/60bf307-bend.json,
//! docs/bend.md). Each dips into the tube (or out into the bore) by 10⁻¹⁴…10⁻¹¹·S
//! between the origin's own crossing and one 10⁻⁷…10⁻⁶·S on: a genuine crossing, kept.
//!
//! The library's answer is checked against the solid's definition alone, evaluated here
//! by its own formulas (no code of the library's): the distance-like function
//! `F = max(f_rad, f_w)` (negative inside) is of one sign over the whole chord between the
//! origin and the hit, at least ten times its f64 rounding at the chord's middle, and of
//! the other sign just before the origin and just past the hit.

use super::{BendFace, PipeBend};
use crate::{DRay, Passage};
use glam::{DVec2, DVec3};
use std::f64::consts::TAU;

/// A bend (centre, axis, φ₀ direction; R, r_min, r_max, φ₀, Δφ), a ray from its surface
/// (origin, direction), and the first crossing past the origin's own (t, face, passage).
type Case = (
    [[f64; 3]; 3],
    [f64; 5],
    [[f64; 3]; 2],
    (f64, BendFace, Passage),
);

const CASES: [Case; 5] = [
    // Δφ = 2π, no bore: out of the tube 2.8·10⁻⁷·S on.
    (
        [
            [
                -0.0019746248461145824,
                -0.0029461541354645713,
                -0.002641725932126363,
            ],
            [
                -0.9994340728838559,
                -0.027617915347328565,
                0.01920376813688821,
            ],
            [
                -0.03839274378281804,
                -0.5015706361275626,
                0.8642643659201847,
            ],
        ],
        [0.004, 0.0, 0.001, -0.4135553324725523, TAU],
        [
            [
                -0.003012353835024316,
                -0.0005034284021232195,
                -0.00630995983544658,
            ],
            [0.3839776212794209, 0.7494345850302565, -0.5393597956069075],
        ],
        (1.3822452583211218e-9, BendFace::Outer, Passage::Exit),
    ),
    // Δφ = π, r_min = R/8: from the bore into the hole, back into the bore's wall
    // 1.7·10⁻⁶·S on (the concave face's re-hit).
    (
        [
            [-4063.927963968598, -5826.442432564374, -3619.900442763744],
            [-0.4486214615214787, -0.3191164149563251, 0.8348074616148055],
            [0.6379370917284685, -0.740060173919516, -0.21294883417205987],
        ],
        [
            4000.0,
            500.0,
            1000.0,
            5.234144575869436,
            std::f64::consts::PI,
        ],
        [
            [-1032.6853178779907, -7651.828150260352, -3013.312688205051],
            [-0.7938955426834177, 0.06795079341920689, 0.604245444319692],
        ],
        (0.008570618684261977, BendFace::Inner, Passage::Enter),
    ),
    // Δφ = π/2, r_min = r_max/2: out of the tube 1.6·10⁻⁶·S on.
    (
        [
            [
                0.9683628968244662,
                -1.2898992145825265,
                -0.41524891552930593,
            ],
            [0.9533858451022077, 0.2588865798794186, 0.15502634975089408],
            [-0.2704095612401064, 0.9403950649676744, 0.20624206887630026],
        ],
        [
            4.0,
            0.5,
            1.0,
            -4.2428158752067215,
            std::f64::consts::FRAC_PI_2,
        ],
        [
            [2.228681110387581, -5.499659413330818, 1.781270478956565],
            [-0.8080322127994893, -0.5401766400518971, 0.2351449353496773],
        ],
        (7.953060063307258e-6, BendFace::Outer, Passage::Exit),
    ),
    // Δφ = π/6, no bore: from the end cap's outer edge into the corner, out of the
    // outer face 4.3·10⁻⁶·S on.
    (
        [
            [
                -0.0070694112850074545,
                -0.005260815943236233,
                0.0026248288246057175,
            ],
            [
                0.46793799360294835,
                -0.5440873756002695,
                -0.6964215403441064,
            ],
            [-0.09513806847870568, 0.8072361469501801, 0.5825105586881394],
        ],
        [0.004, 0.0, 0.001, -5.126034964075151, TAU / 12.0],
        [
            [
                -0.005546322795914502,
                -0.0070190524725663415,
                0.004607172487988897,
            ],
            [
                0.9064590344535395,
                -0.18455667945105142,
                -0.37983002899660095,
            ],
        ],
        (2.1717086449838836e-8, BendFace::Outer, Passage::Exit),
    ),
    // Δφ = π/6, r_min = 0.9·r_max: from the start cap's outer edge, out of the outer
    // face 3.0·10⁻⁶·S on.
    (
        [
            [
                0.0012284150449144425,
                -0.00034560456923205473,
                -0.00359326936255987,
            ],
            [0.870644694383978, -0.0963274599902967, -0.4823886779277137],
            [0.8432010268880604, -0.12192405634464161, 0.5235900617271007],
        ],
        [
            0.004,
            0.0009000000000000001,
            0.001,
            4.324324471309348,
            TAU / 12.0,
        ],
        [
            [
                0.0011966294934207505,
                0.004322819518941651,
                -0.005257426735134356,
            ],
            [-0.6605694424572993, 0.47028247147243163, 0.5852199660960264],
        ],
        (1.4900413485020056e-8, BendFace::Outer, Passage::Exit),
    ),
];

/// The solid's distance-like function at `p` (negative inside), from its definition:
/// `f_rad` of the distance D to the core circle, `f_w` the signed distance to the
/// segment's cone in the plane across the axis.
fn signed(pose: [DVec3; 3], [r, r_min, r_max, start, delta]: [f64; 5], p: DVec3) -> f64 {
    let [c, axis, phi_zero] = pose;
    let a = axis.normalize();
    let e0 = (phi_zero - a * phi_zero.dot(a)).normalize();
    let e1 = a.cross(e0);
    let x = p - c;
    let q = DVec2::new(x.dot(e0), x.dot(e1));
    let d = (q.length() - r).hypot(x.dot(a));
    let f_rad = if r_min > 0.0 {
        (d - 0.5 * (r_min + r_max)).abs() - 0.5 * (r_max - r_min)
    } else {
        d - r_max
    };
    if delta >= TAU {
        return f_rad;
    }
    let edge = |phi: f64| {
        let u = DVec2::new(phi.cos(), phi.sin());
        if q.dot(u) > 0.0 {
            (q.x * u.y - q.y * u.x).abs()
        } else {
            q.length()
        }
    };
    let m = edge(start).min(edge(start + delta));
    let rel = (q.y.atan2(q.x) - start).rem_euclid(TAU);
    f_rad.max(if rel < delta { -m } else { m })
}

#[test]
fn near_tangent_spawned_rays_keep_their_next_crossing() {
    for (k, (pose, radii, line, (t_want, face, passage))) in CASES.into_iter().enumerate() {
        let pose = pose.map(DVec3::from_array);
        let [o, d] = line.map(DVec3::from_array);
        let [r, r_min, r_max, start, delta] = radii;
        let bend =
            PipeBend::new_f64(pose[0], pose[1], pose[2], r, r_min, r_max, start, delta).unwrap();
        let size = r + r_max;
        let ray = DRay::from_surface(o, d).unwrap();
        let hit = bend.intersect(&ray).unwrap();
        let all = bend.intersect_all(&ray);
        let all = all.crossings();
        assert_eq!(
            (hit.face, hit.front_face),
            (face, passage == Passage::Enter),
            "{k}"
        );
        assert_eq!(
            (all[0].t, all[0].face, all[0].passage),
            (hit.t, face, passage),
            "{k}"
        );
        assert!((hit.t - t_want).abs() <= 1e-9 * size, "{k}: {}", hit.t);
        // The definition, along the literal line: the origin within f64 rounding of the
        // surface, the chord (0, t) strictly on one side, the hit on the surface, the
        // other side just before the origin and just past the hit.
        let f = |t: f64| signed(pose, radii, o + d * t);
        let rounding = 4.0 * f64::EPSILON * ((o - pose[0]).length() + size);
        let side = if passage == Passage::Exit { -1.0 } else { 1.0 };
        assert!(f(0.0).abs() <= rounding, "{k}: F(0) = {:e}", f(0.0));
        assert!(f(hit.t).abs() <= rounding, "{k}: F(t) = {:e}", f(hit.t));
        assert!(
            side * f(0.5 * hit.t) > 10.0 * rounding,
            "{k}: {:e}",
            f(0.5 * hit.t)
        );
        for i in 1..32 {
            let t = hit.t * f64::from(i) / 32.0;
            assert!(side * f(t) > 0.0, "{k}: F({t:e}) = {:e}", f(t));
        }
        for t in [-0.5 * hit.t, 1.5 * hit.t] {
            assert!(side * f(t) < -10.0 * rounding, "{k}: F({t:e}) = {:e}", f(t));
        }
    }
}
