// The device's f64 finish as WGSL functions (src/gpu/finish.rs, source.rs's
// wgsl_finish_module): the CPU's f64 method for one ray the certified f32 module
// escalated, on an adapter with SHADER_F64, step for step:
//   src/intersect/{mod,nearest_hit,reduce}.rs   the line in the torus frame (f64), the
//                                               foot point scaled by 1/R, the chord test,
//                                               the depressed quartic's coefficients, t
//                                               and the normal;
//   src/quartic/nearest.rs                      surely_no_real_root, the even quartic,
//                                               Ferrari's split, the clear factors and
//                                               the near-double cold path;
//   src/quartic/{even,resolvent,trisect,factor}.rs;
//   src/intersect/from_surface.rs               a ray from a surface point: its origin's
//                                               own root divided out, the cubic's nearest
//                                               root past it.
// Every threshold comes from the generated header (TC_FIN_*), written from the Rust
// constants the CPU uses. Where the method cannot give the CPU's answer (a value it does
// not hold finite), it hands the ray back to the host: status TORUS_F64_STATUS_HOST.
//
// No bindings and no entry point: a renderer includes this text (with or without the f32
// module, in either order: the two declare no common name), and the library's own f64
// pass is this text plus finish.wgsl (its bindings and entry point). The API:
//   torus_finish_wanted(instruction, code, t, normal) -> bool
//   torus_finish_f64(ray: TorusWorldRay, torus: TorusParams64, instruction) -> TorusHit64
// Every other global name begins with tc_, Tc or TC_.
//
// mirrors: tc_dot64 -> none
// mirrors: tc_copysign64 -> none
// mirrors: tc_finite64 -> none
// mirrors: tc_in_range64 -> crate::quartic::pick::in_range_f64

// The ray as the caller gave it, in world space (32 bytes, as the f32 module's
// TorusRay): origin, t_min, direction, t_max as f32, widened exactly; the range clipped
// to |t| ≤ (|o − c| + 4(R + r))/|d| (ModuleTorus::prepare_f64), beyond which no root
// lies, so no answer changes and no infinity reaches the device.
struct TorusWorldRay {
    origin: vec3<f32>,
    t_min: f32,
    direction: vec3<f32>,
    t_max: f32,
};

// The torus in f64 (136 bytes, 17 f64, ModuleTorus::params64): the centre, the columns
// of the world → torus rotation M, R, 1/R, r/R, 1 − (r/R)², 1 + r/R (the CPU's Tube).
struct TorusParams64 {
    center_x: f64,
    center_y: f64,
    center_z: f64,
    col0_x: f64,
    col0_y: f64,
    col0_z: f64,
    col1_x: f64,
    col1_y: f64,
    col1_z: f64,
    col2_x: f64,
    col2_y: f64,
    col2_z: f64,
    major: f64,
    inv_major: f64,
    minor_rel: f64,
    k_normal: f64,
    outer: f64,
};

// The f64 answer, each value rounded once from f64 as the CPU's Hit is: t along the
// world ray (in units of its direction), the unit world normal, the point o + t·d, and
// status: TORUS_F64_STATUS_FRONT (a hit from the outside, d·n < 0), _BACK (from the
// inside, or exactly tangent), _MISS (no hit in range), _HOST (handed back: finish it
// on the host with the f64 path).
struct TorusHit64 {
    t: f32,
    normal: vec3<f32>,
    point: vec3<f32>,
    status: u32,
};

// (x·x′ + y·y′) + z·z′, glam's order.
fn tc_dot64(a: vec3<f64>, b: vec3<f64>) -> f64 {
    return (a.x * b.x + a.y * b.y) + a.z * b.z;
}

fn tc_copysign64(x: f64, s: f64) -> f64 {
    return select(abs(x), -abs(x), s < 0.0);
}

fn tc_finite64(x: f64) -> bool {
    return abs(x) < TC_FIN_HUGE;
}

// x if it is a real root in [lo, hi], else TC_FIN_NONE (pick.rs, in_range).
fn tc_in_range64(x: f64, real: bool, lo: f64, hi: f64) -> f64 {
    return select(TC_FIN_NONE, x, real && x >= lo && x <= hi);
}

