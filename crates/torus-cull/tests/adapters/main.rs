//! The adapters (features `parry` and `bevy`): parry's and Bevy's queries answered by the
//! library. One test crate; each module builds with its feature.

#[cfg(feature = "bevy")]
mod bevy;
#[cfg(feature = "parry")]
mod parry;
#[cfg(feature = "parry")]
mod parry_solid;
