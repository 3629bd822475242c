//! The seed paper's misprints (table in `docs/math.md`), as counterexamples and as counts
//! of rejected hits.
//! This proves the harness can see a broken cull.

// Every check here runs against the harness's oracle or CLI.

use crate::common::{NUS, family, pairs};
use glam::Vec3;
use torus_cull::Named;
use torus_cull::{Cull, CullKind, CullVisitor, Ray, Torus};
use torus_cull_lab::errata::PrintedCull;
use torus_cull_lab::measure::CountedCull;
use torus_cull_lab::oracle::{OracleClass, classify_line};
use torus_cull_lab::workload::Case;

fn keeps(cull: impl Into<CountedCull>, torus: &Torus, ray: &Ray) -> bool {
    struct One<'a>(&'a Torus, &'a Ray);
    impl CullVisitor for One<'_> {
        type Output = bool;
        fn visit<C: Cull>(self, cull: C) -> bool {
            let line = self.0.line_to_local(self.1);
            cull.keeps(self.0.bounds(), line.origin, line.dir)
        }
    }
    cull.into().visit(One(torus, ray))
}

fn counterexample(o: [f32; 3], d: [f32; 3], printed: PrintedCull) {
    let torus = Torus::canonical(2.0, 1.0).unwrap();
    let ray = Ray::new(Vec3::from(o), Vec3::from(d)).unwrap();
    assert_eq!(classify_line(&torus, &ray).class, OracleClass::Hit);
    for cull in CullKind::TIMED {
        assert!(
            keeps(cull, &torus, &ray),
            "{cull} rejects the counterexample"
        );
    }
    assert!(
        !keeps(printed, &torus, &ray),
        "{} should reject it",
        printed.name()
    );
}

/// Each misprint's counterexample (origin, direction): a hit its printed cull rejects.
#[test]
fn each_misprint_rejects_its_counterexample() {
    for (o, d, printed) in [
        // Eq. 35, the second clause.
        (
            [-6.0, 0.5, 0.0],
            [1.0, 0.0, 0.0],
            PrintedCull::CychoszPrinted,
        ),
        // Eq. 105, the band's height.
        (
            [-5.0, 0.5, 2.0],
            [1.0, 0.0, 0.0],
            PrintedCull::SkalaPrintedC,
        ),
        // Eq. 102, the hole's edge.
        ([0.9, -3.0, 0.5], [0.01, 1.0, 0.0], PrintedCull::SkalaEq102),
    ] {
        counterexample(o, d, printed);
    }
}

/// On the same families the conservativeness test uses, each printed variant rejects
/// oracle hits, while its corrected twin rejects none.
#[test]
fn printed_variants_reject_hits_on_the_test_families() {
    let mut false_rejects = [0usize; 3];
    let mut corrected = 0usize;
    for nu in NUS {
        let mut batches = Vec::new();
        for case in [Case::Uniform, Case::Grazing, Case::OuterBand, Case::Camera] {
            batches.extend(family(case, nu, 6_000, 0xE22A ^ nu.to_bits()));
        }
        for (torus, ray) in pairs(&batches) {
            if classify_line(torus, ray).class != OracleClass::Hit {
                continue;
            }
            for (i, cull) in PrintedCull::ALL.iter().copied().enumerate() {
                false_rejects[i] += usize::from(!keeps(cull, torus, ray));
            }
            for cull in [CullKind::Cychosz, CullKind::Skala] {
                corrected += usize::from(!keeps(cull, torus, ray));
            }
        }
    }
    println!("printed variants' false rejects {:?}", false_rejects);
    for (cull, n) in PrintedCull::ALL.iter().copied().zip(false_rejects) {
        assert!(
            n > 0,
            "{} rejected no hit: the harness cannot see it",
            cull.name()
        );
    }
    assert_eq!(corrected, 0);
}
