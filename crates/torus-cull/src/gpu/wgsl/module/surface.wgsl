// ---------------------------------------------------------------------------------------
// Rays from a surface point (src/certified/surface_cubic.rs; docs/math.md §9, "The
// certified cubic"): the cubic g(v) = (Q(u₀ + v) − Q(u₀))/v left once the origin's own
// root u₀ is divided out. The host forms g's coefficients in f64 from the origin moved onto
// the surface and rounds them to f32 with bounds on their distance from the true ones
// (torus_cull::gpu::ModuleTorus::prepare, the TorusSurfaceRay); the proof that g keeps its
// sign, or changes it once, runs here in f32. Every rounding term of the CPU's proof is
// multiplied by TC_G, as in the certificate, and each bound gains TC_FLUSH_FLOOR for
// flushed subnormals. Where the cubic proves nothing, the literal certificate finishes the
// ray past a start the host or the cubic proved clear, as on the CPU (src/certified/mod.rs).
//
// mirrors: tc_surface_inflate -> none (crate::certified::surface_cubic's INFLATE, times G)
// mirrors: tc_surface_value -> crate::certified::surface_cubic::Cubic32::value
// mirrors: tc_surface_at -> crate::certified::surface_cubic::Cubic32::at
// mirrors: tc_surface_below -> crate::certified::surface_cubic::Cubic32::below
// mirrors: tc_surface_critical -> crate::certified::surface_cubic::Cubic32::critical
// mirrors: tc_surface_tangents -> crate::certified::surface_cubic::tangents
// mirrors: tc_surface_piece -> crate::certified::surface_cubic::Cubic32::piece
// mirrors: tc_surface_positive -> crate::certified::surface_cubic::Cubic32::positive
// mirrors: tc_surface_bisect -> crate::certified::surface_cubic::Cubic32::bisect
// mirrors: tc_surface_first_root -> crate::certified::surface_cubic::Cubic32::first_root
// mirrors: tc_from -> none (torus_trace over the ray's range from a later start)
// mirrors: tc_surface_decide -> crate::certified::surface_cubic::Prepared::decide
// mirrors: torus_intersect_from_surface -> crate::certified::prove

// A ray from a surface point as the host prepared it (64 bytes, four vec4<f32>;
// ModuleTorus::prepare): `coeffs` (a3, a2, a1, s) with s = ±1 the sign of a1 (the side the
// ray leaves into: + outside); `errors` (e3, e2, e1, u₀), each eᵢ a bound on the true
// coefficient's distance from its f32; `range` (α, v_max rounded up, v_max rounded down,
// R/|d| rounded to f32), v in units of R along the ray from the surface point; `start`
// (w_lo, w_hi: the band holding g's inflection point; the ray's own t_min (the TorusRay's
// t_min is the literal start past the origin's root, t*); what the record holds: 0
// nothing (a literal ray), 1 the cubic, 2 the cubic and the literal start).
struct TorusSurfaceRay {
    coeffs: vec4<f32>,
    errors: vec4<f32>,
    range: vec4<f32>,
    start: vec4<f32>,
};

struct TcSurfaceCubic {
    a3: f32,
    a2: f32,
    a1: f32,
    e3: f32,
    e2: f32,
    e1: f32,
    s: f32,
    w_lo: f32,
    w_hi: f32,
};

// Bounds at one point v ≥ 0 of f = s·g: a lower bound of f, and bounds of f′.
struct TcSurfaceAt {
    f_lo: f32,
    slope_lo: f32,
    slope_hi: f32,
};

// 1 + 16·G·u: inflates a bound formed in f32 past its own roundings.
fn tc_surface_inflate() -> f32 {
    return 1.0 + TC_G * 16.0 * TC_U;
}

// s·g̃(v) and a bound on its distance from s·g(v): Horner's rounding (γ₆·Σ|ãᵢ|vⁱ, times
// G) plus the coefficients' own bounds.
fn tc_surface_value(c: TcSurfaceCubic, v: f32) -> vec2<f32> {
    let g = ((v + c.a3) * v + c.a2) * v + c.a1;
    let size = ((v + abs(c.a3)) * v + abs(c.a2)) * v + abs(c.a1);
    let err = (size * (TC_G * 8.0 * TC_U) + (c.e3 * v + c.e2) * v + c.e1) * tc_surface_inflate()
        + 8.0 * TC_FLUSH_FLOOR;
    return vec2<f32>(c.s * g, err);
}

fn tc_surface_at(c: TcSurfaceCubic, v: f32) -> TcSurfaceAt {
    let value = tc_surface_value(c, v);
    let slope = (3.0 * v + 2.0 * c.a3) * v + c.a2;
    let size = (3.0 * v + 2.0 * abs(c.a3)) * v + abs(c.a2);
    let slope_err = (size * (TC_G * 8.0 * TC_U) + 2.0 * c.e3 * v + c.e2) * tc_surface_inflate()
        + 8.0 * TC_FLUSH_FLOOR;
    let s_slope = c.s * slope;
    return TcSurfaceAt(value.x - value.y, s_slope - slope_err, s_slope + slope_err);
}

// Proved: s·g(v) < 0.
fn tc_surface_below(c: TcSurfaceCubic, v: f32) -> bool {
    let value = tc_surface_value(c, v);
    return value.x + value.y < 0.0;
}

// The critical points of g̃ (roots of 3v² + 2a3·v + a2), ascending; (−1, −1) where there
// are fewer than two (no point of the range is negative). Approximate: any point is sound
// where one is used.
fn tc_surface_critical(c: TcSurfaceCubic) -> vec2<f32> {
    let disc = c.a3 * c.a3 - 3.0 * c.a2;
    if (!(disc > 0.0) || !tc_finite(disc)) {
        return vec2<f32>(-1.0);
    }
    let q = -(c.a3 + select(-sqrt(disc), sqrt(disc), c.a3 >= 0.0));
    let x = q / 3.0;
    let y = select(0.0, c.a2 / select(1.0, q, q != 0.0), q != 0.0);
    return vec2<f32>(min(x, y), max(x, y));
}

// Proved: f > 0 on the convex piece [alpha, beta] from bounds at its ends (the tangents
// at both ends lie below f, and their zeros do not overlap).
fn tc_surface_tangents(alpha: f32, beta: f32, at_a: TcSurfaceAt, at_b: TcSurfaceAt) -> bool {
    let both = at_a.f_lo > 0.0 && at_b.f_lo > 0.0;
    let sa = at_a.slope_lo;
    let sb = at_b.slope_hi;
    let lhs = at_a.f_lo * sb + at_b.f_lo * (-sa);
    let rhs = (-sa) * sb * (beta - alpha) * tc_surface_inflate();
    return both && (sa >= 0.0 || sb <= 0.0 || lhs > rhs);
}

// Proved: f > 0 on [a, b], a piece where f is convex (`convex`) or concave; a convex one
// the tangents do not prove is split at g̃'s critical point inside it (f's lowest point).
fn tc_surface_piece(c: TcSurfaceCubic, a: f32, b: f32, at_a: TcSurfaceAt, convex: bool) -> bool {
    let at_b = tc_surface_at(c, b);
    if (!(at_a.f_lo > 0.0 && at_b.f_lo > 0.0)) {
        return false;
    }
    if (!convex || tc_surface_tangents(a, b, at_a, at_b)) {
        return true;
    }
    let crit = tc_surface_critical(c);
    for (var k = 0; k < 2; k++) {
        let m = select(crit.y, crit.x, k == 0);
        if (m > a && m < b) {
            let at_m = tc_surface_at(c, m);
            return tc_surface_tangents(a, m, at_a, at_m) && tc_surface_tangents(m, b, at_m, at_b);
        }
    }
    return false;
}

// Proved: f = s·g > 0 on [x, y] (0 ≤ x ≤ y, finite): concave and convex pieces either side
// of the band [w_lo, w_hi] that holds g's inflection point, and the band by its chord's sag.
fn tc_surface_positive(c: TcSurfaceCubic, x: f32, y: f32) -> bool {
    let at_x = tc_surface_at(c, x);
    let at_y = tc_surface_at(c, y);
    if (!(at_x.f_lo > 0.0 && at_y.f_lo > 0.0)) {
        return false;
    }
    let lo = c.w_lo;
    let hi = c.w_hi;
    // s·g is convex right of w_hi for s > 0, left of w_lo for s < 0.
    if (x <= lo) {
        if (!tc_surface_piece(c, x, min(y, lo), at_x, c.s < 0.0)) {
            return false;
        }
    }
    let a = max(x, lo);
    let b = min(y, hi);
    if (a <= b) {
        let fa = tc_surface_at(c, a).f_lo;
        let fb = tc_surface_at(c, b).f_lo;
        let span = b - a;
        let sag = (hi - lo) * span * span * tc_surface_inflate();
        if (!(fa > 0.0 && fb > 0.0 && min(fa, fb) > sag)) {
            return false;
        }
    }
    if (y >= hi) {
        let right_start = max(x, hi);
        if (!tc_surface_piece(c, right_start, y, tc_surface_at(c, right_start), c.s > 0.0)) {
            return false;
        }
    }
    return true;
}

// The sign change of s·g̃ in (x, y] (positive at x, not at y): safeguarded Newton inside
// the shrinking bracket; the bracket's right end.
fn tc_surface_bisect(c: TcSurfaceCubic, x0: f32, y0: f32) -> f32 {
    var x = x0;
    var y = y0;
    var v = y0;
    for (var k = 0; k < 60; k++) {
        let sg = tc_surface_value(c, v).x;
        if (sg > 0.0) {
            x = v;
        } else {
            y = v;
        }
        let slope = c.s * ((3.0 * v + 2.0 * c.a3) * v + c.a2);
        let newton = v - sg / select(1.0, slope, slope != 0.0);
        let inside = slope != 0.0 && newton > x && newton < y;
        let next = select(0.5 * (x + y), newton, inside);
        if (next == v || !(next > x && next < y)) {
            break;
        }
        v = next;
    }
    return y;
}

// The smallest v in (x, y] where s·g̃ stops being positive, by pieces between g̃'s critical
// points; −1 where there is none.
fn tc_surface_first_root(c: TcSurfaceCubic, x: f32, y: f32) -> f32 {
    let crit = tc_surface_critical(c);
    var piece_start = x;
    for (var k = 0; k < 3; k++) {
        var piece_end = y;
        if (k < 2) {
            piece_end = select(crit.y, crit.x, k == 0);
        }
        if (piece_end > piece_start && piece_end <= y) {
            if (tc_surface_value(c, piece_end).x <= 0.0) {
                return tc_surface_bisect(c, piece_start, piece_end);
            }
            piece_start = piece_end;
        }
    }
    return -1.0;
}

// The ray's range from `from` on (the ray as prepared, its t_min raised to `from`).
fn tc_from(ray: TorusRay, t_start: f32) -> TorusRay {
    return TorusRay(ray.origin, max(ray.t_min, t_start), ray.direction, ray.t_max);
}

// The cubic's verdict on a ray from a surface point: TORUS_HIT (t, and the outward normal
// at the point), TORUS_MISS, or TORUS_ESCALATE with `why` = 0 and t the start past which
// the literal certificate may go on (the stretch before it proved clear of any root but
// the origin's), or −1 where there is none.
fn tc_surface_decide(ray: TorusRay, surf: TorusSurfaceRay, torus: TorusParams) -> TorusHit {
    // Fields in TcSurfaceCubic's order: a3, a2, a1, e3, e2, e1, s, w_lo, w_hi.
    let k = surf.coeffs;
    let e = surf.errors;
    let c = TcSurfaceCubic(k.x, k.y, k.z, e.x, e.y, e.z, k.w, surf.start.x, surf.start.y);
    let alpha = surf.range.x;
    let hi_up = surf.range.y;
    let hi_dn = surf.range.z;
    let t_per_v = surf.range.w;
    // t = v·(R/|d|): the f32 R/|d| and the product are each within u of the true value.
    let t_rel = TC_G * 4.0 * TC_U;
    let no_start = TorusHit(-1.0, vec3<f32>(0.0), TORUS_ESCALATE, 0u);
    let first = tc_surface_first_root(c, alpha, hi_up);
    if (first < 0.0) {
        if (tc_surface_positive(c, alpha, hi_up)) {
            return tc_miss();
        }
    } else {
        // The reported point is within t_rel·v·R of the one at v̂: the bracket shrinks by
        // as much, within the promised 2·10⁻⁴·(R + r).
        let rr = torus.rot_z.w;
        let bracket = min(TC_BRACKET, 1.99e-4 * (1.0 + rr) - 2.0 * t_rel * (first + 1.0));
        let left = max(first - bracket, alpha);
        let right = min(first + bracket, hi_dn);
        let sign_change = bracket > 1e-6 && right > left && tc_surface_below(c, right)
            && tc_surface_positive(c, alpha, left);
        let t = clamp(first * t_per_v, ray.t_min, ray.t_max);
        if (sign_change && tc_finite(t)) {
            // The outward normal at the point: ∇F ∝ (|p|² + 1 − rr²)·p − 2(px, 0, pz).
            let rot = mat3x3<f32>(torus.rot_x.xyz, torus.rot_y.xyz, torus.rot_z.xyz);
            let p = ((ray.origin + t * ray.direction) * rot) * torus.scale.x;
            let wgt = dot(p, p) + 1.0 - rr * rr;
            let g = vec3<f32>(wgt * p.x - 2.0 * p.x, wgt * p.y, wgt * p.z - 2.0 * p.z);
            let n_world = rot * g;
            let n_len = length(n_world);
            return TorusHit(t, n_world / select(1.0, n_len, n_len > 0.0), TORUS_HIT, 0u);
        }
    }
    // A far crossing the cubic cannot resolve: the stretch halfway to it proved clear,
    // for the literal certificate to go on from, only for a ray that leaves into the
    // outside. t_mid is at most t(mid) and at least t(α).
    var toward = hi_up;
    if (first >= 0.0) {
        toward = first;
    }
    let mid = 0.5 * (alpha + toward);
    let t_mid = mid * t_per_v * (1.0 - 4.0 * t_rel);
    let t_alpha = alpha * t_per_v * (1.0 + 4.0 * t_rel);
    let clear = c.s > 0.0 && mid > alpha && t_mid >= t_alpha && t_mid >= 0.0 && tc_finite(t_mid)
        && tc_surface_positive(c, alpha, mid);
    if (clear) {
        return TorusHit(t_mid, vec3<f32>(0.0), TORUS_ESCALATE, 0u);
    }
    return no_start;
}

// The certified intersection of a ray from a surface point (torus_cull::Ray::from_surface)
// with `torus` behind the cull `cull`, its origin's own root left out: `surf` is its
// TorusSurfaceRay (ModuleTorus::prepare). The cubic first, over the ray's own range; where
// it proves nothing, the literal ray from the stretch it proved clear, then `ray` itself
// (the literal ray from the host's start t*); what none of them proves escalates with
// TORUS_WHY_ON_SURFACE. A record that holds nothing (0) is a literal ray: torus_intersect's
// answer.
fn torus_intersect_from_surface(
    ray: TorusRay,
    surf: TorusSurfaceRay,
    torus: TorusParams,
    cull: u32,
) -> TorusHit {
    let holds = surf.start.w;
    if (holds != 1.0 && holds != 2.0) {
        return torus_trace(ray, torus, cull, false);
    }
    let own = TorusRay(ray.origin, surf.start.z, ray.direction, ray.t_max);
    let cubic = tc_surface_decide(own, surf, torus);
    if (cubic.code != TORUS_ESCALATE) {
        return cubic;
    }
    if (cubic.t >= 0.0) {
        let literal = torus_trace(tc_from(own, cubic.t), torus, cull, false);
        if (literal.code != TORUS_ESCALATE) {
            return literal;
        }
    }
    if (holds == 2.0) {
        let literal = torus_trace(ray, torus, cull, false);
        if (literal.code != TORUS_ESCALATE) {
            return literal;
        }
    }
    return tc_escalate(TORUS_WHY_ON_SURFACE);
}
