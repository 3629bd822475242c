#!/usr/bin/env python3
"""Derives the reference roots of the quartic corpus in `cases.rs`, exactly.

Each case is given by its nominal roots (or coefficients); its coefficients are computed
exactly (rational arithmetic) and rounded to f64, as a test program stores them. The
reference roots are then those of the *stored* f64 polynomial, not the nominal ones:
isolated with Sturm sequences and bisected in exact rational arithmetic (Python's
`fractions`), so nothing here rounds but the final conversion of each root to f64. The
same is done for the depressed monic form `x⁴ + p x² + q x + r` (shift `c3/(4c4)`),
computed exactly from the stored coefficients and rounded to f64, where it is finite.

Each real root comes with its multiplicity and its relative condition number
`κ = Σ|cᵢ||x|ⁱ / (|x|·|p'(x)|)` (absolute for x = 0: without the `|x|`): rounding the
coefficients by a relative ε moves the root by about κ·ε relative.

Sources of the cases: A. G. Orellana and C. De Michele, "Algorithm 1010: Boosting
efficiency in solving quartic equations with no compromise in accuracy", ACM TOMS 46(2),
2020 (cases 1-24 of its accuracy test, as listed in the authors' reference code
`accuracytest.cpp` of cridemichel/quarticpp, in its version with case 15's fourth root
2^-48 and case 23's 3/8 computed as a quotient); cases 1-13 are those of
F. Flocke, "Algorithm 954: An accurate and efficient cubic and quartic equation solver
for physical applications", ACM TOMS 41(4), 2015, and 14-18 those of P. Strobach,
"The fast quartic solver", J. Comput. Appl. Math. 234, 2010. The structured cases below
them are this crate's.

Run: python3 cases.py > cases.rs && cargo fmt --all
"""

from fractions import Fraction as F
import math

# ---- polynomials: lists of Fractions, highest degree first ----------------------------


def trim(p):
    while len(p) > 1 and p[0] == 0:
        p = p[1:]
    return p


def deriv(p):
    n = len(p) - 1
    return trim([c * (n - i) for i, c in enumerate(p[:-1])]) if n > 0 else [F(0)]


def ev(p, x):
    acc = F(0)
    for c in p:
        acc = acc * x + c
    return acc


def divmod_poly(a, b):
    a = list(a)
    q = []
    while len(a) >= len(b):
        k = a[0] / b[0]
        q.append(k)
        for i in range(len(b)):
            a[i] -= k * b[i]
        a = a[1:]
    return trim(q) if q else [F(0)], trim(a) if a else [F(0)]


def gcd_poly(a, b):
    while not (len(b) == 1 and b[0] == 0):
        a, b = b, divmod_poly(a, b)[1]
    return [c / a[0] for c in a]


def sturm_seq(p):
    seq = [p, deriv(p)]
    while True:
        r = divmod_poly(seq[-2], seq[-1])[1]
        if len(r) == 1 and r[0] == 0:
            return seq
        seq.append([-c for c in r])


def sign_changes(seq, x):
    signs = [s for s in (ev(p, x) for p in seq) if s != 0]
    return sum(1 for a, b in zip(signs, signs[1:]) if (a < 0) != (b < 0))


def count(seq, a, b):
    """Distinct real roots in (a, b]."""
    return sign_changes(seq, a) - sign_changes(seq, b)


def positive_roots(p):
    """Distinct positive roots of the square-free p, to ~1e-40 relative, as Fractions."""
    seq = sturm_seq(p)
    lo_e, hi_e = -1100, 1100
    out = []
    # Geometric isolation over powers of two, then bisection.
    stack = [(lo_e, hi_e)]
    while stack:
        e0, e1 = stack.pop()
        n = count(seq, F(2) ** e0, F(2) ** e1)
        if n == 0:
            continue
        if n > 1 and e1 - e0 > 1:
            m = (e0 + e1) // 2
            stack += [(e0, m), (m, e1)]
            continue
        out += isolate(p, seq, F(2) ** e0, F(2) ** e1, n)
    return sorted(out)


def isolate(p, seq, a, b, n):
    if n == 0:
        return []
    if n == 1:
        return [refine(p, a, b)]
    m = (a + b) / 2
    return isolate(p, seq, a, m, count(seq, a, m)) + isolate(p, seq, m, b, count(seq, m, b))


def refine(p, a, b):
    """The one root of p in (a, b] (a sign change or a root at b), bisected."""
    fb = ev(p, b)
    if fb == 0:
        return b
    # p has the sign of p(b) on (root, b] and the other on (a, root), whatever p(a) is.
    while (b - a) > abs(b) * F(1, 10**40):
        m = (a + b) / 2
        fm = ev(p, m)
        if fm == 0:
            return m
        if (fm < 0) == (fb < 0):
            b = m
        else:
            a = m
    return (a + b) / 2


def real_roots(p):
    """[(root, multiplicity)] of p, ascending."""
    p = trim(p)
    zero_mult = 0
    while len(p) > 1 and p[-1] == 0:
        p = p[:-1]
        zero_mult += 1
    out = [(F(0), zero_mult)] if zero_mult else []
    if len(p) > 1:
        g = gcd_poly(p, deriv(p))
        sqf = divmod_poly(p, g)[0]
        rts = positive_roots(sqf) + [-x for x in positive_roots([c * (-1) ** i for i, c in enumerate(sqf[::-1])][::-1])]
        g_roots = real_roots(g) if len(g) > 1 else []
        for x in rts:
            m = 1 + sum(k for (y, k) in g_roots if abs(y - x) <= abs(x) * F(1, 10**30))
            out.append((x, m))
    return sorted(out)


def kappa(p, x):
    n = len(p) - 1
    mag = sum(abs(c) * abs(x) ** (n - i) for i, c in enumerate(p))
    d = abs(ev(deriv(p), x))
    if d == 0:
        return math.inf
    k = mag / d
    return float(k / abs(x)) if x != 0 else float(k)


def from_roots(reals, pairs):
    """Exact coefficients of prod (x − a) · prod (x² − 2a x + a² + b²)."""
    p = [F(1)]
    for a in reals:
        p = mul(p, [F(1), -a])
    for a, b in pairs:
        p = mul(p, [F(1), -2 * a, a * a + b * b])
    return p


def mul(a, b):
    out = [F(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] += x * y
    return out


def stored(p):
    return [F(float(c)) for c in p]


def depressed(p):
    c4, c3, c2, c1, c0 = p
    a, b, c, d = c3 / c4, c2 / c4, c1 / c4, c0 / c4
    s = a / 4
    pp = b - 6 * s * s
    qq = c - 2 * s * (b - 4 * s * s)
    rr = d - s * (c - s * (b - 3 * s * s))
    return [pp, qq, rr]


def D(s):
    return F(s)


# ---- the cases ------------------------------------------------------------------------

CASES = []


def case(name, reals=(), pairs=(), coeffs=None):
    CASES.append((name, [D(x) for x in reals], [(D(a), D(b)) for a, b in pairs], coeffs))


case("oqs1_roots_1e9_1e6_1e3_1", ["1e9", "1e6", "1e3", "1"])
case("oqs2_roots_2.003_2.002_2.001_2", ["2.003", "2.002", "2.001", "2"])
case("oqs3_roots_1e53_1e50_1e49_1e47", ["1e53", "1e50", "1e49", "1e47"])
case("oqs4_roots_1e14_2_1_-1", ["1e14", "2", "1", "-1"])
case("oqs5_roots_-2e7_1e7_1_-1", ["-2e7", "1e7", "1", "-1"])
case("oqs6_roots_1e7_-1e6_1+-i", ["1e7", "-1e6"], [("1", "1")])
case("oqs7_roots_-7_-4_-1e6+-1e5i", ["-7", "-4"], [("-1e6", "1e5")])
case("oqs8_roots_1e8_11_1e3+-i", ["1e8", "11"], [("1e3", "1")])
case("oqs9_complex_1e7+-1e6i_1+-2i", [], [("1e7", "1e6"), ("1", "2")])
case("oqs10_complex_1e4+-3i_-7+-1e3i", [], [("1e4", "3"), ("-7", "1e3")])
case("oqs11_complex_1.001+-4.998i_1+-5.001i", [], [("1.001", "4.998"), ("1.000", "5.001")])
case("oqs12_complex_1e3+-3i_1e3+-i", [], [("1e3", "3"), ("1e3", "1")])
case("oqs13_complex_2+-1e4i_1+-1e3i", [], [("2", "1e4"), ("1", "1e3")])
case("oqs14_strobach_quadruple_1000", ["1000"] * 4)
case("oqs15_strobach_triple_1000_and_2^-48", ["1000"] * 3 + [F(1, 2**48)])
# An earlier version of the reference code has 1e-15 for this root (and 3/8 written as
# the string "3.0/8.0" in case 23); both variants of case 15 are kept.
case("oqs15_earlier_triple_1000_and_1e-15", ["1000"] * 3 + ["1e-15"])
case("oqs16_strobach_complex_1e16+-1e7i_1+-0.1i", [], [("1e16", "1e7"), ("1", "0.1")])
case("oqs17_strobach_1e4_10001_10010_10100", ["10000", "10001", "10010", "10100"])
case("oqs18_strobach_complex_4e5+-3e2i_3e4+-7e3i", [], [("4e5", "3e2"), ("3e4", "7e3")])
case("oqs19_roots_1e44_1e30_1e30_1", ["1e44", "1e30", "1e30", "1"])
case("oqs20_roots_1e14_1e7_1e7_1", ["1e14", "1e7", "1e7", "1"])
case("oqs21_roots_1e15_1e7_1e7_1", ["1e15", "1e7", "1e7", "1"])
case("oqs22_roots_1e154_1e152_10_1", ["1e154", "1e152", "10", "1"])
case("oqs23_coefficients_1_1_1_3/8_0.001", coeffs=[F(1), F(1), F(1), F(3, 8), D("0.001")])
S = D("1e30")
case("oqs24_roots_1_1e-30_+-1e30", coeffs=[F(1), -(1 + 1 / S), 1 / S - S * S, S * S + S, -S])
# Structured cases (this crate's).
case("zero_x4", ["0"] * 4)
case("zero_x4_minus_x2", ["0", "0", "1", "-1"])
case("zero_x4_plus_x", coeffs=[F(1), F(0), F(0), F(1), F(0)])
case("zero_x4_minus_x3", coeffs=[F(1), F(-1), F(0), F(0), F(0)])
case("zero_x4_minus_5x2_plus_4", ["1", "-1", "2", "-2"])
case("power_(x-1)^4", ["1"] * 4)
case("power_(x-3)^4", ["3"] * 4)
case("power_(x+2.5)^4", ["-2.5"] * 4)
case("power_x4_minus_16", coeffs=[F(1), F(0), F(0), F(0), F(-16)])
case("power_x4_minus_1", coeffs=[F(1), F(0), F(0), F(0), F(-1)])
case("power_x4_minus_2", coeffs=[F(1), F(0), F(0), F(0), F(-2)])
case("power_x4_minus_1e-20", coeffs=[F(1), F(0), F(0), F(0), D("-1e-20")])
case("power_x4_minus_1e20", coeffs=[F(1), F(0), F(0), F(0), D("-1e20")])
case("power_x4_plus_16", coeffs=[F(1), F(0), F(0), F(0), F(16)])
case("ratio_1e14_roots_-1_1_2_1e14", ["-1", "1", "2", "1e14"])
case("near_double_1e-7_at_1", ["1", "1.0000001", "3", "-2"])
case("near_double_1e-7_at_-0.5_and_4", ["-0.5", "-0.4999999", "4", "4.0000001"])
case("near_double_1e-4_at_1e3", ["1000", "1000.0001", "-1", "5"])
case("near_double_complex_1+-1e-7i", ["3", "-2"], [("1", "1e-7")])
case("huge_+-1e30_1_2", ["1e30", "-1e30", "1", "2"])
case("huge_1e30_1e30+1e23", ["1e30", "1.00000001e30", "-3", "7"])
case("tiny_+-1e-30_1_2", ["1e-30", "-1e-30", "1", "2"])
# Issue 36: a depressed quartic from a larger published corpus, with a close pair of large
# roots (192 889.337 and 192 889.364, beside a complex pair) that the nearest-root query
# returned as one double root between them. Its coefficients as stored, exactly.
case(
    "issue36_close_pair_1.9e5",
    coeffs=[F(1), F(0), F(-59369260987.89166), F(-5803400893965144.0), F(1.9440159814205568e21)],
)


def f64(x):
    return repr(float(x))


def rust_roots(roots, p):
    items = []
    for x, m in roots:
        k = kappa(p, x) if m == 1 else math.inf
        kk = "f64::INFINITY" if math.isinf(k) else f"{k:.3e}"
        items.append(f"({f64(x)}, {m}, {kk})")
    return "&[" + ", ".join(items) + "]"


print("// Generated by cases.py in this directory: the stored f64 coefficients of each case")
print("// and the real roots of that stored polynomial (value, multiplicity, relative")
print("// condition number κ), derived exactly. Do not edit by hand.")
print()
print("/// One corpus case: see `cases.py`.")
print("pub(super) struct Case {")
print("    pub name: &'static str,")
print("    /// `[c4, c3, c2, c1, c0]` as stored.")
print("    pub c: [f64; 5],")
print("    /// Real roots of the stored quartic: (value, multiplicity, κ).")
print("    pub roots: &'static [(f64, u32, f64)],")
print("    /// `[p, q, r]` of the depressed monic form (exact from `c`, rounded), if finite.")
print("    pub depressed: Option<[f64; 3]>,")
print("    /// Real roots of the stored depressed quartic.")
print("    pub depressed_roots: &'static [(f64, u32, f64)],")
print("}")
print()
print("pub(super) const CASES: &[Case] = &[")
for name, reals, pairs, coeffs in CASES:
    exact = coeffs if coeffs is not None else from_roots(reals, pairs)
    c = stored(exact)
    roots = real_roots(c)
    dep = depressed(c)
    try:
        finite = all(math.isfinite(float(v)) for v in dep)
    except OverflowError:
        finite = False
    print("    Case {")
    print(f"        name: \"{name}\",")
    print(f"        c: [{', '.join(f64(v) for v in c)}],")
    print(f"        roots: {rust_roots(roots, c)},")
    if finite:
        d = stored(dep)
        dp = [F(1), F(0)] + d
        print(f"        depressed: Some([{', '.join(f64(v) for v in d)}]),")
        print(f"        depressed_roots: {rust_roots(real_roots(dp), dp)},")
    else:
        print("        depressed: None,")
        print("        depressed_roots: &[],")
    print("    },")
print("];")
