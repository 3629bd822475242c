// torus-cull's WGSL module: the certified f32 ray–torus intersection as functions a shader
// includes (torus_cull::gpu::wgsl_module() gives this text behind its generated `const`
// header; the library's own compute kernel is the same text plus its bindings and entry
// point, src/gpu/wgsl/kernel.wgsl).
//
// Per ray: the world → torus-frame rotation (f32; the host has subtracted the centre, one
// rounding as in f32, and moved a far origin along its line to the foot point in f64), the
// line re-parameterised at its foot point and scaled by 1/R, the cull, Ferrari's split of
// the depressed quartic in f32 (the f64 solver's method, as src/quartic/lanes runs it on
// f32 lanes), then the certificate of src/certified/certificate.rs with the GPU's error
// bounds: every spec term in u = 2⁻²⁴ is multiplied by 4 (WGSL may or may not contract
// a·b + c into an fma, division is good to 2.5 ulp, sqrt is not correctly rounded
// everywhere), and the line's own error is the one of an f32 rotation, which grows with
// the origin's distance |o − c|. What is not proved comes back TORUS_ESCALATE, and the
// host finishes it with the f64 solver (torus_cull::intersect).
//
// Every shared number (TC_U, TC_G, TC_SAFETY_REL, the solver's thresholds and fits, the
// line error's constants, the result, cull and escalation codes) is a `const` of the
// header that src/gpu/source.rs generates from the Rust constants the CPU uses: none is
// written here.
//
// NAMES. Every global name the module declares begins with torus_ / Torus / TORUS_ (the
// API below) or tc_ / Tc / TC_ (internals), so that it can sit in a renderer's shader
// beside names like `miss`, `Line` or `U` (WGSL has no namespaces, and a repeated global
// name is an error).
//
// THE PUBLIC ENTRY POINTS (everything else here is internal):
//
//   fn torus_intersect(ray: TorusRay, torus: TorusParams, cull: u32) -> TorusHit
//   fn torus_intersect_from_surface(ray: TorusRay, surf: TorusSurfaceRay,
//                                   torus: TorusParams, cull: u32) -> TorusHit
//   fn torus_cull_keeps(ray: TorusRay, torus: TorusParams, cull: u32) -> bool
//
// `cull` is one of TORUS_CULL_NONE, _SPHERE, _AABB, _CYCHOSZ, _THICK_CYLINDER, _SKALA,
// _ELLIPSOID, _QUADRIC, _DISCRIMINANT (torus_cull::gpu::GpuCull::ALL's order); every
// cull is conservative here: a rejected ray is a proved miss.
//
// WHAT THE CALLER PREPARES (on the host, as torus_cull::gpu::ModuleTorus does):
//   - TorusParams, once per torus: ModuleTorus::params() (112 bytes, seven vec4<f32>).
//     The culls' bounds rows carry the GPU's margin (the CPU's η plus this module's line
//     error), computed in Rust: do not derive them in the shader.
//   - TorusRay, per ray: ModuleTorus::prepare(ray). The origin relative to the torus
//     centre, o − c formed in f64 and rounded once to f32; an origin farther than
//     2·(R + r) moved along its line to the foot point in f64 (the range shifted by the
//     same t0, clipped to where the bounding sphere can be; add t0 back to the hit's t);
//     an origin beyond 2²⁰·R is not sent (escalate it); a ray from a surface point
//     (torus_cull::Ray::from_surface) sent as its literal ray past the origin's own root,
//     or answered on the host (see ModuleTorus::prepare). A ray prepared otherwise is
//     outside what the certificate proves.
//   - TorusSurfaceRay, per ray, for torus_intersect_from_surface: ModuleTorus::prepare(ray)
//     .surface (64 bytes; surface.wgsl): a ray from a surface point's cubic, its origin's
//     root divided out in f64, which proves the grazing rays and the re-hits near the
//     origin that the literal ray cannot; all zeros for a literal ray. Decode its answers
//     through PreparedRay::from_surface().
//
// WHAT THE ANSWER MEANS: TorusHit.code
//   TORUS_HIT: a proved hit; t (along the prepared ray's direction, from the prepared
//     origin) is within 2·10⁻⁴·(R + r)·|d|⁻¹ of the first root in [t_min, t_max], normal
//     the unit outward world normal;
//   TORUS_MISS: a proved miss (or the cull's proved rejection);
//   TORUS_ESCALATE: not proved either way; `why` says which step did not go through
//     (TORUS_WHY_*, torus_cull::gpu::Escalation). Finish it on the host with the f64 path
//     (torus_cull::intersect), or treat it as unknown: it is never a miss to assume.
//
// mirrors: tc_finite -> none (WGSL only: WGSL may assume every value finite)

// A ray as the module reads it (32 bytes, two vec4<f32> in a storage buffer): the origin
// relative to the torus centre, the range's start, the direction (any length, finite,
// non-zero), the range's end; both ends finite.
struct TorusRay {
    origin: vec3<f32>,
    t_min: f32,
    direction: vec3<f32>,
    t_max: f32,
};

// A torus as the module reads it (112 bytes, seven vec4<f32>; a uniform or storage
// struct): rows of the world → torus rotation M (torus.to_local_rotation()) with, in w,
// R, r and r/R; 1/R (yzw unused); the culls' bounds at R = 1 with the tube padded by the
// GPU's margin (src/gpu/bounds.rs): (R + r_η, (R + r_η)², r_η, r_η²), ((R − r_η)², s,
// s·r_η, the hyperboloid's y coefficient), ((r_η/R)², R − r_η, η_gpu, 0).
struct TorusParams {
    rot_x: vec4<f32>,
    rot_y: vec4<f32>,
    rot_z: vec4<f32>,
    scale: vec4<f32>,
    bounds_a: vec4<f32>,
    bounds_b: vec4<f32>,
    bounds_c: vec4<f32>,
};

// The answer: `code` is TORUS_MISS, TORUS_HIT or TORUS_ESCALATE (TORUS_KEPT from the
// cull alone); for a hit, `t` and the unit world `normal`; for an escalation, `why`
// (TORUS_WHY_*), else 0.
struct TorusHit {
    t: f32,
    normal: vec3<f32>,
    code: u32,
    why: u32,
};

fn tc_finite(x: f32) -> bool {
    return abs(x) < TC_BIG;
}

