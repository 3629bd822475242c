//! The [`crate::Solid`] interface implemented by the library's three shapes, one file per
//! shape, each verb delegating to the shape's own method or free function (which stay as
//! they are): [`crate::Torus`] (`torus.rs`), [`crate::family::Toroid`] (`toroid.rs`),
//! [`crate::bend::PipeBend`] (`bend.rs`); with `From` conversions from each shape's own
//! answer types to the interface's, and [`crate::RayCast`] for each shape and for each
//! shape behind a cull ([`crate::Culled`]).

mod bend;
mod toroid;
mod torus;
