//! The renderer API on arbitrary bit patterns (NaN, ±∞, subnormals, ±0, huge): the
//! constructors refuse what they cannot serve, and on everything they accept the exact
//! intersection and every cull run without a panic, answer finitely inside the ray's
//! range, no cull changes the answer (a rejected ray has no hit), and the `RayCast` queries
//! give the free functions' answers; `intersect_all`'s crossings are finite, sorted, in
//! range and alternate. The quartic solvers take any f64 coefficients
//! (finite, sorted roots), and `solve_quartic` still finds the known roots of quartics
//! scaled far beyond f64's comfortable range.

// Uses the oracle-free API only, but shares the harness feature gate of the suite.

use glam::{DVec3, Vec3};
use proptest::prelude::*;
use torus_cull::quartic::{nearest_root_depressed, solve_depressed_monic, solve_quartic};
use torus_cull::{
    CullKind, DRay, F32Verdict, Passage, Ray, RayCast, Torus, intersect, intersect_all,
    intersect_culled, intersect_f32, intersect_f32_certified,
};

/// The culls that look at the whole line, direction included, and so reject a line with a
/// non-finite origin or direction (which has no hit: `Ray::new` refuses it).
const LOOK_AT_THE_DIRECTION: [CullKind; 7] = [
    CullKind::Sphere,
    CullKind::Cychosz,
    CullKind::Skala,
    CullKind::Ellipsoid,
    CullKind::Quadric,
    CullKind::Discriminant,
    CullKind::DiscriminantF64,
];

/// Floats by bit pattern, for f32 and f64 alike: every class (any bits, finite, small,
/// signed zeros, subnormal, the largest, infinite, NaN) equally likely to come up.
macro_rules! any_float {
    ($name:ident, $t:ty, $bits:ty) => {
        fn $name() -> impl Strategy<Value = $t> {
            prop_oneof![
                any::<$bits>().prop_map(<$t>::from_bits),
                any::<$t>(),
                (-4.0 as $t..4.0),
                Just(0.0 as $t),
                Just(-0.0 as $t),
                Just(<$t>::MIN_POSITIVE / 2.0),
                Just(<$t>::MAX),
                Just(<$t>::INFINITY),
                Just(<$t>::NAN),
            ]
        }
    };
}
any_float!(any_f32, f32, u32);
any_float!(any_f64, f64, u64);

fn vec3() -> impl Strategy<Value = Vec3> {
    prop::array::uniform3(any_f32()).prop_map(Vec3::from)
}

fn dvec3() -> impl Strategy<Value = DVec3> {
    prop::array::uniform3(any_f64()).prop_map(DVec3::from)
}

/// A torus the constructor accepts, often a plain one so that rays meet it.
fn torus() -> impl Strategy<Value = Torus> {
    prop_oneof![
        (vec3(), vec3(), any_f32(), any_f32()),
        (vec3(), vec3(), 0.5f32..4.0, 0.01f32..0.45),
        (Just(Vec3::ZERO), Just(Vec3::Y), Just(2.0f32), Just(1.0f32)),
    ]
    .prop_filter_map("refused", |(c, a, big, small)| {
        Torus::new(c, a, big, small).ok()
    })
}

/// Checks one accepted ray of either precision against every cull, through the free
/// functions and the `RayCast` queries (which must be the same answers).
fn check<R: torus_cull::TorusRay>(
    torus: &Torus,
    ray: &R,
    t_of: impl Fn(&R::Hit) -> (f64, DVec3),
    range: (f64, f64),
) -> Result<(), TestCaseError>
where
    R::Hit: PartialEq + std::fmt::Debug,
    R::Float: PartialEq + std::fmt::Debug,
{
    let found = intersect(torus, ray);
    if let Some(hit) = &found {
        let (t, n) = t_of(hit);
        prop_assert!(
            t.is_finite() && t >= range.0 && t <= range.1,
            "t = {t} outside {range:?}"
        );
        prop_assert!(
            n.is_finite() && (n.length() - 1.0).abs() < 1e-3,
            "normal {n}"
        );
    }
    let found_t = found.as_ref().map(|h| R::hit_t(h));
    prop_assert!(torus.cast_ray_and_get_normal(ray) == found);
    prop_assert!(torus.cast_ray(ray) == found_t);
    prop_assert_eq!(torus.intersects_ray(ray), found.is_some());
    for cull in CullKind::TIMED {
        let culled = intersect_culled(&cull, torus, ray);
        prop_assert!(
            culled == found,
            "{cull} changed the answer: {culled:?} vs {found:?} on {torus:?}"
        );
        let with = torus.with_cull(cull);
        prop_assert!(with.cast_ray_and_get_normal(ray) == found, "{cull}");
        prop_assert!(with.cast_ray(ray) == found_t, "{cull}");
        prop_assert_eq!(with.intersects_ray(ray), found.is_some(), "{}", cull);
    }
    Ok(())
}

/// What `intersect_all` must be on any accepted ray (see the property below).
fn check_all<P: torus_cull::Precision>(
    torus: &Torus,
    ray: &Ray<P>,
    t64: impl Fn(P::Float) -> f64,
    n64: impl Fn(P) -> DVec3,
) -> Result<(), TestCaseError>
where
    Ray<P>: torus_cull::TorusRay<Hit = torus_cull::Hit<P>>,
{
    let all = intersect_all(torus, ray);
    let (lo, hi) = (t64(ray.t_min()), t64(ray.t_max()));
    prop_assert!(all.len() <= 4);
    let mut inside = all.starts_inside();
    let mut last = f64::NEG_INFINITY;
    for c in all.as_slice() {
        let t = t64(c.t);
        prop_assert!(t.is_finite() && t >= lo && t <= hi && t >= last, "{all:?}");
        let n = n64(c.normal);
        prop_assert!(n.is_finite() && (n.length() - 1.0).abs() < 1e-3, "{all:?}");
        match c.passage {
            Passage::Enter => prop_assert!(!inside, "{all:?}"),
            Passage::Exit => prop_assert!(inside, "{all:?}"),
            Passage::Touch => {}
        }
        if c.passage != Passage::Touch {
            inside = !inside;
        }
        last = t;
    }
    let spans = all.spans();
    prop_assert!(spans.len() <= 2);
    for s in spans.as_slice() {
        prop_assert!(t64(s.t_enter) <= t64(s.t_exit), "{spans:?}");
    }
    let first = all.as_slice().first().map(|c| t64(c.t));
    let hit = intersect(torus, ray).map(|h| t64(h.t));
    prop_assert_eq!(first.is_some(), hit.is_some(), "{:?} vs {:?}", all, hit);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 20_000, ..ProptestConfig::default() })]

    #[test]
    fn f32_rays_of_any_bits(torus in torus(), o in vec3(), d in vec3(), aim in any::<bool>()) {
        // Half the rays are aimed at the torus's centre from `o`, so that many meet it.
        let d = if aim { torus.center() - o } else { d };
        if let Ok(ray) = Ray::new(o, d) {
            check(&torus, &ray, |h| (f64::from(h.t), h.normal.as_dvec3()), (0.0, f64::INFINITY))?;
        }
    }

    #[test]
    fn f64_rays_of_any_bits(torus in torus(), o in dvec3(), d in dvec3(), aim in any::<bool>()) {
        let d = if aim { torus.center().as_dvec3() - o } else { d };
        if let Ok(ray) = DRay::new(o, d) {
            check(&torus, &ray, |h| (h.t, h.normal), (0.0, f64::INFINITY))?;
        }
    }

    /// The certified f32 path on any ray the constructors accept: no panic; a proved hit
    /// lies in range with a unit normal, and agrees with the f64 path (a proof is a proof);
    /// what f32 cannot prove comes back escalated with the f64 answer.
    #[test]
    fn certified_f32_path_on_rays_of_any_bits(
        torus in torus(), o in vec3(), d in vec3(), aim in any::<bool>(), surface in any::<bool>(),
    ) {
        let d = if aim { torus.center() - o } else { d };
        // From a surface point too (the certified cubic; an origin off the surface is
        // answered as a literal ray).
        let made = if surface { Ray::from_surface(o, d) } else { Ray::new(o, d) };
        if let Ok(ray) = made {
            match intersect_f32_certified(&torus, &ray) {
                F32Verdict::Hit { t, normal } => {
                    prop_assert!(t.is_finite() && t >= ray.t_min() && t <= ray.t_max(), "t = {t}");
                    prop_assert!((normal.length() - 1.0).abs() < 1e-3, "{normal}");
                    prop_assert!(intersect(&torus, &ray).is_some(), "f32 proved a hit f64 misses");
                }
                F32Verdict::Miss => {
                    prop_assert!(intersect(&torus, &ray).is_none(), "f32 proved a miss f64 hits");
                }
                _ => {
                    let finished = intersect_f32(&torus, &ray);
                    prop_assert!(finished.escalated);
                    prop_assert_eq!(finished.hit, intersect(&torus, &ray));
                }
            }
        }
    }

    /// `intersect_all` on any ray the constructor accepts, f32 and f64, literal or from a
    /// surface point: no panic, at most four crossings with finite `t` in range, sorted,
    /// unit normals, entries and exits alternating from the side at `t_min`, at most two
    /// well-formed spans, and the first crossing where `intersect` puts the hit (or
    /// neither has one).
    #[test]
    fn intersect_all_on_rays_of_any_bits(
        torus in torus(), o in dvec3(), d in dvec3(), aim in any::<bool>(), surface in any::<bool>(),
    ) {
        let d = if aim { torus.center().as_dvec3() - o } else { d };
        let made = if surface { DRay::from_surface(o, d) } else { DRay::new(o, d) };
        if let Ok(ray) = made {
            check_all(&torus, &ray, |t| t, |n| n)?;
            if let Ok(narrow) = if surface {
                Ray::from_surface(o.as_vec3(), d.as_vec3())
            } else {
                Ray::new(o.as_vec3(), d.as_vec3())
            } {
                check_all(&torus, &narrow, f64::from, |n| n.as_dvec3())?;
            }
        }
    }

    /// Every cull's raw `keeps` on any bit patterns of origin and direction (not through a
    /// validated ray: a renderer may pass a raw `Vec3`): no panic, in release or debug
    /// (`RUST_MIN_STACK=268435456 cargo test --test api raw_cull`: the
    /// unoptimized lane code needs a large stack). pulp's integer lanes wrap rather than
    /// panic, so the rescaling's exponent is clamped in the code (an infinite component
    /// used to make the factor 2^(254 − 255 wrapped) = −∞); a non-finite line is then
    /// rejected by the culls that look at the direction (it has no hit: `Ray::new`
    /// refuses it).
    ///
    /// Which culls reject such a line is checked too ([`LOOK_AT_THE_DIRECTION`]); the
    /// others (`none` keeps everything, the slab tests of `aabb` and `thick_cylinder`
    /// compare coordinates one at a time, and a NaN comparison keeps) may keep it.
    #[test]
    fn raw_cull_keeps_takes_any_bits(torus in torus(), o in vec3(), d in vec3()) {
        let bounds = torus.bounds();
        let finite = o.is_finite() && d.is_finite();
        for cull in CullKind::TIMED {
            let keep = cull.keeps(bounds, o, d);
            if !finite && LOOK_AT_THE_DIRECTION.contains(&cull) {
                prop_assert!(!keep, "{cull:?} keeps the non-finite line o = {o}, d = {d}");
            }
        }
    }

    #[test]
    fn depressed_quartic_solvers_take_any_coefficients(
        c in prop::array::uniform3(any_f64()),
        lo in any_f64(),
        hi in any_f64(),
    ) {
        let all = solve_depressed_monic(c[0], c[1], c[2]);
        prop_assert!(all.as_slice().iter().all(|r| r.is_finite()), "{all:?}");
        prop_assert!(all.as_slice().windows(2).all(|w| w[0] <= w[1]), "{all:?}");
        if let Some(u) = nearest_root_depressed(c[0], c[1], c[2], lo, hi) {
            prop_assert!(u.is_finite() && u >= lo && u <= hi, "{u} outside [{lo}, {hi}]");
        }
    }

    /// The general solver on any coefficients: finite roots, sorted, never a panic.
    #[test]
    fn general_quartic_solver_takes_any_coefficients(c in prop::array::uniform5(any_f64())) {
        let all = solve_quartic(c);
        prop_assert!(all.as_slice().iter().all(|r| r.is_finite()), "{c:?}: {all:?}");
        prop_assert!(all.as_slice().windows(2).all(|w| w[0] <= w[1]), "{c:?}: {all:?}");
    }

    /// ... and not by answering nothing: a quartic with four known, separated roots of any
    /// scale 2^±200, times a leading coefficient of any scale 2^±150 (so that the monic
    /// form's coefficients span 2^±950), has its four roots found. The roots are scaled by
    /// a power of two after the symmetric functions are formed, so the coefficients are the
    /// base quartic's, exactly scaled, and the roots are the scaled base roots to the
    /// base quartic's conditioning (gaps ≥ 1/2 on [−8, 8]: far below the 1e-8 allowed).
    #[test]
    fn general_quartic_solver_finds_known_roots_at_any_scale(
        base in prop::array::uniform4(-8.0f64..8.0).prop_filter("close roots", |r| {
            let mut s = *r;
            s.sort_by(f64::total_cmp);
            s.windows(2).all(|w| w[1] - w[0] >= 0.5)
        }),
        root_exp in -200i32..=200,
        lead_exp in -150i32..=150,
        lead in prop_oneof![1.0f64..2.0, -2.0f64..-1.0],
    ) {
        let mut base = base;
        base.sort_by(f64::total_cmp);
        let [a, b, c, d] = base;
        // Elementary symmetric functions of the base roots.
        let e = [
            1.0,
            a + b + c + d,
            a * b + a * c + a * d + b * c + b * d + c * d,
            a * b * c + a * b * d + a * c * d + b * c * d,
            a * b * c * d,
        ];
        let lead = lead * 2f64.powi(lead_exp);
        let coefficients: [f64; 5] = std::array::from_fn(|k| {
            let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
            sign * e[k] * lead * 2f64.powi(root_exp * k as i32)
        });
        let scale = 2f64.powi(root_exp);
        let roots = solve_quartic(coefficients);
        prop_assert_eq!(roots.len(), 4, "{:?}: {:?}", coefficients, roots);
        for (got, want) in roots.as_slice().iter().zip(base) {
            prop_assert!(
                (got / scale - want).abs() <= 1e-8 * 8.0,
                "{coefficients:?}: {roots:?}, want {base:?} × {scale:e}"
            );
        }
    }
}

/// The case the bit-pattern property first found for `solve_quartic`: made monic as given,
/// c[4]/c[0] = f64::MAX/−1.1e-308 overflows and the "roots" came back ±∞. The roots are
/// ±(f64::MAX/1.1e-308)^¼ ≈ ±1.13e154 (the −5e-324·t² term is negligible).
#[test]
fn solve_quartic_takes_any_coefficients() {
    let roots = solve_quartic([-1.1251701976475783e-308, 0.0, -5e-324, 0.0, f64::MAX]);
    assert!(roots.as_slice().iter().all(|r| r.is_finite()), "{roots:?}");
    // Fourth roots first: the quotient itself overflows f64.
    let want = f64::MAX.sqrt().sqrt() / 1.1251701976475783e-308f64.sqrt().sqrt();
    assert_eq!(roots.len(), 2, "{roots:?}");
    for (got, want) in roots.as_slice().iter().zip([-want, want]) {
        assert!((got / want - 1.0).abs() < 1e-12, "{roots:?} vs ±{want:e}");
    }
}

/// The cases the properties above first found. An f32 origin at f32::MAX aimed back at the
/// torus: its f64 foot point erred by about 10²² (sphere rejected the hit), and its hit
/// lies past f32's largest t (it was reported at t = ∞). An f64 origin at f64::MAX: the
/// same t overflow in f64. A depressed quartic with q = f64::MAX: ±∞ "roots".
#[test]
fn the_first_found_cases_stay_fixed() {
    let torus = Torus::canonical(2.0, 1.0).unwrap();
    let far = Ray::new(
        Vec3::new(0.0, 0.0, f32::MAX),
        Vec3::new(0.0, 0.0, -2.760_388_6e16),
    )
    .unwrap();
    let found = intersect(&torus, &far);
    let hit = found.expect("the line hits the tube at z = 3 and t ≈ 1.2e22");
    assert!((f64::from(hit.t) - 1.2327335e22).abs() < 1e16, "{hit:?}");
    for cull in CullKind::TIMED {
        assert_eq!(intersect_culled(&cull, &torus, &far), found, "{cull}");
    }
    let beyond = Ray::new(
        Vec3::new(f32::MAX, 0.0, 0.0),
        Vec3::new(-0.836_716, 0.0, 0.0),
    )
    .unwrap();
    assert_eq!(
        intersect(&torus, &beyond),
        None,
        "t past f32::MAX is not a finite hit"
    );
    let beyond = DRay::new(DVec3::new(0.0, 0.0, f64::MAX), DVec3::new(0.0, 0.0, -0.52)).unwrap();
    assert_eq!(
        intersect(&torus, &beyond),
        None,
        "t past f64::MAX is not a finite hit"
    );
    let roots = solve_depressed_monic(0.0, f64::MAX, 0.364_952_612_642_686_25);
    assert!(
        !roots.is_empty() && roots.as_slice().iter().all(|r| r.is_finite()),
        "{roots:?}"
    );
}
