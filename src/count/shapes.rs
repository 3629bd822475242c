//! The count channel's other shapes: the torus family's members and the pipe bends, as
//! `time family` and `time bend` time them (`crate::paired::family::members`,
//! `crate::paired::bend::bends`, each on its uniform box rays): per member, the exact
//! intersection alone (`exact`) and behind each cull; per bend, no cull (`none`), each
//! cull, and each cull behind the segment's wedge (`wedge+<cull>`). Metric
//! `family_total` or `bend_total`, the wall channel's `family_total_ns`, `bend_total_ns`.

use super::region::Announcer;
use crate::paired::shapes::TimedShape;
use crate::workload::box_rays::box_rays;
use std::hint::black_box;
use std::io::Write;
use torus_cull::bend::PipeBend;
use torus_cull::family::Toroid;
use torus_cull::{Cull, CullKind, CullVisitor, Ray};

/// One member's or bend's rays, and the record's key but for the cull.
struct Unit<'s, S> {
    shape: &'s S,
    rays: &'s [Ray],
    group: &'static str,
    case: &'s str,
    nu: f64,
    metric: &'static str,
}

/// A member behind a cull.
struct FamilyPass<'s, 'a, W: Write> {
    unit: &'s Unit<'a, Toroid>,
    announcer: &'s mut Announcer<W>,
}

impl<W: Write> CullVisitor for FamilyPass<'_, '_, W> {
    type Output = std::io::Result<()>;

    fn visit<C: Cull>(self, cull: C) -> std::io::Result<()> {
        let u = self.unit;
        let key = (u.group, u.case, u.nu, cull.name(), u.metric);
        self.announcer.region(key, u.rays.len(), &mut || {
            for ray in black_box(u.rays) {
                black_box(u.shape.intersect_culled(&cull, ray));
            }
        })
    }
}

/// A bend behind a cull, or behind the cull and the segment's wedge.
struct BendPass<'s, 'a, W: Write> {
    unit: &'s Unit<'a, PipeBend>,
    wedge: bool,
    announcer: &'s mut Announcer<W>,
}

impl<W: Write> CullVisitor for BendPass<'_, '_, W> {
    type Output = std::io::Result<()>;

    fn visit<C: Cull>(self, cull: C) -> std::io::Result<()> {
        let u = self.unit;
        let rays = u.rays;
        if self.wedge {
            let name = format!("wedge+{}", cull.name());
            let key = (u.group, u.case, u.nu, name.as_str(), u.metric);
            let cull = u.shape.wedge_cull(cull);
            return self.announcer.region(key, rays.len(), &mut || {
                for ray in black_box(rays) {
                    black_box(u.shape.intersect_culled(&cull, ray));
                }
            });
        }
        let key = (u.group, u.case, u.nu, cull.name(), u.metric);
        self.announcer.region(key, rays.len(), &mut || {
            for ray in black_box(rays) {
                black_box(u.shape.intersect_culled(&cull, ray));
            }
        })
    }
}

/// Every family member's regions, `rays` box rays each (seeded as `time family` seeds
/// them), for `culls`.
pub fn family<W: Write>(
    culls: &[CullKind],
    (rays, seed): (usize, u64),
    ann: &mut Announcer<W>,
) -> Result<(), String> {
    let io = |e: std::io::Error| format!("count worker: writing to the parent: {e}");
    for (i, member) in crate::paired::family::members()?.iter().enumerate() {
        let (big, a, b) = member.box_radii();
        let batch = box_rays(big, a, b, rays, seed.wrapping_add(i as u64));
        let case = member.case_name();
        eprintln!("count: {case}");
        let unit = Unit {
            shape: member,
            rays: &batch,
            group: "family",
            case: &case,
            nu: big / a,
            metric: "family_total",
        };
        let key = (unit.group, unit.case, unit.nu, "exact", unit.metric);
        ann.region(key, batch.len(), &mut || {
            for ray in black_box(batch.as_slice()) {
                black_box(member.intersect(ray));
            }
        })
        .map_err(io)?;
        for &cull in culls {
            cull.visit(FamilyPass {
                unit: &unit,
                announcer: ann,
            })
            .map_err(io)?;
        }
    }
    Ok(())
}

/// Every bend's regions, as [`family`]'s: each cull alone, then behind the wedge.
pub fn bends<W: Write>(
    culls: &[CullKind],
    (rays, seed): (usize, u64),
    ann: &mut Announcer<W>,
) -> Result<(), String> {
    let io = |e: std::io::Error| format!("count worker: writing to the parent: {e}");
    for (i, bend) in crate::paired::bend::bends()?.iter().enumerate() {
        let (big, a, b) = bend.box_radii();
        let batch = box_rays(big, a, b, rays, seed.wrapping_add(i as u64));
        let case = bend.case_name();
        eprintln!("count: {case}");
        let unit = Unit {
            shape: bend,
            rays: &batch,
            group: "bend",
            case: &case,
            nu: big / a,
            metric: "bend_total",
        };
        for wedge in [false, true] {
            for &cull in culls {
                cull.visit(BendPass {
                    unit: &unit,
                    wedge,
                    announcer: ann,
                })
                .map_err(io)?;
            }
        }
    }
    Ok(())
}
