//! World rays to torus-frame lines on f32 lanes: [`crate::Torus::line_to_local`] for a
//! whole batch, bit for bit.
//!
//! The near case of `line_to_local` is `R·(o − c)` and `R·d` with R the f32 rotation,
//! which glam evaluates as `(x_axis·v.x + y_axis·v.y) + z_axis·v.z`; the kernel does the
//! same on lanes. A lane whose origin lies farther than `NEAR_ORIGIN_REL`·(R + r) from the
//! centre (or whose square is not finite) takes the scalar f64 foot-point path instead,
//! exactly as the scalar code decides.

use super::lines::{BLOCK, Lines};
use super::mask::KeepMask;
use crate::num::F32s;
use crate::num::Vec3s;
use crate::{Ray, Torus};
use glam::{Mat3, Vec3};
use pulp::{Simd, WithSimd};

impl Lines {
    /// [`Lines::from_rays`] on SIMD lanes at the level `dispatch`: the same lines, bit for
    /// bit, into this buffer (its memory reused).
    pub fn fill_from_rays_batch(
        &mut self,
        dispatch: &super::Dispatch,
        torus: &Torus,
        rays: &[Ray],
    ) {
        self.fill_world(rays);
        // The lines whose origin is too far for the f32 rotation, a bit each.
        let mut far = KeepMask::new();
        far.resize(self.len());
        dispatch.run(ToLocal {
            lines: self,
            center: torus.center(),
            rotation: torus.to_local_rotation(),
            near_sq: torus.near_origin_sq(),
            far: &mut far.words,
        });
        far.clear_tail();
        for i in far.kept() {
            let line = torus.line_to_local(&rays[i]);
            self.set(i, line.origin, line.dir);
        }
    }
}

/// The in-place transform kernel.
struct ToLocal<'a> {
    lines: &'a mut Lines,
    center: Vec3,
    rotation: Mat3,
    near_sq: f32,
    far: &'a mut [u64],
}

impl WithSimd for ToLocal<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: Simd>(self, s: S) {
        let lanes = S::F32_LANES;
        let ToLocal {
            lines,
            center,
            rotation,
            near_sq,
            far,
        } = self;
        let (c, x_axis, y_axis, z_axis) = (
            Vec3s::splat(s, center),
            Vec3s::splat(s, rotation.x_axis),
            Vec3s::splat(s, rotation.y_axis),
            Vec3s::splat(s, rotation.z_axis),
        );
        // A macro, not a closure: a closure that LLVM leaves outlined would run without
        // the SIMD target features and call every intrinsic out of line.
        macro_rules! rotate {
            ($v:expr) => {{
                let v: Vec3s<S> = $v;
                x_axis * v.x + y_axis * v.y + z_axis * v.z
            }};
        }
        let near = F32s::splat(s, near_sq);
        for (block, word) in far.iter_mut().enumerate() {
            let mut bits = 0u64;
            // The last block stops at the register holding the last line.
            for k in (0..BLOCK.min(lines.len() - block * BLOCK)).step_by(lanes) {
                let at = block * BLOCK + k..block * BLOCK + k + lanes;
                let [ox, oy, oz] = &mut lines.origin;
                let origin = Vec3s::new(
                    F32s::load(s, &ox[at.clone()]),
                    F32s::load(s, &oy[at.clone()]),
                    F32s::load(s, &oz[at.clone()]),
                );
                let relative = origin - c;
                bits |= (!relative.length_squared().le(near)).bits() << k;
                let o = rotate!(relative);
                o.x.store(&mut ox[at.clone()]);
                o.y.store(&mut oy[at.clone()]);
                o.z.store(&mut oz[at.clone()]);
                let [dx, dy, dz] = &mut lines.dir;
                let dir = Vec3s::new(
                    F32s::load(s, &dx[at.clone()]),
                    F32s::load(s, &dy[at.clone()]),
                    F32s::load(s, &dz[at.clone()]),
                );
                let d = rotate!(dir);
                d.x.store(&mut dx[at.clone()]);
                d.y.store(&mut dy[at.clone()]);
                d.z.store(&mut dz[at.clone()]);
            }
            *word = bits;
        }
    }
}
