# Adversarial rays for the GPU check (docs/gpu.md): python3 make_rays.py R r N SEED > rays-R-r.csv
# Adversarial rays for the GPU check on real hardware: grazing rays tangent to the torus
# (offsets 1e-7..1e-2 of R+r inside and outside), rays through the hole, random lines,
# and rays spawned on the surface (on_surface = 1). Torus frame: axis +y.
import math, random, sys
R, r, n, seed = float(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
rng = random.Random(seed)
S = R + r
print("ox,oy,oz,dx,dy,dz,t_min,t_max,on_surface")
def surf(th, ph):
    c = R + r*math.cos(th)
    p = (c*math.cos(ph), r*math.sin(th), c*math.sin(ph))
    nrm = (math.cos(th)*math.cos(ph), math.sin(th), math.cos(th)*math.sin(ph))
    return p, nrm
def cross(a,b): return (a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0])
def unit(a):
    l = math.sqrt(sum(x*x for x in a)); return tuple(x/l for x in a)
for i in range(n):
    k = i % 4
    if k == 0:  # grazing
        th = rng.choice([0, math.pi/2, math.pi, -math.pi/2, rng.uniform(-math.pi, math.pi)])
        ph = rng.uniform(0, 2*math.pi)
        p, nr = surf(th, ph)
        a = unit((rng.gauss(0,1), rng.gauss(0,1), rng.gauss(0,1)))
        t = unit(cross(nr, a))
        off = rng.choice([-1, 1]) * 10**rng.uniform(-7, -2) * S
        o = tuple(p[j] + off*nr[j] - 3*S*t[j] for j in range(3))
        d = tuple(t[j]*10**rng.uniform(-1, 1) for j in range(3))
        print(",".join(repr(x) for x in o+d) + ",0,inf,0")
    elif k == 1:  # hole
        o = (rng.uniform(-0.5,0.5)*(R-r), 3*S*rng.choice([-1,1]), rng.uniform(-0.5,0.5)*(R-r))
        tgt = (rng.uniform(-1,1)*(R-r), rng.uniform(-r, r), rng.uniform(-1,1)*(R-r))
        d = unit(tuple(tgt[j]-o[j] for j in range(3)))
        print(",".join(repr(x) for x in o+d) + ",0,inf,0")
    elif k == 2:  # random lines with ranges
        o = tuple(rng.uniform(-2*S, 2*S) for _ in range(3))
        d = unit((rng.gauss(0,1), rng.gauss(0,1), rng.gauss(0,1)))
        tmin = rng.choice([0, 0, rng.uniform(0, S)])
        tmax = rng.choice(["inf", repr(tmin + rng.uniform(0, 4*S))])
        print(",".join(repr(x) for x in o+d) + f",{tmin!r},{tmax},0")
    else:  # spawned from the surface, any direction, many near the tangent plane
        th, ph = rng.uniform(-math.pi, math.pi), rng.uniform(0, 2*math.pi)
        p, nr = surf(th, ph)
        a = unit((rng.gauss(0,1), rng.gauss(0,1), rng.gauss(0,1)))
        t = unit(cross(nr, a))
        al = rng.choice([rng.uniform(-1.5, 1.5), rng.choice([-1,1])*10**rng.uniform(-5,-1)])
        d = tuple(math.cos(al)*t[j] + math.sin(al)*nr[j] for j in range(3))
        print(",".join(repr(x) for x in p+d) + ",0,inf,1")
