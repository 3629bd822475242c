//! [`SceneKind`], the many-torus scene layouts by name: what a workload file's `bvh` key
//! lists (`workload::spec`) and what `scene` builds, so it sits below both.

use serde::{Deserialize, Serialize};
use torus_cull::Named;

/// A many-torus scene layout.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SceneKind {
    /// Tori at random centres in a cube, with random axes.
    RingField,
    /// Rows of interlocked links; the camera looks down on them, so every other link is
    /// seen face-on and rays fall through its hole.
    Chain,
    /// A square grid of tori whose axes all point at the camera: the hole-heavy case the
    /// paper targets.
    FacingGrid,
    /// Tori as in `ring_field`, each of its own ν, drawn log-uniformly from 1.25 to 16
    /// (the scene's ν is not used).
    MixedNu,
    /// Tori as in `ring_field` packed into a cube a third as wide, so that boxes (and
    /// tori) overlap and a ray meets several leaves.
    Dense,
}

/// Every scene by its stable name, in table order.
impl Named for SceneKind {
    const KIND: &'static str = "scene";
    const ALL: &'static [SceneKind] = &[
        SceneKind::RingField,
        SceneKind::Chain,
        SceneKind::FacingGrid,
        SceneKind::MixedNu,
        SceneKind::Dense,
    ];

    fn name(self) -> &'static str {
        match self {
            SceneKind::RingField => "ring_field",
            SceneKind::Chain => "chain",
            SceneKind::FacingGrid => "facing_grid",
            SceneKind::MixedNu => "mixed_nu",
            SceneKind::Dense => "dense",
        }
    }
}

torus_cull::named_display_and_from_str!(SceneKind);
