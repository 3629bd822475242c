//! Property tests (proptest): the constructors never panic and keep their invariants, every
//! cull stays conservative on arbitrary lines at arbitrary poses and direction scales, and
//! `eval` never panics on arbitrary rows.

// Every check here runs against the harness's oracle or CLI.

use glam::Vec3;
use proptest::prelude::*;
use torus_cull::{CullKind, Ray, Torus};
use torus_cull_lab::eval::{Precision, eval_csv};
use torus_cull_lab::oracle::{OracleClass, classify_line};

fn vec3(range: std::ops::Range<f32>) -> impl Strategy<Value = Vec3> {
    (range.clone(), range.clone(), range).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 20_000, ..ProptestConfig::default() })]

    #[test]
    fn constructors_never_panic(
        c in prop::array::uniform3(any::<f32>()),
        a in prop::array::uniform3(any::<f32>()),
        big in any::<f32>(),
        small in any::<f32>(),
        o in prop::array::uniform3(any::<f32>()),
        d in prop::array::uniform3(any::<f32>()),
    ) {
        if let Ok(t) = Torus::new(Vec3::from(c), Vec3::from(a), big, small) {
            prop_assert!(t.nu() > 1.0 && t.minor_radius() > 0.0);
            prop_assert!((t.axis().length() - 1.0).abs() < 1e-5);
        }
        if let Ok(r) = Ray::new(Vec3::from(o), Vec3::from(d)) {
            prop_assert!(r.origin().is_finite() && r.dir().is_finite());
            let len_sq = r.dir().length_squared();
            prop_assert!(len_sq.is_finite() && len_sq >= f32::MIN_POSITIVE);
        }
    }

    /// Lines through a box around the torus, at any pose, ν (1.01–1000), scale
    /// (R = 1e-3–1e3) and direction scale: no cull rejects an oracle hit, skala rejects
    /// everything cychosz does, and quadric everything ellipsoid does.
    #[test]
    fn culls_are_conservative_on_arbitrary_lines(
        nu in prop_oneof![1.01f64..64.0, 64.0f64..1000.0],
        major in prop_oneof![0.001f32..1.0, 1.0f32..1000.0],
        center in vec3(-10.0..10.0),
        axis in vec3(-1.0..1.0),
        through in vec3(-1.6..1.6),
        dir in vec3(-1.0..1.0),
        scale_exp in -15.0f32..15.0,
        back in -300.0f32..300.0,
    ) {
        prop_assume!(axis.length() > 1e-3 && dir.length() > 1e-3);
        let torus = Torus::new(center * major, axis, major, major / nu as f32).unwrap();
        let outer = torus.outer_radius();
        let d = dir * 10f32.powf(scale_exp);
        let p = torus.center() + through * outer;
        let ray = Ray::new(p - dir.normalize() * (back * outer), d).unwrap();
        let label = classify_line(&torus, &ray);
        let line = torus.line_to_local(&ray);
        let bounds = torus.bounds();
        for cull in CullKind::TIMED {
            prop_assert!(
                cull.keeps(bounds, line.origin, line.dir) || label.class != OracleClass::Hit,
                "{} rejects a hit: {:?} {:?} margin {:e}", cull, torus, ray, label.margin
            );
        }
        let keeps = |c: CullKind| c.keeps(bounds, line.origin, line.dir);
        prop_assert!(
            keeps(CullKind::Cychosz) || !keeps(CullKind::Skala),
            "skala keeps what cychosz rejects: {:?}", ray
        );
        prop_assert!(
            keeps(CullKind::Ellipsoid) || !keeps(CullKind::Quadric),
            "quadric keeps what ellipsoid rejects: {:?}", ray
        );
    }

    #[test]
    fn eval_never_panics(rows in prop::collection::vec("[-0-9.,eEnaifNI ]{0,40}", 0..6)) {
        let input = format!("ox,oy,oz,dx,dy,dz\n{}\n", rows.join("\n"));
        for precision in [Precision::F64, Precision::F32] {
            let mut out = Vec::new();
            match eval_csv(2.0, 1.0, precision, input.as_bytes(), "prop.csv", &mut out) {
                Ok(n) => prop_assert!(n <= rows.len()),
                Err(e) => prop_assert!(e.to_string().starts_with("prop.csv:")),
            }
        }
    }
}
