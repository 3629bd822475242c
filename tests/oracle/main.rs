//! The exact intersection and every cull against the independent f64 oracle: adversarial
//! lines, structured grids, every scale and ν, rays from a surface point, crossings for
//! CSG.
//!
//! One test crate (one link step); each module was its own crate before.

#[path = "../common/mod.rs"]
mod common;

mod adversarial;
mod bend;
mod capture;
mod conservative;
mod errata;
mod f64_rays;
mod family;
mod family_points;
mod family_spindle;
mod generators;
mod intersect_adversarial;
mod intersect_all;
mod intersect_vs_oracle;
mod limits;
mod nu_limit;
mod point_queries;
mod properties;
mod saddle_rays;
mod secondary_rays;
mod thin_wall;
