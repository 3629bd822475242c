//! The wire format between the host and the kernel: the bytes of a ray and of a result
//! record, the parameter block's size, the result codes and the kernel's mode.

/// Bytes per ray, in and out: two `vec4<f32>` each.
pub(crate) const RAY_BYTES: u64 = 32;

/// Bytes per ray of the surface records (`TorusSurfaceRay`, four `vec4<f32>`): the cubic
/// of a ray from a surface point, formed on the host in f64 ([`super::frame::Frame::prepare`]).
pub(crate) const SURFACE_BYTES: u64 = 64;

/// `TorusSurfaceRay.start.w`: what the record holds. A literal ray (not from a surface
/// point, or one the host sends as its literal ray past the origin's root) has none.
pub(crate) const SURFACE_NONE: f32 = 0.0;
/// The cubic, and no literal start past the origin's root to fall back on.
pub(crate) const SURFACE_CUBIC: f32 = 1.0;
/// The cubic, and the literal start in `start.z` to fall back on.
pub(crate) const SURFACE_CUBIC_AND_START: f32 = 2.0;

/// Size of the parameter block (`Params` in the kernel): eight 16-byte rows, the module's
/// `TorusParams` (seven) and the kernel's `config`.
pub(crate) const PARAMS_BYTES: u64 = 128;

/// The module's result code (`TorusHit.code`, `TORUS_MISS`): a proved miss, or the cull
/// rejected the ray.
pub(crate) const CODE_MISS: u32 = 0;
/// `TORUS_HIT`: a proved hit.
pub(crate) const CODE_HIT: u32 = 1;
/// `TORUS_ESCALATE`: not proved; `why` says which step.
pub(crate) const CODE_ESCALATE: u32 = 2;
/// `TORUS_KEPT`: the cull alone kept the ray's line.
pub(crate) const CODE_KEPT: u32 = 3;

/// What the kernel does per ray (`Params.config.z`; `config.w` is 1 where the dispatch's
/// surface records are to be read).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Mode {
    /// The cull, then the certified intersection.
    Intersect = 0,
    /// The cull alone: code 0 rejected, 3 kept.
    CullOnly = 1,
}

/// The result records `(t, n.xyz, code, why, 0, 0)` of mapped result bytes.
pub(crate) fn decode_records(bytes: &[u8]) -> impl Iterator<Item = [f32; 8]> + '_ {
    bytes.chunks_exact(RAY_BYTES as usize).map(|record| {
        std::array::from_fn(|k| {
            f32::from_le_bytes(record[4 * k..4 * k + 4].try_into().expect("4 bytes"))
        })
    })
}

/// `words` as little-endian bytes, as the kernel's buffers hold them.
pub(crate) fn as_bytes(words: &[f32]) -> Vec<u8> {
    words.iter().flat_map(|w| w.to_le_bytes()).collect()
}
