//! What `eval` intersects: the circular ring torus (R, r), as it always has, or a member
//! of the torus family ([`Toroid`]: an elliptical tube `--axial b ≠ r`, or a horn or
//! spindle, R ≤ r, whose surface is the apple).
//!
//! The circular ring torus keeps its own path ([`Torus`], the circular oracle, every
//! precision): its rows are byte for byte those of a binary without the family. A family
//! member is answered by [`Toroid::intersect`] (f64 and f32 rays), its culls by
//! [`Toroid::kept_by`] (a cull that does not accept its shape keeps every ray), its
//! oracle column by the family oracle ([`crate::family_label`]), and its `on_surface`
//! origins are checked against its own surface (the family oracle's nearest point). The
//! certified f32 path and the GPU take a [`Torus`]: a family member is refused there ([`Toroid::as_torus`]), the error naming the mode and the shape.
//!
//! **The pipe bend** (`--bore r_min`, `--phi-start φ₀`, `--delta-phi Δφ`): the solid of
//! [`PipeBend::canonical`] (centre 0, axis +y, φ = 0 along +x), answered by
//! [`PipeBend::intersect`] (its nearest crossing of any face), its culls by
//! [`PipeBend::kept_by`] (the torus cull on the outer torus, a whole-line test), its
//! oracle column by the bend oracle ([`crate::oracle::bend::BendQuery`], the on-surface rule for `on_surface`
//! rows), and an `on_surface` origin must lie within [`torus_cull::ON_SURFACE_REL`]·(R +
//! r_max) of a face; `--exact f32` answers it by [`PipeBend::intersect_f32`] (its misses of the outer
//! torus proved in f32, the rest escalated). A whole bend (no bore, Δφ = 2π) is the ring
//! torus, answered as without the flags.
//!
//! **Through the shape interfaces**: the nearest `t` in either precision
//! ([`torus_cull::RayCast`], every shape's), the certified f32 answer
//! ([`Solid::hit_f32_certified`]), the distance of an `on_surface` origin
//! ([`Solid::signed_distance`], the ring torus's and the bend's), the oracle column (each
//! shape's [`LabShape::label`]) and the cull columns ([`form_keeps`]: the interface's
//! `kept_by` per cull form, a bend's wedge forms after the culls). What stays per shape,
//! explicitly: the construction from the flags and their errors, the refusals of the
//! certified and GPU paths, and the family member's on-surface rule (its oracle's nearest
//! point: the interface refuses an elliptical horn's distance). [`super::EvalShape`] is
//! what `eval` asks; any [`LabShape`] answers it as well as a `Target`.

use super::EvalError;
use super::shape::{EvalShape, form_keeps, guard_columns, on_surface_bound};
use crate::check::shapes::bend::PosedBend;
use crate::check::shapes::bend::rays::Spec;
use crate::lab_shape::LabShape;
use crate::number::Num;
use crate::oracle::OracleLabel;
use glam::{DVec3, Vec3};
use torus_cull::bend::PipeBend;
use torus_cull::family::{Toroid, ToroidError};
use torus_cull::{DRay, Precision, Ray, RayCast, Solid, Torus};

/// The torus `eval` answers for.
#[derive(Debug, Clone)]
pub enum Target {
    /// The circular ring torus: R > r, no `--axial` or `--axial` = `--minor`.
    Ring(Torus),
    /// Any other member of the family.
    Family(Toroid),
    /// A pipe bend with a bore or a φ segment, with the parameters its oracle takes
    /// (boxed: it holds two tori).
    Bend(Box<PosedBend>),
}

/// `--bore`, `--phi-start`, `--delta-phi` as given (each `None` when absent).
pub type BendFlags = (Option<f64>, Option<f64>, Option<f64>);

impl Target {
    /// The canonical torus for `--major R --minor r [--axial b]`. The circular ring
    /// torus (b absent or equal to r, and not `0 < R ≤ r`) is [`Torus::canonical`]'s,
    /// with its errors; every other member is [`Toroid::new`]'s, its errors naming the
    /// flags.
    pub fn new(major: f32, minor: f32, axial: Option<f32>) -> Result<Target, EvalError> {
        Target::with_bend(major, minor, axial, (None, None, None))
    }

    /// [`Target::new`], or the pipe bend of `--bore`, `--phi-start` and `--delta-phi`
    /// where any is given (r_min 0, φ₀ 0 and Δφ 2π by default): [`PipeBend::canonical`]'s,
    /// with its errors naming the flags. A whole bend is the ring torus. A bend takes a
    /// circular tube (no `--axial` other than `--minor`).
    pub fn with_bend(
        major: f32,
        minor: f32,
        axial: Option<f32>,
        (bore, start, delta): BendFlags,
    ) -> Result<Target, EvalError> {
        if bore.is_some() || start.is_some() || delta.is_some() {
            if axial.is_some_and(|b| b != minor) {
                return Err(EvalError::Bend(
                    "--axial with --bore/--phi-start/--delta-phi: a pipe bend's tube is \
                     circular (give --axial equal to --minor, or leave it out)"
                        .into(),
                ));
            }
            let bend = PipeBend::canonical(
                f64::from(major),
                bore.unwrap_or(0.0),
                f64::from(minor),
                start.unwrap_or(0.0),
                delta.unwrap_or(std::f64::consts::TAU),
            )
            .map_err(|e| {
                EvalError::Bend(bend_flag_error(
                    &e,
                    (f64::from(major), bore.unwrap_or(0.0), f64::from(minor)),
                ))
            })?;
            if bend.as_torus().is_err() {
                let spec = Spec::canonical(
                    bend.major_radius_f64(),
                    bend.bore_radius_f64(),
                    bend.tube_radius_f64(),
                    bend.start_phi(),
                    bend.delta_phi(),
                );
                return Ok(Target::Bend(Box::new(PosedBend { spec, bend })));
            }
        }
        let circular = axial.is_none_or(|b| b == minor);
        let horn_or_spindle = major > 0.0 && minor > 0.0 && major <= minor;
        if circular && !horn_or_spindle {
            return Torus::canonical(major, minor)
                .map(Target::Ring)
                .map_err(EvalError::Torus);
        }
        Toroid::new(Vec3::ZERO, Vec3::Y, major, minor, axial.unwrap_or(minor))
            .map(Target::Family)
            .map_err(EvalError::Toroid)
    }

    /// The torus the certified f32 path and the GPU take (`mode` names the flag): the
    /// circular ring torus, or an error naming the mode and the member's shape.
    pub fn as_torus(&self, mode: &'static str) -> Result<&Torus, EvalError> {
        match self {
            Target::Ring(torus) => Ok(torus),
            Target::Family(toroid) => toroid.as_torus().map_err(|e| EvalError::Mode {
                mode,
                message: format!(
                    "{} torus (R = {}, a = {}, b = {}): {e}; use --exact f64",
                    kind_name(toroid),
                    toroid.major_radius_f64(),
                    toroid.radial_semi_axis_f64(),
                    toroid.axial_semi_axis_f64()
                ),
            }),
            Target::Bend(posed) => Err(EvalError::Mode {
                mode,
                message: format!(
                    "a pipe bend (R = {}, r_min = {}, r_max = {}, Δφ = {}): {}; use --exact f64",
                    posed.bend.major_radius_f64(),
                    posed.bend.bore_radius_f64(),
                    posed.bend.tube_radius_f64(),
                    posed.bend.delta_phi(),
                    torus_cull::bend::BendError::NotWhole
                ),
            }),
        }
    }

    /// Refuses a target the certified f32 path cannot take (`--exact f32`): a family
    /// member other than the circular ring torus. The ring torus and the pipe bend pass.
    pub fn check_certified_f32(&self) -> Result<(), EvalError> {
        match self {
            Target::Bend(_) => Ok(()),
            _ => self.as_torus("--exact f32").map(|_| ()),
        }
    }

    /// The certified f32 path's nearest `t` and whether it escalated to f64: the shape's
    /// [`Solid::hit_f32_certified`] (the ring torus's `intersect_f32`, the pipe bend's
    /// `PipeBend::intersect_f32`). Any other family member is refused first, by
    /// [`Target::check_certified_f32`]: its certified answer proves nothing in f32.
    pub fn certified_f32(&self, ray: &Ray) -> Result<(Option<f32>, bool), EvalError> {
        Ok(match self {
            Target::Bend(posed) => certified(&posed.bend, ray),
            _ => certified(self.as_torus("--exact f32")?, ray),
        })
    }

    /// The oracle's label of the ray over its range: the literal ray's, or by the
    /// on-surface rule ([`LabShape::label`] of each shape). A line the oracle cannot
    /// answer is an error for its row.
    pub fn oracle(&self, ray: &DRay) -> Result<OracleLabel, String> {
        match self {
            Target::Ring(torus) => torus.label(ray),
            Target::Family(toroid) => toroid.label(ray),
            Target::Bend(posed) => posed.label(ray),
        }
    }

    /// The exact intersection's nearest `t` in range: the shape's own, through the
    /// interface (`Target::caster`).
    pub fn t_hit<P: Precision>(&self, ray: &Ray<P>) -> Option<P::Float> {
        self.caster::<P>().cast_ray(ray)
    }

    /// The shape as the interface's ray caster in the ray's precision: [`RayCast`], which
    /// every [`Solid`] implements for f32 and f64 rays (the torus's `intersect`, the
    /// toroid's and the bend's, the bend's face dropped: eval prints no face). `dyn`, not
    /// generic: one call a row of a text file, untimed, and one match instead of one per
    /// verb; [`Solid`] itself cannot be the object here, its `Face` differing per shape.
    fn caster<P: Precision>(&self) -> &dyn RayCast<Ray<P>> {
        match self {
            Target::Ring(torus) => torus,
            Target::Family(toroid) => toroid,
            Target::Bend(posed) => &posed.bend,
        }
    }

    /// Each of [`torus_cull::CullKind::TIMED`]'s verdicts on the ray (true keeps), in that order; for a
    /// pipe bend then the wedge's, alone and behind each cull but `none`
    /// ([`super::bend_wedge_columns`]), as `bend` and `time` price them: every shape's
    /// through the interface's [`torus_cull::Solid::kept_by`] ([`form_keeps`]).
    pub fn keeps<P: Precision>(&self, ray: &Ray<P>) -> Vec<bool> {
        match self {
            Target::Ring(torus) => form_keeps(torus, ray),
            Target::Family(toroid) => form_keeps(toroid, ray),
            Target::Bend(posed) => form_keeps(posed.as_ref(), ray),
        }
    }

    /// An `on_surface` row's origin must be a surface point: within
    /// [`torus_cull::ON_SURFACE_REL`]·(R + r) of the ring torus's surface, or
    /// [`torus_cull::ON_SURFACE_REL`]·(R + max(a, b)) of a family member's (docs/math.md §9).
    pub fn check_on_surface(&self, origin: DVec3) -> Result<(), String> {
        match self {
            Target::Ring(torus) => on_surface_bound(
                surface_off(torus, origin)?,
                torus.major_radius_f64() + torus.minor_radius_f64(),
                "(R + r)",
            ),
            Target::Family(toroid) => {
                // The family oracle's own nearest surface point, and (E − 1)·min(a, b) for
                // a point it leaves where it is (on the axis, at a cusp): the interface's
                // distance refuses an elliptical horn or spindle.
                let query = crate::family_label::query(
                    toroid,
                    &DRay::new(origin, DVec3::Y).map_err(|e| e.to_string())?,
                );
                let moved = (query.on_surface().origin - origin).length();
                let off = moved.max(query.g(0.0).abs());
                on_surface_bound(off, size(toroid), "(R + max(a, b))")
            }
            Target::Bend(posed) => on_surface_bound(
                surface_off(&posed.bend, origin)?,
                posed.size(),
                "(R + r_max)",
            ),
        }
    }
}

/// `eval`'s questions of the flags' shapes: the methods above, the GPU's and the
/// certified path's refusals named per shape.
impl EvalShape for Target {
    fn check_mode(&self, precision: super::Precision) -> Result<(), EvalError> {
        match precision {
            super::Precision::CertifiedF32 => self.check_certified_f32(),
            super::Precision::CertifiedGpu => self.as_torus("--exact gpu").map(|_| ()),
            _ => Ok(()),
        }
    }

    fn gpu_torus(&self) -> Result<&Torus, EvalError> {
        self.as_torus("--exact gpu")
    }

    fn oracle(&self, ray: &DRay) -> Result<OracleLabel, String> {
        Target::oracle(self, ray)
    }

    fn t_hit_f32(&self, ray: &Ray) -> Option<f32> {
        self.t_hit(ray)
    }

    fn t_hit_f64(&self, ray: &DRay) -> Option<f64> {
        self.t_hit(ray)
    }

    fn certified_f32(&self, ray: &Ray) -> Result<(Option<f32>, bool), EvalError> {
        Target::certified_f32(self, ray)
    }

    fn keeps<P: Precision>(&self, ray: &Ray<P>) -> Vec<bool> {
        Target::keeps(self, ray)
    }

    fn guard_columns(&self) -> Vec<String> {
        match self {
            Target::Bend(posed) => guard_columns(posed.as_ref()),
            _ => Vec::new(),
        }
    }

    fn check_on_surface(&self, origin: DVec3) -> Result<(), String> {
        Target::check_on_surface(self, origin)
    }
}

/// [`Solid::hit_f32_certified`]'s `t` and whether it escalated.
fn certified<S: Solid>(shape: &S, ray: &Ray) -> (Option<f32>, bool) {
    let answer = shape.hit_f32_certified(ray);
    (answer.hit.map(|h| h.t), answer.escalated)
}

/// |[`Solid::signed_distance`]|: how far `origin` lies from the shape's surface (the ring
/// torus's |hypot(ρ − R, y) − r|, the bend's nearest face's).
fn surface_off<S: Solid>(shape: &S, origin: DVec3) -> Result<f64, String> {
    Ok(shape
        .signed_distance(origin)
        .map_err(|e| e.to_string())?
        .abs())
}

/// A bend's error with the flags that gave the values (R, r_min and r_max as the bend
/// took them).
fn bend_flag_error(
    e: &torus_cull::bend::BendError,
    (major, bore, minor): (f64, f64, f64),
) -> String {
    use torus_cull::bend::{BendError, MIN_WALL_REL};
    use torus_cull::{MAX_NU, TorusError};
    match e {
        BendError::Torus {
            which: "bore",
            error: TorusError::TooThin { .. },
        } => format!(
            "--bore {bore} gives the bore's torus nu = --major/--bore = {} above {MAX_NU} \
             (allowed: --bore 0, or --major/{MAX_NU} = {} <= --bore <= --minor - \
             {MIN_WALL_REL:e}*(--major + --minor) = {})",
            major / bore,
            major / MAX_NU,
            minor - MIN_WALL_REL * (major + minor)
        ),
        BendError::Bore {
            bore_radius,
            tube_radius,
        } => format!(
            "--bore {} is invalid (allowed: 0 <= --bore < --minor = {})",
            Num(*bore_radius),
            Num(*tube_radius)
        ),
        BendError::Segment { name, value } => {
            let flag = if *name == "start_phi" {
                "--phi-start"
            } else {
                "--delta-phi"
            };
            format!(
                "{flag} {} is invalid (allowed: --phi-start finite; 0 < --delta-phi <= 2*pi = {})",
                Num(*value),
                std::f64::consts::TAU
            )
        }
        BendError::ThinWall {
            bore_radius,
            tube_radius,
            max_bore_radius,
        } => format!(
            "--bore {bore_radius} leaves a wall --minor - --bore = {:e}, thinner than \
             {:e}*(--major + --minor), the thinnest a pipe bend is tested at (allowed: \
             --bore 0, or 0 < --bore <= {max_bore_radius})",
            tube_radius - bore_radius,
            torus_cull::bend::MIN_WALL_REL
        ),
        // Not the torus's "ring tori only": eval takes horn and spindle tori, a bend
        // alone needs a hole for its tube.
        BendError::Torus {
            error:
                torus_cull::TorusError::NoHole {
                    major_radius,
                    minor_radius,
                },
            ..
        } => format!(
            "--major {} --minor {}: a pipe bend needs R > r_max, the tube's outer radius \
             (allowed: --major > --minor; R <= r_max is a horn or spindle, which eval takes \
             without --bore/--phi-start/--delta-phi)",
            // As typed: --major and --minor are read as f32.
            Num::from(*major_radius as f32),
            Num::from(*minor_radius as f32)
        ),
        other => format!("--major/--minor/--bore: {other}"),
    }
}

/// R + max(a, b): the member's size, the scale of its margins.
pub fn size(toroid: &Toroid) -> f64 {
    toroid.major_radius_f64()
        + toroid
            .radial_semi_axis_f64()
            .max(toroid.axial_semi_axis_f64())
}

/// "elliptical ring", "horn" or "spindle".
fn kind_name(toroid: &Toroid) -> &'static str {
    use torus_cull::family::ToroidKind;
    match toroid.kind() {
        ToroidKind::Ring => "an elliptical ring",
        ToroidKind::Horn => "a horn",
        ToroidKind::Spindle => "a spindle",
    }
}

/// A family member's error with the flags that gave the values: `major_radius` is
/// `--major`, `radial_semi_axis` `--minor`, `axial_semi_axis` `--axial`; the values as
/// the f32 the flags were read as (`0.2`, not its f64 widening).
pub fn flag_error(e: &ToroidError) -> String {
    use torus_cull::family::{MAX_ASPECT, MIN_ASPECT, MIN_FAMILY_NU};
    let f = |v: f64| v as f32;
    match e {
        ToroidError::BadRadius { name, value } => {
            let value = f(*value);
            let flag = match *name {
                "major_radius" => "--major",
                "radial_semi_axis" => "--minor",
                _ => "--axial",
            };
            format!("{flag} {value} is invalid (allowed: a finite number > 0)")
        }
        ToroidError::Aspect {
            radial_semi_axis,
            axial_semi_axis,
        } => format!(
            "--axial {}: --axial / --minor = {} is outside the allowed range \
             {MIN_ASPECT} ..= {MAX_ASPECT} (--minor {}: --axial from {} to {})",
            f(*axial_semi_axis),
            f(axial_semi_axis / radial_semi_axis),
            f(*radial_semi_axis),
            f(MIN_ASPECT * radial_semi_axis),
            f(MAX_ASPECT * radial_semi_axis)
        ),
        ToroidError::TooFat {
            major_radius,
            radial_semi_axis,
        } => format!(
            "--major {}: --major / --minor = {} is below the allowed {MIN_FAMILY_NU} \
             (allowed: {MIN_FAMILY_NU} <= --major / --minor <= {})",
            f(*major_radius),
            f(major_radius / radial_semi_axis),
            torus_cull::MAX_NU
        ),
        other => format!("--major/--minor/--axial: {other}"),
    }
}
