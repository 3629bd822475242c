//! [`SceneKind`], the many-torus scene layouts by name: what a workload file's `bvh` key
//! lists (`workload::spec`) and what `scene` builds, so it sits below both.

use serde::{Deserialize, Serialize};

crate::named::named_enum! {
    /// A many-torus scene layout; [`Named::ALL`](torus_cull::Named::ALL) lists every scene by its stable name, in
    /// table order.
    #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
    #[serde(rename_all = "snake_case")]
    pub enum SceneKind: "scene" {
        /// Tori at random centres in a cube, with random axes.
        RingField = "ring_field",
        /// Rows of interlocked links; the camera looks down on them, so every other link is
        /// seen face-on and rays fall through its hole.
        Chain = "chain",
        /// A square grid of tori whose axes all point at the camera: the hole-heavy case the
        /// paper targets.
        FacingGrid = "facing_grid",
        /// Tori as in `ring_field`, each of its own ν, drawn log-uniformly from 1.25 to 16
        /// (the scene's ν is not used).
        MixedNu = "mixed_nu",
        /// Tori as in `ring_field` packed into a cube a third as wide, so that boxes (and
        /// tori) overlap and a ray meets several leaves.
        Dense = "dense",
    }
}

torus_cull::named_display_and_from_str!(SceneKind);
