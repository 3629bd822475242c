//! Miss capture (rejected / oracle misses) of the culls beyond the paper, against
//! independent reference figures and against what the padding allows.
//!
//! The reference: isotropic lines through the bounding sphere, 10⁶ per ν, from an
//! independent numpy implementation (cychosz, skala, ellipsoid, quadric). A wrong
//! formula (a bound that is too loose, or a quadric of the wrong torus) moves these by
//! far more than the ±0.015 allowed here; 40 000 lines give a standard error ≤ 0.0025.

// Every check here runs against the harness's oracle or CLI.

use torus_cull::CullKind;
use torus_cull_lab::measure::{LabeledBatch, count};
use torus_cull_lab::oracle::OracleClass;
use torus_cull_lab::workload::{Case, Pose, generate};

const SEED: u64 = 20261121;

/// ν, then cychosz, skala, ellipsoid, quadric.
const REFERENCE: [(f64, [f64; 4]); 5] = [
    (1.1, [0.561, 0.613, 0.914, 0.914]),
    (2.0, [0.646, 0.745, 0.870, 0.936]),
    (4.0, [0.614, 0.869, 0.721, 0.960]),
    (10.0, [0.553, 0.949, 0.592, 0.984]),
    (32.0, [0.517, 0.984, 0.528, 0.995]),
];

fn labeled(case: Case, nu: f64, rays: usize) -> LabeledBatch {
    LabeledBatch::label(generate(case, nu, rays, SEED, Pose::Random).unwrap())
}

/// Miss capture of `cull` on the batch; also checks it rejected no hit.
fn capture(cull: CullKind, batch: &LabeledBatch) -> f64 {
    let (record, false_rejects) = count(cull, batch);
    assert!(false_rejects.is_empty(), "{cull}: {false_rejects:?}");
    record.miss_capture.expect("the batch has misses")
}

#[test]
fn capture_matches_the_independent_reference_on_isotropic_lines() {
    let culls = [
        CullKind::Cychosz,
        CullKind::Skala,
        CullKind::Ellipsoid,
        CullKind::Quadric,
    ];
    for (nu, reference) in REFERENCE {
        let batch = labeled(Case::Uniform, nu, 40_000);
        let got = culls.map(|c| capture(c, &batch));
        println!("nu={nu:>4}: {culls:?} = {got:.4?} (reference {reference:?})");
        for ((cull, g), r) in culls.iter().zip(got).zip(reference) {
            assert!((g - r).abs() <= 0.015, "{cull} at nu={nu}: {g:.4} vs {r}");
        }
        let [cychosz, skala, ellipsoid, quadric] = got;
        assert!(ellipsoid >= cychosz, "nu={nu}");
        assert!(quadric >= skala && quadric >= ellipsoid, "nu={nu}");
    }
}

#[test]
fn quadric_captures_at_least_skala_on_uniform_and_camera_lines() {
    for case in [Case::Uniform, Case::Camera] {
        for nu in [1.1, 2.0, 4.0, 8.0, 32.0] {
            let batch = labeled(case, nu, 20_000);
            let (skala, quadric) = (
                capture(CullKind::Skala, &batch),
                capture(CullKind::Quadric, &batch),
            );
            println!("{case} nu={nu:>4}: skala {skala:.4} quadric {quadric:.4}");
            assert!(quadric >= skala, "{case} nu={nu}: {quadric} < {skala}");
        }
    }
}

/// `discriminant` keeps exactly the lines that enter the padded torus: every miss it
/// keeps passes within η of the surface, so its capture is all that the padding allows.
/// That is ≥ 0.998 on uniform and camera lines except uniform at ν = 1.1, where
/// 0.16–0.24 % of the misses pass within η (0.9976–0.9984 over seeds). Hole lines are all
/// near the tube when the hole is small: at ν = 1.1 1.5 % of them pass within η
/// (η = 2⁻¹²·(R + r) ≈ 4.7e-4 against a hole of radius 0.09), at ν = 2 0.24 %.
#[test]
fn discriminant_keeps_no_miss_beyond_the_padding_band() {
    for case in [Case::Uniform, Case::Camera, Case::Hole] {
        for nu in [1.1, 2.0, 4.0, 8.0, 32.0] {
            let batch = labeled(case, nu, 40_000);
            let torus = &batch.batch.torus;
            let eta = f64::from(torus.bounds().minor_safe() - torus.minor_radius());
            for cull in [CullKind::Discriminant, CullKind::DiscriminantF64] {
                let keeps = torus_cull_lab::measure::verdicts(cull, &batch.batch);
                let worst = batch
                    .labels
                    .iter()
                    .zip(&keeps)
                    .filter(|(l, keep)| **keep && l.class == OracleClass::Miss)
                    .map(|(l, _)| l.margin / eta)
                    .fold(0.0, f64::max);
                let got = capture(cull, &batch);
                println!("{case} nu={nu:>4} {cull}: capture {got:.4}, kept misses ≤ {worst:.4} η");
                assert!(
                    worst <= 1.01,
                    "{case} nu={nu} {cull}: kept a miss at {worst} η"
                );
                let floor = match (case, nu) {
                    (Case::Hole, 1.1) => 0.98,
                    (Case::Hole, 2.0) => 0.996,
                    (Case::Uniform, 1.1) => 0.997,
                    _ => 0.998,
                };
                assert!(got >= floor, "{case} nu={nu} {cull}: {got} < {floor}");
            }
        }
    }
}
