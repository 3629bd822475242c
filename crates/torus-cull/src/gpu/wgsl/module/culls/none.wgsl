// ---------------------------------------------------------------------------------------
// `none` (src/cull/none.rs): no test, every line is kept.
//
// mirrors: tc_none_keeps -> crate::cull::none::NoCull::keeps_lanes

fn tc_none_keeps(b: TcBounds, q: vec3<f32>, dh: vec3<f32>) -> bool {
    return true;
}
