//! The [`crate::Solid`] interface implemented by the library's three shapes, one file per
//! shape, each verb delegating to the shape's own method or free function (which stay as
//! they are): [`crate::Torus`] (`torus.rs`), [`crate::family::Toroid`] (`toroid.rs`),
//! [`crate::bend::PipeBend`] (`bend.rs`); with `From` conversions from each shape's own
//! answer types to the interface's, and [`crate::RayCast`] for each shape and for each
//! shape behind a cull ([`crate::Culled`]). The trait itself is `solid.rs`.
//!
//! **A new shape** of the library adds its own folder (its methods) and one file here;
//! a shape outside the library implements [`Solid`] in its own crate (docs/layout.md,
//! "Adding a shape").

/// The ray verbs of [`Solid`] whose f32 and f64 forms are one expression, for a shape
/// whose own functions are generic over the ray's precision: `hit`/`hit_f64` from
/// `$intersect(self, ray)`, `occluded`/`occluded_f64` from `$occluded`,
/// `crossings`/`crossings_f64` from `$all`, `spawn`/`spawn_f64` from `$spawn`, each
/// answer converted into the interface's type; `hit_f32_certified` from `$f32(self, ray)`
/// and `kept_by` from `$kept(self, cull, ray)`. Written once here, not per shape and per
/// precision (eight twins in each of three files).
macro_rules! ray_verbs {
    ($intersect:path, $occluded:path, $all:path, $spawn:path, $f32:path, $kept:path) => {
        fn hit_f32_certified(&self, ray: &Ray) -> SolidF32Hit<Self::Face> {
            $f32(self, ray).into()
        }

        #[inline]
        fn kept_by<C: Cull + ?Sized, P: Precision>(&self, cull: &C, ray: &Ray<P>) -> bool {
            $kept(self, cull, ray)
        }

        fn hit(&self, ray: &Ray) -> Option<SolidHit<Vec3, Self::Face>> {
            $intersect(self, ray).map(SolidHit::from)
        }

        fn hit_f64(&self, ray: &DRay) -> Option<SolidHit<DVec3, Self::Face>> {
            $intersect(self, ray).map(SolidHit::from)
        }

        fn occluded(&self, ray: &Ray) -> bool {
            $occluded(self, ray)
        }

        fn occluded_f64(&self, ray: &DRay) -> bool {
            $occluded(self, ray)
        }

        fn crossings(&self, ray: &Ray) -> SolidCrossings<Vec3, Self::Face> {
            $all(self, ray).into()
        }

        fn crossings_f64(&self, ray: &DRay) -> SolidCrossings<DVec3, Self::Face> {
            $all(self, ray).into()
        }

        fn spawn(&self, ray: &Ray, t: f32, dir: Vec3) -> Result<Ray, RayError> {
            $spawn(self, ray, t, dir)
        }

        fn spawn_f64(&self, ray: &DRay, t: f64, dir: DVec3) -> Result<DRay, DRayError> {
            $spawn(self, ray, t, dir)
        }
    };
}

/// [`Solid`]'s point verbs for a shape whose own `contains`, `signed_distance` and
/// `project_point` answer with an error that converts into [`crate::PointQueryError`].
macro_rules! point_verbs {
    ($shape:ty) => {
        fn contains(&self, p: DVec3) -> Result<bool, PointQueryError> {
            Ok(<$shape>::contains(self, p)?)
        }

        fn signed_distance(&self, p: DVec3) -> Result<f64, PointQueryError> {
            Ok(<$shape>::signed_distance(self, p)?)
        }

        fn project_point(&self, p: DVec3) -> Result<SolidProjection<Self::Face>, PointQueryError> {
            Ok(<$shape>::project_point(self, p)?.into())
        }
    };
}

mod bend;
mod solid;
mod toroid;
mod torus;

pub use solid::Solid;
