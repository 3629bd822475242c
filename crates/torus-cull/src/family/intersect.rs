//! A family member's rays: the nearest hit, a shadow ray's verdict, every crossing, and the
//! cull in front, each the circular image's on the image line (module docs of
//! [`crate::family`]).

use super::{Toroid, ToroidKind};
use crate::intersect::sealed::{FromExact, Steps};
use crate::intersect::{Roots, crossings_in_frame, exact_in_frame, line_crossings};
use crate::{Crossings, Cull, F32Hit, Precision, Ray, TorusRay, intersect_f32};
use glam::DVec3;

impl Toroid {
    /// The nearest hit with `t ∈ [t_min, t_max]`, as [`crate::intersect()`] answers it for
    /// a ring torus: the outward normal, `front_face` where the ray enters the solid, a
    /// ray from a surface point ([`Ray::from_surface`]) past its origin's own crossing.
    /// A horn's or spindle's hit is the apple's, never the lemon's.
    #[inline]
    #[must_use]
    pub fn intersect<R: TorusRay>(&self, ray: &R) -> Option<R::Hit> {
        let (t, n) = self.exact(ray)?;
        let (o, d) = ray.world_f64();
        R::Hit::from_exact(t, self.normal_to_world(n), o, d)
    }

    /// Whether the ray meets the member at some `t ∈ [t_min, t_max]` (the same solve as
    /// [`Toroid::intersect`]).
    #[inline]
    #[must_use]
    pub fn occluded<R: TorusRay>(&self, ray: &R) -> bool {
        self.exact(ray).is_some_and(|(t, _)| R::fits(t))
    }

    /// Every crossing in `[t_min, t_max]`, as [`crate::intersect_all`] gives them for a
    /// ring torus: sorted, entering or leaving, tangents as touches, paired into spans
    /// with [`Crossings::spans`]. A horn or spindle has the apple's crossings alone; a
    /// line along the axis through a spindle enters and leaves at its two cusps.
    pub fn intersect_all<P: Precision>(&self, ray: &Ray<P>) -> Crossings<P> {
        let line = self.image_line_f64(ray);
        let roots = match self.kind() {
            ToroidKind::Ring => Roots::All,
            ToroidKind::Horn | ToroidKind::Spindle => Roots::Apple,
        };
        crossings_in_frame(ray, self.image().tube(), line, roots, |n| {
            self.normal_to_world(n)
        })
    }

    /// `cull` on the ray's line ([`Toroid::line_to_local`]) against the image torus's
    /// bounds, then the exact intersection if the cull keeps it. A cull that does not list
    /// this member's shape ([`Cull::shapes`], [`Toroid::shape`]) is declined: the exact
    /// intersection runs alone.
    #[inline]
    #[must_use]
    pub fn intersect_culled<C: Cull + ?Sized, R: TorusRay>(
        &self,
        cull: &C,
        ray: &R,
    ) -> Option<R::Hit> {
        if self.kept_by(cull, ray) {
            self.intersect(ray)
        } else {
            None
        }
    }

    /// Whether `cull` keeps the ray (true where the member's shape is not among the
    /// cull's: the cull is declined).
    #[inline]
    #[must_use]
    pub fn kept_by<C: Cull + ?Sized, R: TorusRay>(&self, cull: &C, ray: &R) -> bool {
        if !cull.shapes().contains(&self.shape()) {
            return true;
        }
        let line = self.line_to_local(ray.as_ray());
        cull.keeps(self.image().bounds(), line.origin, line.dir)
    }

    /// The certified f32 intersection for a circular ring member ([`intersect_f32`]);
    /// every other member is answered by the f64 path and counted as escalated.
    #[must_use]
    pub fn intersect_f32(&self, ray: &Ray) -> F32Hit {
        match self.as_torus() {
            Ok(torus) => intersect_f32(torus, ray),
            Err(_) => F32Hit {
                hit: self.intersect(ray),
                escalated: true,
            },
        }
    }

    /// The nearest crossing in range, `t` and the image's torus-frame normal.
    #[inline(always)]
    fn exact<R: TorusRay>(&self, ray: &R) -> Option<(f64, DVec3)> {
        let line = self.image_line_f64(ray.as_ray());
        let range = ray.range_f64();
        match self.kind() {
            ToroidKind::Ring => exact_in_frame(self.image().tube(), line, range, ray.on_surface()),
            ToroidKind::Horn | ToroidKind::Spindle => {
                // The apple's first crossing: `intersect_all`'s walk, its `t` in f64.
                let mut first = None;
                line_crossings(
                    self.image().tube(),
                    line,
                    range,
                    ray.on_surface(),
                    Roots::Apple,
                    |t, n, _| {
                        first.get_or_insert((t, n));
                    },
                );
                first
            }
        }
    }
}
