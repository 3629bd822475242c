// ---------------------------------------------------------------------------------------
// mirrors: tc_sphere_slab -> crate::cull::cychosz::sphere_slab
// mirrors: tc_cychosz_keeps -> crate::cull::cychosz::CychoszCull::keeps_lanes

struct TcSphereSlab {
    half_chord_sq: f32,
    unit_y_sq: f32,
    keep: bool,
};

// `cychosz`: the sphere chord and the slab, squared, without a root (src/cull/cychosz.rs).
fn tc_sphere_slab(b: TcBounds, q: vec3<f32>, d: vec3<f32>) -> TcSphereSlab {
    var out: TcSphereSlab;
    out.half_chord_sq = b.outer_sq - dot(q, q);
    out.unit_y_sq = d.y * d.y / dot(d, d);
    let above = abs(q.y) - b.minor;
    let beyond_slab = above > 0.0 && above * above > out.unit_y_sq * out.half_chord_sq;
    out.keep = out.half_chord_sq >= 0.0 && !beyond_slab;
    return out;
}

// `cychosz`: the sphere chord and the slab.
fn tc_cychosz_keeps(b: TcBounds, q: vec3<f32>, dh: vec3<f32>) -> bool {
    return tc_sphere_slab(b, q, dh).keep;
}
