//! The torus family in the BVH: `Toroid`s (ring, horn, spindle; circular and elliptical
//! tubes) and `PipeBend`s (bores, φ segments) give brute force's answers through the lab's
//! traversal, for camera rays (closest hit), shadow rays (any-hit, spawned on the hit
//! shape) and one bounce per hit (closest, spawned with the shape's own spawn), with every
//! cull at the leaves by the shapes' own rule. At R = 10⁻³ … 10³, and where obvhs's node
//! clamp at t = 10⁻⁴ bites: shapes below its scale, and long direction vectors.

// Every check here runs against brute force over all shapes, with no BVH and no cull.

use crate::renderer_rays::{Rays, assert_every_cull_matches};
use std::collections::BTreeMap;
use torus_cull::Ray;
use torus_cull::bend::BendFace;
use torus_cull_lab::scene::family::{FamilyScene, ShapeClass};

/// Camera, random and bore rays of a family scene, for [`Rays::of`].
fn primary(scene: &FamilyScene) -> Vec<Ray> {
    let mut primary = scene.camera_rays(64);
    primary.extend(scene.random_rays(2000, 5));
    primary.extend(scene.bore_rays(20, 6));
    primary
}

/// What the family's checks count of its rays.
impl Rays {
    /// Camera and random rays' hits, per class of the shape hit.
    fn hits_per_class(&self, scene: &FamilyScene) -> BTreeMap<ShapeClass, usize> {
        let mut per = BTreeMap::new();
        for (id, _) in self.primary_truth.iter().flatten() {
            *per.entry(scene.shapes[*id as usize].class()).or_insert(0) += 1;
        }
        per
    }

    /// The bends' hits (camera, random and bounce rays) per face.
    fn bend_hits_per_face(&self, scene: &FamilyScene) -> BTreeMap<String, usize> {
        let mut hit: Vec<(usize, Ray)> = Vec::new();
        for (ray, h) in self.primary.iter().zip(&self.primary_truth) {
            hit.extend(h.map(|(id, _)| (id as usize, *ray)));
        }
        for (s, h) in self.bounce.iter().zip(&self.bounce_truth) {
            // A bounce is a surface ray on its own shape only.
            hit.extend(h.map(|(id, _)| {
                let ray = if id == s.from { s.ray } else { s.literal() };
                (id as usize, ray)
            }));
        }
        let mut per = BTreeMap::new();
        for (id, ray) in hit {
            if let Some(face) = scene.shapes[id].intersect(&ray).and_then(|h| h.face) {
                *per.entry(format!("{face:?}")).or_insert(0) += 1;
            }
        }
        per
    }

    /// Hits of each kind: camera and random rays, bounces, blocked shadow rays.
    fn counts(&self) -> (usize, usize, usize) {
        (
            self.primary_truth.iter().flatten().count(),
            self.bounce_truth.iter().flatten().count(),
            self.shadow_truth.iter().filter(|&&b| b).count(),
        )
    }
}

/// Every cull (`none`: the exact intersection alone) against brute force, closest and
/// any-hit; panics naming the first mismatches.
fn assert_all_match(scene: &FamilyScene, rays: &Rays, what: &str) {
    let (hits, rehits, blocked) = rays.counts();
    eprintln!(
        "{what}: {} camera/random rays ({hits} hit), {} bounces ({rehits} hit), {} shadow \
         rays ({blocked} blocked); hits per class {:?}, bends' hits per face {:?}",
        rays.primary.len(),
        rays.bounce.len(),
        rays.shadow.len(),
        rays.hits_per_class(scene),
        rays.bend_hits_per_face(scene)
    );
    assert_every_cull_matches(scene, rays, what, |cull, wrong, stats| {
        eprintln!(
            "  {cull}: {wrong} wrong; per ray {:.3} leaf visits, {:.3} culled, {:.3} solves",
            stats.leaf_visits as f64 / rays.len() as f64,
            stats.cull_rejects as f64 / rays.len() as f64,
            stats.quartic_solves as f64 / rays.len() as f64
        );
        assert_eq!(stats.leaf_visits, stats.cull_rejects + stats.quartic_solves);
    });
}

/// Every class of shape hit by at least 10 camera, random and bore rays, and every face of
/// the bends (outer, bore, both caps) by at least 5 of those and the bounces.
fn assert_every_class_hit(scene: &FamilyScene, rays: &Rays, what: &str) {
    let per = rays.hits_per_class(scene);
    for class in ShapeClass::ALL {
        let n = per.get(&class).copied().unwrap_or(0);
        assert!(n >= 10, "{what}: {class:?} hit {n} times: test too weak");
    }
    let faces = rays.bend_hits_per_face(scene);
    for face in [
        BendFace::Outer,
        BendFace::Inner,
        BendFace::StartCap,
        BendFace::EndCap,
    ] {
        let n = faces.get(&format!("{face:?}")).copied().unwrap_or(0);
        assert!(
            n >= 5,
            "{what}: bends' {face:?} hit {n} times: test too weak"
        );
    }
}

/// The scene spread out and packed (shapes overlapping, rays meeting several boxes), at
/// R = 10⁻³, 1 and 10³: camera, shadow and bounce rays.
#[test]
fn family_rays_match_brute_force_at_every_scale() {
    for spread in [1.5, 0.5] {
        for scale in [1e-3, 1.0, 1e3] {
            let what = format!("spread {spread} R={scale}");
            let scene = FamilyScene::build(120, 7, scale, spread).unwrap();
            let rays = Rays::of(&scene, &primary(&scene), 1.0);
            let (hits, rehits, blocked) = rays.counts();
            assert!(
                hits > 200 && rehits > 30 && blocked > 10 && blocked < rays.shadow.len(),
                "{what}: {hits} hits, {rehits} bounces hit, {blocked} of {} shadow rays \
                 blocked: test too weak",
                rays.shadow.len()
            );
            assert_every_class_hit(&scene, &rays, &what);
            assert_all_match(&scene, &rays, &what);
        }
    }
}

/// Shapes below the clamp's scale (R = 10⁻⁵, packed, unit directions): bounces re-hit a
/// neighbour at t < 10⁻⁴, inside a box that obvhs's node test skips.
#[test]
fn tiny_family_below_obvhs_clamp() {
    let scene = FamilyScene::build(120, 3, 1e-5, 0.5).unwrap();
    assert_clamp_case(&scene, 1.0, "R = 1e-5");
}

/// Shapes of R = 1 (packed) and directions 10⁵ long: every box within 10 of a spawned
/// ray's origin lies below t = 10⁻⁴.
#[test]
fn long_directions_family_under_obvhs_clamp() {
    let scene = FamilyScene::build(120, 3, 1.0, 0.5).unwrap();
    assert_clamp_case(&scene, 1e5, "|d| = 1e5");
}

/// Where obvhs's clamp bites: more than 20 bounces re-hit a neighbour below t = 10⁻⁴ (so
/// the case is real), every class of shape is hit, and every traversal equals brute force.
fn assert_clamp_case(scene: &FamilyScene, direction_length: f32, what: &str) {
    let rays = Rays::of(scene, &primary(scene), direction_length);
    let shallow = rays.neighbour_hits_below(1e-4);
    eprintln!("{what}: {shallow} bounces hit a neighbour below t = 1e-4");
    assert!(
        shallow > 20,
        "{what}: only {shallow} neighbour re-hits below 1e-4"
    );
    assert_every_class_hit(scene, &rays, what);
    assert_all_match(scene, &rays, what);
}

/// A scale that is not a positive finite number is refused by both scene builders, naming
/// the value and the allowed range.
#[test]
fn scenes_refuse_a_bad_scale() {
    use torus_cull_lab::scene::{Scene, SceneKind};
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let errors = [
            FamilyScene::build(12, 3, bad, 1.5)
                .err()
                .map(|e| e.to_string()),
            Scene::build_scaled(SceneKind::RingField, 4.0, 12, 3, bad)
                .err()
                .map(|e| e.to_string()),
        ];
        for e in errors {
            let e = e.unwrap_or_else(|| panic!("scale {bad} accepted"));
            assert!(
                e.contains("scale = ") && e.contains("positive finite"),
                "{e}"
            );
        }
    }
}

/// The BVH's leaf boxes, now the shape interface's `Solid::world_aabb`, are the boxes the
/// scene always gave: a toroid's own `world_aabb`, a bend's outer torus's (the whole ring,
/// holding any segment). A tighter box for a cut bend would change the BVH and its timings:
/// it must come as a decision of its own, proved conservative, not through this interface.
#[test]
fn family_boxes_are_the_shapes_own_and_a_bends_outer_torus() {
    use torus_cull_lab::scene::family::FamilyShape;
    let scene = FamilyScene::build(24, 11, 1.0, 1.5).unwrap();
    let mut bends = 0;
    for shape in &scene.shapes {
        let want = match shape {
            FamilyShape::Toroid(t) => t.world_aabb(),
            FamilyShape::Bend(b) => {
                bends += 1;
                b.outer().world_aabb()
            }
        };
        assert_eq!(shape.world_box(), want, "{:?}", shape.class());
    }
    assert_eq!(
        bends, 8,
        "24 shapes cycle through 6 classes, 2 of them bends"
    );
}
