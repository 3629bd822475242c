//! Lines in the torus frame, structure of arrays: what the batch culls read.

use crate::{LocalLine, Ray, Torus};
use glam::Vec3;

/// Lines per block: the batch culls write one `u64` of verdicts per block, and every
/// lane count (1, 2, 4, 8, 16) divides it.
pub const BLOCK: usize = 64;

/// Torus-frame lines `origin + t·dir` as six f32 arrays (x, y, z of origin and
/// direction), the layout SIMD lanes load without shuffling.
///
/// The arrays are padded to a whole [`BLOCK`] with a harmless line (origin 0, direction
/// +x), so the kernels never need a scalar tail; the padding's verdicts are cleared.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Lines {
    len: usize,
    pub(crate) origin: [Vec<f32>; 3],
    pub(crate) dir: [Vec<f32>; 3],
}

impl Lines {
    /// No lines.
    pub fn new() -> Lines {
        Lines::default()
    }

    /// The lines as the culls see them: each ray through [`Torus::line_to_local`] (the
    /// same f32 transform, far origins moved to the foot point in f64), so a batch
    /// verdict can be compared bit for bit with the scalar one.
    pub fn from_rays(torus: &Torus, rays: &[Ray]) -> Lines {
        let mut lines = Lines::new();
        lines.fill_from_rays(torus, rays);
        lines
    }

    /// [`Lines::from_rays`] into this buffer, reusing its memory.
    pub fn fill_from_rays(&mut self, torus: &Torus, rays: &[Ray]) {
        self.clear();
        for ray in rays {
            let line = torus.line_to_local(ray);
            self.push(line.origin, line.dir);
        }
    }

    /// The rays' world origins and directions, untransformed (the first step of
    /// [`Lines::fill_from_rays_batch`]), with whole blocks of padding.
    pub(crate) fn fill_world(&mut self, rays: &[Ray]) {
        self.len = rays.len();
        let padded = rays.len().div_ceil(BLOCK) * BLOCK;
        for (v, pad) in self.origin.iter_mut().zip([0.0, 0.0, 0.0]) {
            v.clear();
            v.resize(padded, pad);
        }
        for (v, pad) in self.dir.iter_mut().zip([1.0, 0.0, 0.0]) {
            v.clear();
            v.resize(padded, pad);
        }
        let n = rays.len();
        // Sliced to the rays' length, so the indexing below needs no bounds checks.
        let [ox, oy, oz] = &mut self.origin;
        let (ox, oy, oz) = (&mut ox[..n], &mut oy[..n], &mut oz[..n]);
        let [dx, dy, dz] = &mut self.dir;
        let (dx, dy, dz) = (&mut dx[..n], &mut dy[..n], &mut dz[..n]);
        for (i, ray) in rays.iter().enumerate() {
            let (o, d) = (ray.origin(), ray.dir());
            (ox[i], oy[i], oz[i]) = (o.x, o.y, o.z);
            (dx[i], dy[i], dz[i]) = (d.x, d.y, d.z);
        }
    }

    /// Overwrites line `i`.
    pub(crate) fn set(&mut self, i: usize, origin: Vec3, dir: Vec3) {
        for k in 0..3 {
            self.origin[k][i] = origin[k];
            self.dir[k][i] = dir[k];
        }
    }

    /// From lines already in the torus frame.
    pub fn from_local(lines: &[LocalLine]) -> Lines {
        let mut out = Lines::new();
        for l in lines {
            out.push(l.origin, l.dir);
        }
        out
    }

    /// Removes every line (keeps the memory).
    pub fn clear(&mut self) {
        self.len = 0;
        for v in self.origin.iter_mut().chain(self.dir.iter_mut()) {
            v.clear();
        }
    }

    /// Appends one line.
    #[inline]
    pub fn push(&mut self, origin: Vec3, dir: Vec3) {
        if self.len == self.origin[0].len() {
            // Open a new block of padding lines; `push` then overwrites them in order.
            for (v, pad) in self.origin.iter_mut().zip([0.0, 0.0, 0.0]) {
                v.resize(v.len() + BLOCK, pad);
            }
            for (v, pad) in self.dir.iter_mut().zip([1.0, 0.0, 0.0]) {
                v.resize(v.len() + BLOCK, pad);
            }
        }
        let i = self.len;
        for (k, (o, d)) in origin
            .to_array()
            .into_iter()
            .zip(dir.to_array())
            .enumerate()
        {
            self.origin[k][i] = o;
            self.dir[k][i] = d;
        }
        self.len += 1;
    }

    /// How many lines.
    #[inline]
    pub fn len(&self) -> usize {
        self.len
    }

    /// No lines.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Line `i`.
    ///
    /// # Panics
    ///
    /// If `i ≥ self.len()`.
    #[must_use]
    pub fn get(&self, i: usize) -> LocalLine {
        assert!(i < self.len, "line {i} of {}", self.len);
        LocalLine {
            origin: Vec3::new(self.origin[0][i], self.origin[1][i], self.origin[2][i]),
            dir: Vec3::new(self.dir[0][i], self.dir[1][i], self.dir[2][i]),
        }
    }

    /// Blocks of [`BLOCK`] lines (the last one padded).
    #[inline]
    pub(crate) fn blocks(&self) -> usize {
        self.origin[0].len() / BLOCK
    }
}

/// Sizes a lane pass's output for `n` lanes (a multiple of [`BLOCK`]): the world normal's
/// three columns per lane, and two bit words (say "hit" and "left undecided") per block.
pub(crate) fn size_lane_output<T: Copy + Default>(
    n: usize,
    normal: &mut [Vec<T>; 3],
    bits: [&mut Vec<u64>; 2],
) {
    for c in normal {
        c.resize(n, T::default());
    }
    for b in bits {
        b.resize(n / BLOCK, 0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pads_to_whole_blocks_and_reads_back() {
        let mut lines = Lines::new();
        assert_eq!(lines.blocks(), 0);
        for i in 0..70 {
            lines.push(
                Vec3::new(i as f32, 1.0, 2.0),
                Vec3::new(0.0, -1.0, i as f32),
            );
        }
        assert_eq!(lines.len(), 70);
        assert_eq!(lines.blocks(), 2);
        assert_eq!(lines.get(69).origin, Vec3::new(69.0, 1.0, 2.0));
        assert_eq!(lines.get(69).dir, Vec3::new(0.0, -1.0, 69.0));
        // The padding is the harmless line.
        assert_eq!(lines.dir[0][70], 1.0);
        lines.clear();
        assert!(lines.is_empty());
        assert_eq!(lines.blocks(), 0);
    }
}
