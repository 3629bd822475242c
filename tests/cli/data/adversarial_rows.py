#!/usr/bin/env python3
"""The nothing-lost set: adversarial `eval` rows for every member of the family and for
pipe bends, ≥ 50 000 rows in all, written deterministically (Python's Mersenne Twister,
seeded per member; floats printed with repr, which round-trips), so that `eval` of two
binaries reads the same rows and can be compared byte for byte
(`nothing_lost_compare.sh`).

    python3 tests/cli/data/adversarial_rows.py OUT_DIR [PER_KIND]

writes OUT_DIR/<name>.csv per member and OUT_DIR/members.tsv: `name<TAB>eval flags`.
PER_KIND (default 320) scales every structured kind; the default gives about 59 000 rows.

The members: circular rings (ν 1.1, 3, 8, and ν 3 at 10⁻³ and 10³ scale), elliptical rings
(b/a ¼, ½, 4), horns (b/a 1, ¼), spindles (ν ¾, ½, 0.2, 0.05, 0.02; b/a ½…4), and pipe
bends (a bore and a segment, a segment without a bore, a whole ring with a bore, a thin
wall). The ring and family rows are family_rows.py's kinds (the axis, the cusps, tangents
pushed ±10⁻⁹…10⁻³, inside the lemon, short ranges, surface points, uniform); a bend adds
rays at its caps' edges, along its caps' planes, tangent to its bore, through the bore's
hole, and from surface points inside the segment. φ is right-handed about +y
(docs/math.md §1): the point at φ is (ρ cos φ, y, −ρ sin φ).
"""

import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import family_rows  # noqa: E402

# name, (R, a, b)
FAMILY = [
    ("ring_nu1.1", (1.1, 1.0, 1.0)),
    ("ring_nu3", (3.0, 1.0, 1.0)),
    ("ring_nu8", (8.0, 1.0, 1.0)),
    ("ring_nu3_small", (3e-3, 1e-3, 1e-3)),
    ("ring_nu3_large", (3e3, 1e3, 1e3)),
    ("elliptic_b0.25", (4.0, 1.0, 0.25)),
    ("elliptic_b0.5", (2.0, 1.0, 0.5)),
    ("elliptic_b4", (1.25, 1.0, 4.0)),
    ("horn", (1.0, 1.0, 1.0)),
    ("horn_b0.25", (1.0, 1.0, 0.25)),
    ("spindle_nu0.75_b2", (0.75, 1.0, 2.0)),
    ("spindle_nu0.5", (0.5, 1.0, 1.0)),
    ("spindle_nu0.5_b4", (0.5, 1.0, 4.0)),
    ("spindle_nu0.2", (0.2, 1.0, 1.0)),
    ("spindle_nu0.05_b0.5", (0.05, 1.0, 0.5)),
    ("spindle_nu0.02", (0.02, 1.0, 1.0)),
]

# name, (R, bore r_min, tube r_max, φ₀, Δφ)
BENDS = [
    ("bend_bore_segment", (3.0, 0.5, 1.0, 0.3, 2.0)),
    ("bend_segment", (2.0, 0.0, 1.0, 0.0, math.pi / 2)),
    ("bend_whole_bore", (5.0, 0.9, 1.0, 0.0, 2 * math.pi)),
    ("bend_thin_wall", (4.0, 0.999, 1.0, -1.0, math.pi)),
]


def at(rho, y, phi):
    return [rho * math.cos(phi), y, -rho * math.sin(phi)]


def bend_rows(big, r_min, r_max, phi0, dphi, rng, per_kind):
    size = big + r_max
    out = []

    def ray(o, d, t_min=0.0, t_max=math.inf, on=0):
        out.append((o, d, t_min, t_max, on))

    def back(p, d, k=3.0):
        return [x - k * size * y for x, y in zip(p, d)]

    ends = [phi0, phi0 + dphi] if dphi < 2 * math.pi else []
    # The caps' edges: the cap circle's rim (outer and bore), pushed ±1e-9…1e-3 off it,
    # from random directions.
    for _ in range(per_kind if ends else 0):
        phi = rng.choice(ends)
        rad = rng.choice([r_max, r_min] if r_min > 0 else [r_max])
        th = rng.uniform(0, 2 * math.pi)
        push = size * 10 ** rng.uniform(-9, -3) * rng.choice((1.0, -1.0))
        p = at(big + (rad + push) * math.cos(th), (rad + push) * math.sin(th), phi)
        d = family_rows.unit(rng)
        ray(back(p, d), d)
    # Along a cap's plane (in it, or 1e-12…1e-4 off it), toward the axis or across.
    for _ in range(per_kind if ends else 0):
        phi = rng.choice(ends)
        normal = [-math.sin(phi), 0.0, -math.cos(phi)]  # ∂/∂φ of the point at φ, unit
        inplane = family_rows.tangent_to(normal, rng)
        off = rng.choice((0.0, 1.0, -1.0)) * size * 10 ** rng.uniform(-12, -4)
        p = at(big + rng.uniform(-r_max, r_max), rng.uniform(-r_max, r_max), phi)
        p = [x + off * n for x, n in zip(p, normal)]
        ray(back(p, inplane), inplane)
    # Tangent to the bore (the concave face) and to the outer face, pushed ±1e-9…1e-3.
    for _ in range(2 * per_kind):
        rad = r_min if (r_min > 0 and rng.random() < 0.5) else r_max
        th = rng.uniform(0, 2 * math.pi)
        phi = phi0 + rng.uniform(0, dphi)
        p = at(big + rad * math.cos(th), rad * math.sin(th), phi)
        n = [math.cos(th) * math.cos(phi), math.sin(th), -math.cos(th) * math.sin(phi)]
        d = family_rows.tangent_to(n, rng)
        push = size * 10 ** rng.uniform(-9, -3) * rng.choice((1.0, -1.0))
        p = [x + push * y for x, y in zip(p, n)]
        ray(back(p, d), d)
    # From the bore's hollow core (inside the pipe, in the air), any direction.
    for _ in range(per_kind if r_min > 0 else 0):
        th = rng.uniform(0, 2 * math.pi)
        rad = r_min * rng.uniform(0.0, 0.99)
        phi = phi0 + rng.uniform(0, dphi)
        ray(at(big + rad * math.cos(th), rad * math.sin(th), phi), family_rows.unit(rng))
    # From surface points of the outer face well inside the segment (on_surface = 1).
    for _ in range(per_kind):
        th = rng.uniform(0, 2 * math.pi)
        margin = min(1e-3, dphi / 4)
        phi = phi0 + rng.uniform(margin, dphi - margin)
        p = at(big + r_max * math.cos(th), r_max * math.sin(th), phi)
        ray(p, family_rows.unit(rng), on=1)
    # Short ranges ending near the outer face.
    for _ in range(per_kind):
        th = rng.uniform(0, 2 * math.pi)
        phi = phi0 + rng.uniform(0, dphi)
        p = at(big + r_max * math.cos(th), r_max * math.sin(th), phi)
        d = [-math.cos(th) * math.cos(phi), -math.sin(th), math.cos(th) * math.sin(phi)]
        k = 3.0 * size
        ray(back(p, d), d, k * rng.uniform(0.5, 0.99), k * (1 + 10 ** rng.uniform(-9, -3)))
    # Uniform rays at the bend's box, and the axis.
    for sign in (1.0, -1.0):
        ray([0.0, 3.0 * size * sign, 0.0], [0.0, -sign, 0.0])
    for _ in range(2 * per_kind):
        o = [x * 4.0 * size for x in family_rows.unit(rng)]
        target = [rng.uniform(-size, size), rng.uniform(-r_max, r_max), rng.uniform(-size, size)]
        ray(o, [t - x for t, x in zip(target, o)])
    return out


def write(path, rows):
    lines = ["ox,oy,oz,dx,dy,dz,t_min,t_max,on_surface"]
    for o, d, t_min, t_max, on in rows:
        vals = [repr(x) for x in o + d]
        vals += [repr(t_min), "inf" if t_max == math.inf else repr(t_max), str(on)]
        lines.append(",".join(vals))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return len(rows)


def main():
    out = sys.argv[1]
    per_kind = int(sys.argv[2]) if len(sys.argv) > 2 else 320
    os.makedirs(out, exist_ok=True)
    family_rows.PER_KIND = per_kind
    manifest, total = [], 0
    for i, (name, (big, a, b)) in enumerate(FAMILY):
        rows = family_rows.rows(big, a, b, random.Random(61_000 + i))
        total += write(os.path.join(out, name + ".csv"), rows)
        manifest.append(f"{name}\t--major {big!r} --minor {a!r} --axial {b!r}")
    for i, (name, (big, r_min, r_max, phi0, dphi)) in enumerate(BENDS):
        rng = random.Random(62_000 + i)
        rows = bend_rows(big, r_min, r_max, phi0, dphi, rng, per_kind)
        # The outer torus's own adversarial kinds too; its surface points only where they
        # are the bend's (inside the segment, 10⁻³ from the caps).
        def on_bend(row):
            o, on = row[0], row[4]
            rel = (math.atan2(-o[2], o[0]) - phi0) % (2 * math.pi)
            return on == 0 or dphi == 2 * math.pi or 1e-3 < rel < dphi - 1e-3
        rows += [row for row in family_rows.rows(big, r_max, r_max, rng) if on_bend(row)]
        total += write(os.path.join(out, name + ".csv"), rows)
        manifest.append(
            f"{name}\t--major {big!r} --minor {r_max!r} --bore {r_min!r}"
            f" --phi-start {phi0!r} --delta-phi {dphi!r}"
        )
    with open(os.path.join(out, "members.tsv"), "w") as f:
        f.write("\n".join(manifest) + "\n")
    print(f"{total} rows over {len(manifest)} members in {out}")


if __name__ == "__main__":
    main()
