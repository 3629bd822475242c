//! Issue 19's f32 check (`check --shape ring --precision f32`, alias `f32-check`), on a
//! few thousand rays per family: ours (the certified f32
//! verdict and the whole f32 path) never misses a definite hit, never answers a definite
//! miss with a `t`, and every accepted `t` is within 2e-4·(R + r) + 4 ulp of the oracle's
//! first root, on every family; the peer (the plain f32 closed form of shaders) is
//! counted on the same rays and shows its speckles where the families aim.

use crate::support::assert_ok;
use std::process::Command;
use std::sync::OnceLock;
use torus_cull_lab::check::record::{AnswerRecord, CheckFile, ClassRecord};
use torus_cull_lab::check::shapes::ring::{self as f32_check, RingF32, families};
use torus_cull_lab::oracle::OracleClass;
use torus_cull_lab::peer_f32::intersect_peer_f64;

const BIN: &str = env!("CARGO_BIN_EXE_torus-cull");
const RAYS: usize = 3000;
const SEED: u64 = 20261121;

/// One family's record as the tests read it: the class and its three intersectors.
struct FamilyRecord {
    family: String,
    nu: Option<f64>,
    rays: u64,
    hits: u64,
    misses: u64,
    ambiguous: u64,
    certified: Tally,
    f32_path: Tally,
    peer: Tally,
}

/// One intersector's counts.
#[derive(Debug)]
struct Tally {
    escalated: u64,
    escalation_rate: f64,
    missed: u64,
    spurious: u64,
    far: u64,
    hits_answered: u64,
    t_error: Option<torus_cull_lab::check::record::ErrorStats>,
}

impl Tally {
    fn of(a: &AnswerRecord, rays: u64) -> Tally {
        Tally {
            escalated: a.count("escalated"),
            escalation_rate: a.count("escalated") as f64 / rays as f64,
            missed: a.wrong["missed"],
            spurious: a.wrong["spurious"],
            far: a.wrong["far"],
            hits_answered: a.count("hits_answered"),
            t_error: a.t_error,
        }
    }
}

impl FamilyRecord {
    fn of(c: &ClassRecord) -> FamilyRecord {
        let who = |w: &str| Tally::of(c.answers.iter().find(|a| a.who == w).unwrap(), c.rays);
        let (hits, misses, ambiguous) = c.labels();
        FamilyRecord {
            family: c.words["family"].clone(),
            nu: c.params.get("nu").copied(),
            rays: c.rays,
            hits,
            misses,
            ambiguous,
            certified: who("cert"),
            f32_path: who("f32"),
            peer: who("peer"),
        }
    }
}

/// Every family's record, computed once for the whole test binary (no timings), and the
/// records as the check writes them.
fn checked() -> &'static (Vec<ClassRecord>, Vec<FamilyRecord>) {
    static RECORDS: OnceLock<(Vec<ClassRecord>, Vec<FamilyRecord>)> = OnceLock::new();
    RECORDS.get_or_init(|| {
        let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
        let shape = RingF32 {
            families: families::all(),
            rounds: 0,
        };
        let all: Vec<usize> = (0..shape.families.len()).collect();
        let checked = torus_cull_lab::check::check(&shape, &all, (RAYS, SEED), threads, &|_, _| {})
            .expect("every family generates");
        let view = checked.records.iter().map(FamilyRecord::of).collect();
        (checked.records, view)
    })
}

fn records() -> &'static [FamilyRecord] {
    &checked().1
}

fn is_tangent(r: &FamilyRecord) -> bool {
    r.family.starts_with("tangent_") || r.family == "bitangent"
}

#[test]
fn ours_misses_nothing_invents_nothing_and_every_t_is_within_tolerance() {
    let records = records();
    assert_eq!(records.len(), families::all().len());
    let mut problems = Vec::new();
    for r in records {
        for (who, t) in [("certified", &r.certified), ("f32 path", &r.f32_path)] {
            if t.missed + t.spurious + t.far > 0 {
                problems.push(format!(
                    "{} nu {:?}: {who} missed {} spurious {} far {} (t error {:?})",
                    r.family, r.nu, t.missed, t.spurious, t.far, t.t_error
                ));
            }
        }
        // The two views of ours agree on what escalated.
        assert_eq!(r.certified.escalated, r.f32_path.escalated, "{}", r.family);
        // The whole path answers every definite hit with a t.
        assert_eq!(r.f32_path.hits_answered, r.hits, "{}", r.family);
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// The peer is counted, and the families find its speckles: on every tangent and
/// bitangent family it misses hits or reports hits that are not there.
#[test]
fn the_peer_shows_speckles_on_the_tangent_families() {
    let tangent: Vec<&FamilyRecord> = records().iter().filter(|r| is_tangent(r)).collect();
    assert_eq!(tangent.len(), 9);
    for r in &tangent {
        assert!(
            r.peer.missed + r.peer.spurious > 0,
            "{}: the peer got every definite ray right ({} hits, {} misses)",
            r.family,
            r.hits,
            r.misses
        );
    }
    let rays: u64 = tangent.iter().map(|r| r.rays).sum();
    let wrong: u64 = tangent
        .iter()
        .map(|r| r.peer.missed + r.peer.spurious)
        .sum();
    assert!(
        wrong * 100 > rays,
        "{wrong} of {rays}: fewer speckles than 1 %"
    );
    // The table shows them.
    let table = torus_cull_lab::check::table::table(&checked().0);
    for r in &tangent {
        assert!(table.contains(&r.family), "{}", r.family);
    }
}

/// The speckles are the method's in f32, not a broken peer: on isotropic rays the f32
/// peer is right but for a handful of rays, and the same closed form in f64 agrees with
/// the oracle's roots to 1e-8·(R + r).
#[test]
fn the_peer_is_sound_on_easy_rays() {
    for r in records().iter().filter(|r| r.family == "uniform") {
        let wrong = r.peer.missed + r.peer.spurious;
        assert!(wrong * 200 <= r.rays, "uniform nu {:?}: {wrong}", r.nu);
    }
    for family in families::all()
        .into_iter()
        .filter(|f| matches!(f.name.as_str(), "uniform" | "camera"))
    {
        let rays = f32_check::label(&family.generate(500, SEED).unwrap());
        for l in rays {
            let twin = intersect_peer_f64(&l.torus, &l.ray);
            match l.class {
                OracleClass::Hit => {
                    let t = twin.unwrap_or_else(|| panic!("{} {:?}: missed", family.name, l.ray));
                    let err = (t - l.first_root.unwrap()).abs() * f64::from(l.ray.dir().length())
                        / l.outer();
                    assert!(err < 1e-8, "{} {:?}: error {err:e}", family.name, l.ray);
                }
                OracleClass::Miss => assert_eq!(twin, None, "{} {:?}", family.name, l.ray),
                OracleClass::Ambiguous => {}
            }
        }
    }
}

/// Each family holds what it is for: the adversarial ones both definite hits and
/// definite misses (so that missed and spurious both mean something), hole only misses.
#[test]
fn the_families_hold_definite_hits_and_misses() {
    for r in records() {
        assert_eq!(r.rays, RAYS as u64, "{}", r.family);
        assert_eq!(r.hits + r.misses + r.ambiguous, r.rays, "{}", r.family);
        assert!(
            r.ambiguous * 2 < r.rays,
            "{}: {} ambiguous",
            r.family,
            r.ambiguous
        );
        match r.family.as_str() {
            "hole" => assert_eq!(r.hits, 0),
            "uniform" | "camera" | "outer_band" => {}
            _ => assert!(
                r.hits > 0 && r.misses > 0,
                "{}: {} hits, {} misses",
                r.family,
                r.hits,
                r.misses
            ),
        }
    }
}

/// The escalation rate of the certified verdict on `families` above `limit`, listed.
fn escalating(families: &[&str], limit: f64) -> Vec<String> {
    records()
        .iter()
        .filter(|r| families.contains(&r.family.as_str()))
        .filter(|r| r.certified.escalation_rate > limit)
        .map(|r| {
            format!(
                "{} nu {:?}: {:.2} %",
                r.family,
                r.nu,
                100.0 * r.certified.escalation_rate
            )
        })
        .collect()
}

/// Issue 19: escalation ≤ 1 % on uniform and camera rays at every ν, and on secondary
/// rays with a scene-scale ε (t_min = 1e-4·(R + r)).
#[test]
fn escalation_is_at_most_one_percent_on_uniform_camera_and_secondary_rays() {
    let over = escalating(&["uniform", "camera", "secondary_scene_eps"], 0.01);
    assert!(over.is_empty(), "{}", over.join("\n"));
}

/// The same for secondary rays with a tube-scale ε (t_min = 1e-4·r): for thin tubes the
/// ray starts within ~1e-7·R of the surface, where F > 0 on [t_min, root) is not proved
/// in f32. Measured at commit c86a11b: 40 % (uniform hemisphere) and 93 % (grazing).
#[test]
#[ignore = "issue 19: secondary rays with t_min = 1e-4·r escalate ~40 % (grazing ~93 %)"]
fn escalation_is_at_most_one_percent_on_secondary_rays_with_a_tube_scale_epsilon() {
    let over = escalating(&["secondary", "secondary_grazing"], 0.01);
    assert!(over.is_empty(), "{}", over.join("\n"));
}

#[test]
fn the_cli_writes_the_json_and_refuses_bad_outputs() {
    let dir = std::env::temp_dir().join(format!("torus-cull-f32-check-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let run = |out: &std::path::Path| {
        Command::new(BIN)
            .args(["f32-check", "--rays", "40", "--rounds", "1", "--out"])
            .arg(out)
            .output()
            .unwrap()
    };
    // A directory and a missing parent are refused before any work.
    for (out, needle) in [
        (dir.clone(), "is a directory"),
        (dir.join("missing/out.json"), "does not exist"),
    ] {
        let o = run(&out);
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{}: {stderr}", out.display());
        assert!(
            stderr.contains("--out") && stderr.contains(needle),
            "{stderr}"
        );
    }
    let out = dir.join("f32.json");
    let o = run(&out);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_ok(&o);
    assert!(
        stdout.contains("bitangent") && stdout.contains("peer"),
        "{stdout}"
    );
    let file: CheckFile = serde_json::from_slice(&std::fs::read(&out).unwrap()).unwrap();
    assert_eq!(
        file.schema_version,
        torus_cull_lab::check::record::SCHEMA_VERSION
    );
    assert_eq!(file.meta.tool.as_deref(), Some("check"));
    assert_eq!(
        (file.shape.as_str(), file.precision.as_str()),
        ("ring", "f32")
    );
    assert_eq!(file.rays_per_class, 40);
    assert_eq!(file.classes.len(), families::all().len());
    assert!(file.classes.iter().all(|f| f.ns_per_ray.is_some()));
    // No temp file is left next to it: the file and its four plots (issue 29).
    let mut names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(
        names,
        [
            "f32-escalation.svg",
            "f32-ns_per_ray.svg",
            "f32-t_error.svg",
            "f32-wrong.svg",
            "f32.json"
        ]
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
