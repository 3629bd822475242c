#!/usr/bin/env python3
"""Adversarial `eval` rows for the torus family members accepted at 4ee9b1d (ν = R/a ≥ 1/2),
written deterministically (Python's own Mersenne Twister, seeded per member; floats printed
with repr, which round-trips), so that `eval` before and after a change reads the same rows.

    python3 tests/cli/data/family_rows.py            # writes tests/cli/data/family_rows/
    for f in tests/cli/data/family_rows/*.csv; do     # one member per file: R_a_b.csv
        IFS=_ read -r big a b <<< "$(basename "$f" .csv)"
        torus-cull eval --major "$big" --minor "$a" --axial "$b" --rays "$f"
    done

Rows per member, in the torus frame (centre 0, axis +y), header
`ox,oy,oz,dx,dy,dz,t_min,t_max,on_surface`:
- the axis, exactly and 1e-12…1e-2 of the size off it, both ways, from outside and from
  the centre;
- through a spindle's two cusps (a horn's centre) from random directions;
- tangent to the surface (the apple's arc for a horn or spindle) pushed ±1e-9…1e-3 of the
  size along the normal;
- from inside the lemon (a spindle), and along the lemon's tangents;
- short ranges ending near a crossing;
- from surface points (on_surface = 1), near the cusps among them;
- uniform rays at the member's box.
"""

import math
import os
import random

# (R, a, b) accepted at 4ee9b1d: circular and elliptical rings, horns, spindles ν ≥ 1/2.
MEMBERS = [
    (3.0, 1.0, 1.0),
    (4.0, 1.0, 0.25),
    (1.25, 1.0, 4.0),
    (1.0, 1.0, 1.0),
    (1.0, 1.0, 0.25),
    (0.75, 1.0, 2.0),
    (0.5, 1.0, 1.0),
    (0.5, 1.0, 4.0),
]

PER_KIND = 24


def unit(rng):
    while True:
        v = [rng.uniform(-1.0, 1.0) for _ in range(3)]
        n = math.sqrt(sum(x * x for x in v))
        if 0.1 < n <= 1.0:
            return [x / n for x in v]


def surface(big, a, b, theta, phi):
    """The point at tube angle θ (ρ = R + a cos θ, clamped at 0) and azimuth φ, and its
    outward normal."""
    rho = max(big + a * math.cos(theta), 0.0)
    p = [rho * math.cos(phi), b * math.sin(theta), rho * math.sin(phi)]
    nr, ny = math.cos(theta) / a, math.sin(theta) / b
    ln = math.hypot(nr, ny)
    n = [nr / ln * math.cos(phi), ny / ln, nr / ln * math.sin(phi)]
    return p, n


def tangent_to(n, rng):
    while True:
        v = unit(rng)
        d = sum(x * y for x, y in zip(v, n))
        t = [x - d * y for x, y in zip(v, n)]
        ln = math.sqrt(sum(x * x for x in t))
        if ln > 1e-3:
            return [x / ln for x in t]


def rows(big, a, b, rng):
    size = big + max(a, b)
    out = []

    def ray(o, d, t_min=0.0, t_max=math.inf, on=0):
        out.append((o, d, t_min, t_max, on))

    def back(p, d, k=3.0):
        return [x - k * size * y for x, y in zip(p, d)]

    cusp = b * math.sqrt(max(1.0 - (big / a) ** 2, 0.0))
    top = math.acos(max(-big / a, -1.0))  # the apple's arc: |θ| ≤ top
    for sign in (1.0, -1.0):
        ray([0.0, 3.0 * size * sign, 0.0], [0.0, -sign, 0.0])
        ray([0.0, 0.0, 0.0], [0.0, sign, 0.0])
    for _ in range(PER_KIND):
        off = size * 10 ** rng.uniform(-12, -2)
        phi = rng.uniform(0, 2 * math.pi)
        tilt = 10 ** rng.uniform(-8, -2)
        sign = rng.choice((1.0, -1.0))
        o = [off * math.cos(phi), 3.0 * size * sign, off * math.sin(phi)]
        ray(o, [tilt * math.sin(phi), -sign, -tilt * math.cos(phi)])
    for _ in range(PER_KIND):
        c = [0.0, rng.choice((cusp, -cusp)), 0.0]
        d = unit(rng)
        ray(back(c, d), d)
    for _ in range(PER_KIND):
        theta = rng.uniform(-top, top)
        p, n = surface(big, a, b, theta, rng.uniform(0, 2 * math.pi))
        d = tangent_to(n, rng)
        push = size * 10 ** rng.uniform(-9, -3) * rng.choice((1.0, -1.0))
        ray(back([x + push * y for x, y in zip(p, n)], d), d)
    if big < a:
        for _ in range(PER_KIND):
            phi = rng.uniform(0, 2 * math.pi)
            rho = rng.uniform(0.0, a - big)
            ymax = b * math.sqrt(max(1.0 - ((rho + big) / a) ** 2, 0.0))
            y = rng.uniform(-1.0, 1.0) * ymax
            ray([rho * math.cos(phi), y, rho * math.sin(phi)], unit(rng))
            theta = rng.uniform(top, 2 * math.pi - top)
            rho = -(big + a * math.cos(theta))
            p = [rho * math.cos(phi), b * math.sin(theta), rho * math.sin(phi)]
            nr, ny = -math.cos(theta) / a, math.sin(theta) / b
            ln = math.hypot(nr, ny)
            n = [nr / ln * math.cos(phi), ny / ln, nr / ln * math.sin(phi)]
            d = tangent_to(n, rng)
            ray(back(p, d), d)
    for _ in range(PER_KIND):
        theta = rng.uniform(-top, top)
        p, n = surface(big, a, b, theta, rng.uniform(0, 2 * math.pi))
        d = [-x for x in n]
        k = 3.0 * size
        ray(back(p, d), d, k * rng.uniform(0.5, 0.99), k * (1 + 10 ** rng.uniform(-9, -3)))
    for i in range(2 * PER_KIND):
        # Near the cusps for half of them: |θ| within 1e-3 of the arc's end.
        theta = rng.uniform(-top, top) if i % 2 else rng.choice((1, -1)) * (top - 10 ** rng.uniform(-6, -3))
        p, n = surface(big, a, b, theta, rng.uniform(0, 2 * math.pi))
        ray(p, unit(rng), on=1)
    for _ in range(PER_KIND):
        o = [x * 4.0 * size for x in unit(rng)]
        target = [rng.uniform(-big - a, big + a), rng.uniform(-b, b), rng.uniform(-big - a, big + a)]
        ray(o, [t - x for t, x in zip(target, o)])
    return out


def main():
    here = os.path.join(os.path.dirname(os.path.abspath(__file__)), "family_rows")
    os.makedirs(here, exist_ok=True)
    for i, (big, a, b) in enumerate(MEMBERS):
        rng = random.Random(54_000 + i)
        lines = ["ox,oy,oz,dx,dy,dz,t_min,t_max,on_surface"]
        for o, d, t_min, t_max, on in rows(big, a, b, rng):
            vals = [repr(x) for x in o + d] + [repr(t_min), "inf" if t_max == math.inf else repr(t_max), str(on)]
            lines.append(",".join(vals))
        with open(os.path.join(here, f"{big}_{a}_{b}.csv"), "w") as f:
            f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
