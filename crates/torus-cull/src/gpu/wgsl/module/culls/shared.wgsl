// ---------------------------------------------------------------------------------------
// The culls (src/cull/*.rs): the CPU's math on the kernel's line, q (the foot point, in
// units of R) and dh (a unit direction), against the torus R = 1, r = rr padded by the
// GPU's margin η_gpu = SAFETY_REL·(1 + rr) + E (the bounds in Params, made by the host:
// src/gpu/bounds.rs). E bounds the kernel's line error on every line that meets the
// torus, so the computed line meets the torus padded by E; what is left of the margin,
// SAFETY_REL·(1 + rr) = 4096u·(1 + rr), absorbs each cull's own f32 evaluation as on the
// CPU (docs/math.md, "The GPU's culls"): the kernel's line is a foot point with |q| ≲ 2
// and a unit direction, so every rounding acts like moving the line (or a radius) by a
// few G·u·(1 + rr), far below. Two culls compare values whose margin is not of that
// size, and carry an explicit error bound instead: `quadric` (H's margin is only
// (R − r)·η) and `discriminant` (Δ has no margin at a tangent: a running error bound).
// `thick_cylinder`'s hole test bounds its ρ² the same way (margin 2(R − r)·η).
// WGSL may assume no infinities or NaNs: every division below has a divisor bounded
// away from 0, where the CPU's divides by 0 and lets ±∞ decide.
//
// The culls' shared parts: the running error bound (TcEv) and the point error. The bounds
// the host packs into TorusParams, TcBounds and tc_bounds_of, are generated from the
// table of per-torus constants (src/geometry/bounds.rs; src/gpu/bounds.rs writes them).
// Each cull is its own file, culls/<name>.wgsl, with `fn tc_<name>_keeps(b: TcBounds, q: vec3<f32>, dh: vec3<f32>) -> bool`;
// the dispatch `tc_cull_keeps` is generated from the table of culls (src/gpu/source.rs).
//
// mirrors: tc_ev_exact -> none (the GPU culls' running error bound)
// mirrors: tc_ev_round -> none
// mirrors: tc_ev_add -> none
// mirrors: tc_ev_sub -> none
// mirrors: tc_ev_mul -> none
// mirrors: tc_ev_scale -> none
// mirrors: tc_ev_positive -> none
// mirrors: tc_ev_maybe_nonnegative -> none
// mirrors: tc_point_error -> none (the GPU's point error)

// A value and a bound on its distance from the exact value of the same expression on
// exact inputs: |v − exact| ≤ e. Each operation adds its own rounding, G·u·|result|
// (+, −, × are correctly rounded in WGSL, G = 4 leaves room), plus FLUSH_FLOOR for a flushed
// subnormal; a product adds |a|e_b + |b|e_a + e_a·e_b, which is exact, not first
// order. The bounds are themselves rounded (down by at most ~1 + 200u over a cull):
// `ev_certain` widens them by 2⁻¹⁰ before a sign is read.
struct TcEv {
    v: f32,
    e: f32,
};

fn tc_ev_exact(v: f32) -> TcEv {
    return TcEv(v, 0.0);
}

fn tc_ev_round(v: f32) -> f32 {
    return TC_G * TC_U * abs(v) + TC_FLUSH_FLOOR;
}

fn tc_ev_add(a: TcEv, b: TcEv) -> TcEv {
    let s = a.v + b.v;
    return TcEv(s, a.e + b.e + tc_ev_round(s));
}

fn tc_ev_sub(a: TcEv, b: TcEv) -> TcEv {
    let s = a.v - b.v;
    return TcEv(s, a.e + b.e + tc_ev_round(s));
}

fn tc_ev_mul(a: TcEv, b: TcEv) -> TcEv {
    let p = a.v * b.v;
    return TcEv(p, abs(a.v) * b.e + abs(b.v) * a.e + a.e * b.e + tc_ev_round(p));
}

// k·a for a small integer or power of two k (exact in f32).
fn tc_ev_scale(k: f32, a: TcEv) -> TcEv {
    let p = k * a.v;
    return TcEv(p, abs(k) * a.e + tc_ev_round(p));
}

// The exact value is > 0.
fn tc_ev_positive(a: TcEv) -> bool {
    return a.v > a.e * (1.0 + 0.0009765625);
}

// The exact value may be ≥ 0 (not proved < 0).
fn tc_ev_maybe_nonnegative(a: TcEv) -> bool {
    return a.v >= -a.e * (1.0 + 0.0009765625);
}

// How far the computed point q + τ·d (each component one product and one sum, fused or
// not) can stand from the exact one, in each coordinate.
fn tc_point_error(q: vec3<f32>, d: vec3<f32>, tau: f32) -> f32 {
    return TC_G * 2.0 * TC_U * (length(q) + length(d) * abs(tau)) * 1.01 + TC_FLUSH_FLOOR;
}
