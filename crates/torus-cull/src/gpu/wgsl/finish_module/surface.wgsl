// ---------------------------------------------------------------------------------------
// A ray from a surface point (intersect/from_surface.rs): the origin's own root divided
// out of the quartic, the nearest root of the cubic left, past it.
//
// mirrors: tc_cubic_g64 -> crate::intersect::from_surface::cubic
// mirrors: tc_cubic_rounding64 -> crate::intersect::from_surface::rounding
// mirrors: tc_bracketed_root64 -> crate::intersect::from_surface::bracketed_root
// mirrors: tc_nearest_cubic_root64 -> crate::intersect::from_surface::nearest_cubic_root
// mirrors: tc_starts_on_the_surface64 -> crate::intersect::from_surface::starts_on_the_surface
// mirrors: tc_nearest_surface_point64 -> crate::geometry::tube::Tube::nearest_surface_point

// g(v) = v³ + a v² + b v + c and g′(v).
fn tc_cubic_g64(a: f64, b: f64, c: f64, v: f64) -> vec2<f64> {
    return vec2<f64>(((v + a) * v + b) * v + c, (3.0 * v + 2.0 * a) * v + b);
}

// A bound on g's rounding at v.
fn tc_cubic_rounding64(a: f64, b: f64, c: f64, v: f64) -> f64 {
    let x = abs(v);
    return TC_FIN_EIGHT_EPS * (((x + abs(a)) * x + abs(b)) * x + abs(c));
}

// The root of g in [x, y], where g is monotone and changes sign (gx of the sign of g(x)):
// Newton inside the shrinking bracket, bisection where a step would leave it.
fn tc_bracketed_root64(a: f64, b: f64, c: f64, x0: f64, y0: f64, gx: f64) -> f64 {
    let rising = gx < 0.0;
    var x = x0;
    var y = y0;
    var v = 0.5 * (x + y);
    for (var i = 0; i < 200; i++) {
        let g = tc_cubic_g64(a, b, c, v);
        if (g.x == 0.0) {
            return v;
        }
        if ((g.x < 0.0) == rising) {
            x = v;
        } else {
            y = v;
        }
        var next = 0.5 * (x + y);
        if (g.y != 0.0) {
            let newton = v - g.x / g.y;
            if (newton > x && newton < y) {
                next = newton;
            }
        }
        if (abs(next - v) <= TC_FIN_TWO_EPS * abs(next) || y - x <= TC_FIN_TWO_EPS * max(abs(y), abs(x))) {
            return next;
        }
        v = next;
    }
    return v;
}

struct TcCubicRoot64 {
    v: f64,
    found: bool,
};

// The smallest root of g in (lo, hi] (in [lo, hi] for lo > 0) by monotone pieces
// between the critical points (from_surface.rs, nearest_cubic_root).
fn tc_nearest_cubic_root64(a: f64, b: f64, c: f64, lo: f64, hi_in: f64) -> TcCubicRoot64 {
    let none = TcCubicRoot64(0.0, false);
    if (!(lo <= hi_in)) {
        return none;
    }
    let bound = 1.0 + max(abs(a), max(abs(b), abs(c)));
    let hi = min(hi_in, bound);
    if (lo > hi) {
        return none;
    }
    var ends = array<f64, 4>(lo, hi, hi, hi);
    var n = 1;
    // The critical points (roots of 3v² + 2av + b), ascending, without cancellation.
    let disc = a * a - 3.0 * b;
    if (disc > 0.0) {
        let q = -(a + tc_copysign64(sqrt(disc), a));
        let x = q / 3.0;
        var y = 0.0lf;
        if (q != 0.0) {
            y = b / q;
        }
        let first = min(x, y);
        let second = max(x, y);
        if (first > lo && first < hi) {
            ends[n] = first;
            n++;
        }
        if (second > lo && second < hi) {
            ends[n] = second;
            n++;
        }
    }
    ends[n] = hi;
    let open = lo == 0.0;
    var x = lo;
    var gx = tc_cubic_g64(a, b, c, lo).x;
    if (gx == 0.0 && !open) {
        return TcCubicRoot64(lo, true);
    }
    for (var k = 1; k <= n; k++) {
        let y = ends[k];
        let gy = tc_cubic_g64(a, b, c, y).x;
        if ((gx < 0.0 && gy > 0.0) || (gx > 0.0 && gy < 0.0)) {
            return TcCubicRoot64(tc_bracketed_root64(a, b, c, x, y, gx), true);
        }
        let at_end = y == hi;
        if (gy == 0.0 || (!at_end && abs(gy) <= tc_cubic_rounding64(a, b, c, y))) {
            return TcCubicRoot64(y, true);
        }
        x = y;
        gx = gy;
    }
    return none;
}

// The origin at u₀ is on the surface within TC_FIN_OWN_ROOT_REACH (in units of R;
// from_surface.rs, starts_on_the_surface; √(a² + b²) for the CPU's hypot).
fn tc_starts_on_the_surface64(o: vec3<f64>, inv_major: f64, minor_rel: f64) -> bool {
    let x = o * inv_major;
    let rho = sqrt(x.x * x.x + x.z * x.z);
    let off = abs(sqrt((rho - 1.0) * (rho - 1.0) + x.y * x.y) - minor_rel);
    return off <= TC_FIN_OWN_ROOT_REACH;
}

// The surface point nearest to o (torus frame): the core circle's nearest point, then r
// along the way to o (tube.rs, Tube::nearest_surface_point); o itself on the axis or the
// core circle, or where the result is not finite.
fn tc_nearest_surface_point64(o: vec3<f64>, major: f64, minor: f64) -> vec3<f64> {
    let rho = sqrt(o.x * o.x + o.z * o.z);
    if (!(rho > 0.0)) {
        return o;
    }
    let core = vec3<f64>(o.x, 0.0, o.z) * (major / rho);
    let off = o - core;
    let len = sqrt(tc_dot64(off, off));
    if (!(len > 0.0)) {
        return o;
    }
    return core + off * (minor / len);
}

