// ---------------------------------------------------------------------------------------
// mirrors: tc_ellipsoid_slab -> crate::cull::ellipsoid::ellipsoid_slab
// mirrors: tc_ellipsoid_keeps -> crate::cull::ellipsoid::EllipsoidCull::keeps_lanes

struct TcEllipsoidChord {
    foot: vec3<f32>,
    dir: vec3<f32>,
    inv_len_sq: f32,
    half_chord_sq: f32,
    keep: bool,
};

// `ellipsoid` (src/cull/ellipsoid.rs): y scaled by s turns the outer ellipsoid into the
// sphere R + r_η; Cychosz's chord and slab |y′| ≤ s·r_η on the scaled line.
fn tc_ellipsoid_slab(b: TcBounds, q: vec3<f32>, d: vec3<f32>) -> TcEllipsoidChord {
    var out: TcEllipsoidChord;
    out.dir = vec3<f32>(d.x, b.y_scale * d.y, d.z);
    let o = vec3<f32>(q.x, b.y_scale * q.y, q.z);
    out.inv_len_sq = 1.0 / dot(out.dir, out.dir);
    out.foot = o - out.dir * (dot(o, out.dir) * out.inv_len_sq);
    out.half_chord_sq = b.outer_sq - dot(out.foot, out.foot);
    let unit_y_sq = out.dir.y * out.dir.y * out.inv_len_sq;
    let above = abs(out.foot.y) - b.slab;
    let beyond_slab = above > 0.0 && above * above > unit_y_sq * out.half_chord_sq;
    out.keep = out.half_chord_sq >= 0.0 && !beyond_slab;
    return out;
}

// `ellipsoid`: the scaled line's chord and slab.
fn tc_ellipsoid_keeps(b: TcBounds, q: vec3<f32>, dh: vec3<f32>) -> bool {
    return tc_ellipsoid_slab(b, q, dh).keep;
}
