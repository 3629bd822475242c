//! **The one table of culls.** Every list of culls in the crate comes from these rows:
//! [`super::CullKind`] (every cull, its stable name, [`super::CullKind::TIMED`]),
//! [`super::BatchCull`] and [`super::BATCHED`] (the culls with a lane form), the GPU's
//! `GpuCull` (the culls with a WGSL function), the conversions between them and the
//! dispatch from an enum to the cull's type.
//!
//! A row is `Variant "name" module::Type [forms] [shapes], "doc"` (`module`: the cull's
//! file in `cull/`, declared from the row, one row a file); each enum names the cull by the same variant, and the type is
//! re-exported from `cull` and the crate root by [`export_culls`]:
//! - `lanes`: the type is also a [`super::kernel::CullKernel`] and runs in the batch
//!   paths;
//! - `gpu`: the WGSL module has its function (a test checks that every GPU row has one);
//! - `shapes`: the tori the cull accepts (today the ring torus only); a shape issue adds
//!   to this column, not a second table.
//!
//! Adding a cull: a row here, its kernel (its own file in `cull/`), and, where it has a
//! GPU form, its WGSL function (docs/layout.md, "Adding a cull").

/// Calls `$then! { rows }` with the table's rows (module docs).
macro_rules! cull_table {
    ($then:ident $(@$arm:ident)?) => {
        $then! { $(@$arm)?
            NoCull "none" none::NoCull [lanes gpu] [Ring Elliptic Spindle],
                "No test: always run the quartic (the baseline), [`crate::NoCull`]; named `none`.";
            Sphere "sphere" sphere::SphereCull [lanes gpu] [Ring Elliptic Spindle],
                "Bounding sphere of radius R + r.";
            Aabb "aabb" aabb::AabbCull [lanes gpu] [Ring Elliptic Spindle],
                "The torus's box [−(R+r), R+r] × [−r, r] × [−(R+r), R+r].";
            Cychosz "cychosz" cychosz::CychoszCull [lanes gpu] [Ring Elliptic Spindle],
                "Cychosz (Graphics Gems II, 1991): sphere R + r, then the slab |y| ≤ r at the chord ends.";
            ThickCylinder "thick_cylinder" thick_cylinder::ThickCylinderCull [lanes gpu] [Ring Elliptic Spindle],
                "The shell R − r ≤ ρ ≤ R + r, |y| ≤ r (POV-Ray's `Test_Thick_Cylinder`).";
            Skala "skala" skala::SkalaCull [lanes gpu] [Ring Elliptic Spindle],
                "Skala's circle-based test, with the paper's misprints corrected.";
            Ellipsoid "ellipsoid" ellipsoid::EllipsoidCull [lanes gpu] [Ring Elliptic Spindle],
                "Cychosz with the sphere replaced by the outer ellipsoid ρ² + (ν + 1)·y² ≤ (R + r)².";
            Quadric "quadric" quadric::QuadricCull [lanes gpu] [Ring Elliptic Spindle],
                "The outer ellipsoid ∩ the slab ∩ the inner hyperboloid ρ² − (ν − 1)·y² ≥ (R − r)².";
            Discriminant "discriminant" discriminant::DiscriminantCull [lanes gpu] [Ring Elliptic],
                "The quartic's real-root classification (no root, no branch), in f32.";
            DiscriminantF64 "discriminant_f64" discriminant_f64::DiscriminantF64Cull [] [Ring Elliptic],
                "The same classification evaluated in f64.";
        }
    };
}
pub(crate) use cull_table;

/// The shapes of the torus family a cull may accept (the table's `shapes` column).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Shape {
    /// The ring torus: a circular tube, R > r.
    Ring,
    /// A ring torus with an elliptical tube (semi-axes a ≠ b, R > a): culled as the
    /// circular torus (R, a) on the line with y scaled by a/b (`crate::family`).
    Elliptic,
    /// A horn or spindle torus (R ≤ a, either tube): the apple, culled as its circular
    /// image (R, a), whose padded bounds hold the apple. The two `discriminant` culls do
    /// not take it: their padding argument (a hitting line keeps real roots under a
    /// rounding smaller than the padding η) fails on the axis, which meets the quartic
    /// of every padded image (R, a + η) in double roots at the cusps (the horn's centre),
    /// the boundary Δ = 0, S = P² of their "no real root" set; lines down a spindle's axis
    /// were rejected while they crossed the solid (docs/family.md).
    Spindle,
}

/// The cull types, re-exported where the crate makes them public: `export_culls!(cull)`
/// in `cull` (from each cull's module), `export_culls!(root)` at the crate root (from
/// `cull`); `export_culls!(modules)` declares each row's module in `cull`. A new row is
/// declared and exported with no line to add.
macro_rules! export_culls {
    (modules) => { $crate::cull::table::cull_table!(export_culls @modules); };
    (cull) => { $crate::cull::table::cull_table!(export_culls @cull); };
    (root) => { $crate::cull::table::cull_table!(export_culls @root); };
    // (`export_culls` must be in scope where it is called: `cull_table!` calls it back by
    // name.)
    (@cull $(
        $kind:ident $name:literal $module:ident :: $ty:ident
        [$($forms:ident)*] [$($shape:ident)*], $doc:literal;
    )*) => {
        $(pub use self::$module::$ty;)*
    };
    (@root $(
        $kind:ident $name:literal $module:ident :: $ty:ident
        [$($forms:ident)*] [$($shape:ident)*], $doc:literal;
    )*) => {
        $(pub use crate::cull::$ty;)*
    };
    // Each row's module, `cull/<module>.rs` (one cull type a file, so no module twice).
    (@modules $(
        $kind:ident $name:literal $module:ident :: $ty:ident
        [$($forms:ident)*] [$($shape:ident)*], $doc:literal;
    )*) => {
        $(mod $module;)*
    };
}
pub(crate) use export_culls;

/// `CullKind` and `BatchCull`, their lists, names, conversions and dispatch, from the
/// rows of [`cull_table`].
macro_rules! define_culls {
    ($(
        $kind:ident $name:literal $module:ident :: $ty:ident
        [$($lanes:ident $($gpu:ident)?)?] [$($shape:ident)*], $doc:literal;
    )*) => {
        /// Every cull by name: the registry.
        ///
        /// A cull chosen at run time (from a results file, the command line, a setting)
        /// is a `CullKind`; it is a [`Cull`] itself, and [`CullKind::visit`] hands
        /// generic code the concrete cull type instead. The names are stable
        /// ([`Named`]): they are what results files record.
        ///
        /// ```
        /// use torus_cull::{CullKind, Named, Ray, Torus, intersect_culled};
        /// use glam::Vec3;
        ///
        /// let kind: CullKind = "skala".parse()?;
        /// assert_eq!(kind, CullKind::Skala);
        /// assert_eq!(kind.to_string(), "skala");
        /// assert_eq!(CullKind::NoCull.name(), "none"); // the baseline: no test at all
        /// assert!("donut".parse::<CullKind>().is_err());
        ///
        /// let torus = Torus::new(Vec3::ZERO, Vec3::Y, 4.0, 1.0)?;
        /// let hole = Ray::new(Vec3::new(0.5, 10.0, 0.0), Vec3::NEG_Y)?; // down the hole
        /// let line = torus.line_to_local(&hole);
        /// assert!(!kind.keeps(torus.bounds(), line.origin, line.dir)); // a proven miss
        /// assert!(CullKind::NoCull.keeps(torus.bounds(), line.origin, line.dir)); // keeps all
        ///
        /// // Every cull gives the same answer; they differ in how many quartics they spare.
        /// for kind in CullKind::TIMED {
        ///     assert_eq!(intersect_culled(&kind, &torus, &hole), None, "{kind}");
        /// }
        /// # Ok::<(), Box<dyn std::error::Error>>(())
        /// ```
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum CullKind {
            $(#[doc = $doc] $kind,)*
        }

        impl CullKind {
            /// Every cull, in table order (the order of results and plots).
            pub const TIMED: [CullKind; [$($name),*].len()] = [$(CullKind::$kind),*];

            /// Hands the concrete cull to `visitor`, so generic code is monomorphized per
            /// cull.
            pub fn visit<V: CullVisitor>(self, visitor: V) -> V::Output {
                match self {
                    $(CullKind::$kind => visitor.visit(crate::cull::$ty),)*
                }
            }

            /// This cull's batch form, or `None` for a cull without one
            /// (`discriminant_f64`).
            pub const fn batched(self) -> Option<BatchCull> {
                match self {
                    $(CullKind::$kind => define_culls!(@some $(BatchCull::$kind, $lanes)?),)*
                }
            }

            /// The shapes of the torus family this cull accepts.
            pub const fn shapes(self) -> &'static [Shape] {
                match self {
                    $(CullKind::$kind => &[$(Shape::$shape),*],)*
                }
            }

            /// Whether this cull is proved conservative for `shape` ([`CullKind::shapes`]).
            pub fn accepts(self, shape: Shape) -> bool {
                self.shapes().contains(&shape)
            }

            /// Whether this cull has a function in the GPU kernel.
            pub const fn has_gpu_form(self) -> bool {
                match self {
                    $(CullKind::$kind => define_culls!(@has $($($gpu)?)?),)*
                }
            }
        }

        $(
            impl crate::cull::$ty {
                /// The shapes of the torus family this cull accepts (its row's `shapes`).
                pub const SHAPES: &'static [Shape] = &[$(Shape::$shape),*];
            }
        )*

        /// The registry by stable name: `"skala".parse::<CullKind>()`, `format!("{kind}")`.
        impl Named for CullKind {
            const KIND: &'static str = "cull";
            const ALL: &'static [CullKind] = &CullKind::TIMED;

            fn name(self) -> &'static str {
                match self {
                    $(CullKind::$kind => $name,)*
                }
            }
        }

        /// The culls with a batch form ([`crate::batch::cull_batch`], the
        /// [`crate::batch::Wavefront`]): every [`CullKind`] but `discriminant_f64`, whose
        /// point is the f64 evaluation, which the f32 `discriminant` already makes
        /// unnecessary at this padding. The batch API takes a `BatchCull`, so a cull
        /// without a batch form is refused when the program is compiled, not when it
        /// runs; [`CullKind::batched`] converts a cull chosen at run time.
        ///
        /// ```
        /// use torus_cull::batch::{BATCHED, BatchCull};
        /// use torus_cull::{CullKind, Named};
        ///
        /// assert_eq!(CullKind::Skala.batched(), Some(BatchCull::Skala));
        /// assert_eq!(CullKind::DiscriminantF64.batched(), None);
        /// assert_eq!(CullKind::from(BatchCull::Skala), CullKind::Skala);
        /// // The same stable names as the scalar culls, in the same table order.
        /// assert_eq!(BatchCull::Quadric.name(), "quadric");
        /// assert_eq!(BATCHED.len(), CullKind::TIMED.len() - 1);
        /// let err = BatchCull::parse("discriminant_f64").unwrap_err().to_string();
        /// assert!(err.starts_with("unknown batched cull 'discriminant_f64' (allowed: none, "));
        /// ```
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum BatchCull {
            $($(#[doc = $doc] #[cfg_attr(any(), doc = stringify!($lanes))] $kind,)?)*
        }

        /// Every [`BatchCull`], in [`CullKind::TIMED`] order.
        pub const BATCHED: [BatchCull; [$($(stringify!($lanes),)?)*].len()] =
            [$($(define_culls!(@pick BatchCull::$kind, $lanes),)?)*];

        impl BatchCull {
            /// The same cull in the registry of every cull.
            pub const fn kind(self) -> CullKind {
                match self {
                    $($(define_culls!(@pick BatchCull::$kind, $lanes) => CullKind::$kind,)?)*
                }
            }

            /// Hands the cull's one-source kernel to `visitor`.
            pub(crate) fn visit_kernel<V: KernelVisitor>(self, visitor: V) -> V::Output {
                match self {
                    $($(define_culls!(@pick BatchCull::$kind, $lanes) => visitor.visit(crate::cull::$ty),)?)*
                }
            }
        }
    };
    (@some $value:path, $flag:ident) => { Some($value) };
    (@some) => { None };
    // A variant of a row that has the form `$flag`: the flag only selects the row.
    (@pick $value:path, $flag:ident) => { $value };
    (@has $gpu:ident) => { true };
    (@has) => { false };
}
pub(crate) use define_culls;

/// The GPU kernel's `GpuCull` from the rows of [`cull_table`] that have a `gpu` form.
#[cfg(feature = "gpu")]
macro_rules! define_gpu_culls {
    ($(
        $kind:ident $name:literal $module:ident :: $ty:ident
        [$($lanes:ident $($gpu:ident)?)?] [$($shape:ident)*], $doc:literal;
    )*) => {
        /// The cull the kernel runs before the intersection (a rejected ray is a miss):
        /// every cull with a GPU form in the table of culls, the CPU's math on the torus
        /// padded by the GPU's margin (the CPU's η plus the kernel's line error; see the
        /// module doc and docs/math.md, "The GPU's culls").
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        #[non_exhaustive]
        pub enum GpuCull {
            $($($(#[doc = $doc] #[cfg_attr(any(), doc = stringify!($gpu))] $kind,)?)?)*
        }

        impl GpuCull {
            /// Every cull, in [`CullKind::TIMED`] order (the kernel's codes 0, 1, …).
            pub const ALL: [GpuCull; [$($($(stringify!($gpu),)?)?)*].len()] =
                [$($($(define_gpu_culls!(@pick GpuCull::$kind, $gpu),)?)?)*];

            /// The same cull in the registry of every cull.
            pub const fn kind(self) -> CullKind {
                match self {
                    $($($(define_gpu_culls!(@pick GpuCull::$kind, $gpu) => CullKind::$kind,)?)?)*
                }
            }

            /// The same cull's batch form on the CPU.
            pub const fn batched(self) -> BatchCull {
                match self.kind().batched() {
                    Some(cull) => cull,
                    None => panic!("every GPU cull has a batch form"),
                }
            }
        }

        /// A [`CullKind`] on the GPU: every one with a GPU form.
        impl TryFrom<CullKind> for GpuCull {
            type Error = CullKind;

            fn try_from(kind: CullKind) -> Result<GpuCull, CullKind> {
                match kind {
                    $($($(CullKind::$kind => Ok(define_gpu_culls!(@pick GpuCull::$kind, $gpu)),)?)?)*
                    #[allow(unreachable_patterns)]
                    other => Err(other),
                }
            }
        }
    };
    (@pick $value:path, $flag:ident) => { $value };
}
#[cfg(feature = "gpu")]
pub(crate) use define_gpu_culls;

#[cfg(test)]
mod tests {
    use super::Shape;
    use crate::CullKind;

    // That BATCHED lists the timed culls with a lane form is registry.rs's test.
    #[test]
    fn the_lists_follow_the_table() {
        for kind in CullKind::TIMED {
            // Every cull runs on the elliptical tube's image line (crate::family).
            assert!(
                kind.accepts(Shape::Ring) && kind.accepts(Shape::Elliptic),
                "{kind}"
            );
            // Today every cull with a lane form has a GPU form, and only those.
            assert_eq!(kind.has_gpu_form(), kind.batched().is_some(), "{kind}");
        }
    }
}
