//! The batch culls' answer: one keep bit per line.

use super::lines::BLOCK;

/// Bit `i` is set when the cull keeps line `i` (run the quartic); clear means a proven
/// miss. One `u64` per [`BLOCK`] of lines; bits past [`KeepMask::len`] are always clear.
///
/// A bit mask, not a `Vec<bool>`: a batch cull's arithmetic is shared by all the lanes of
/// a register, so a byte store per line would be of the same order as the cull itself,
/// where a block's verdicts are one `u64`; and the survivors are found a word at a time
/// ([`KeepMask::kept`], the compaction step of a wavefront).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct KeepMask {
    len: usize,
    pub(crate) words: Vec<u64>,
}

impl KeepMask {
    /// An empty mask.
    pub fn new() -> KeepMask {
        KeepMask::default()
    }

    /// Sizes the mask for `len` lines (contents unspecified until a cull writes them).
    pub(crate) fn resize(&mut self, len: usize) {
        self.len = len;
        self.words.resize(len.div_ceil(BLOCK), 0);
    }

    /// Clears the bits past `len` in the last word.
    pub(crate) fn clear_tail(&mut self) {
        let rem = self.len % BLOCK;
        if rem != 0 {
            if let Some(last) = self.words.last_mut() {
                *last &= (1u64 << rem) - 1;
            }
        }
    }

    /// Lines covered.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Covers no line.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Whether line `i` is kept.
    ///
    /// # Panics
    ///
    /// If `i ≥ self.len()`.
    #[inline]
    #[must_use]
    pub fn get(&self, i: usize) -> bool {
        assert!(i < self.len, "line {i} of {}", self.len);
        self.words[i / BLOCK] >> (i % BLOCK) & 1 == 1
    }

    /// Kept lines.
    pub fn count_kept(&self) -> usize {
        self.words.iter().map(|w| w.count_ones() as usize).sum()
    }

    /// The indices of the kept lines, ascending: a word at a time, one `trailing_zeros`
    /// per survivor, no branch per rejected line.
    pub fn kept(&self) -> impl Iterator<Item = usize> + '_ {
        set_bits(&self.words, self.len)
    }

    /// The verdicts as booleans (for tests and reports).
    pub fn to_vec(&self) -> Vec<bool> {
        (0..self.len).map(|i| self.get(i)).collect()
    }
}

/// The indices below `len` of the set bits of `words` (bit i of word w is index
/// w·64 + i), ascending: the one set-bit walk of batch mode (kept lines, hit lanes,
/// lanes handed to the scalar solver).
pub(crate) fn set_bits(words: &[u64], len: usize) -> impl Iterator<Item = usize> + '_ {
    words
        .iter()
        .enumerate()
        .flat_map(|(w, &word)| {
            let mut bits = word;
            std::iter::from_fn(move || {
                (bits != 0).then(|| {
                    let i = bits.trailing_zeros() as usize;
                    bits &= bits - 1;
                    w * BLOCK + i
                })
            })
        })
        .take_while(move |&i| i < len)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kept_lists_the_set_bits_and_the_tail_is_cleared() {
        let mut m = KeepMask::new();
        m.resize(70);
        m.words[0] = 0b1001;
        m.words[1] = u64::MAX;
        m.clear_tail();
        assert_eq!(m.words[1], 0b11_1111);
        let kept: Vec<usize> = m.kept().collect();
        assert_eq!(kept, vec![0, 3, 64, 65, 66, 67, 68, 69]);
        assert_eq!(m.count_kept(), 8);
        assert!(m.get(3) && !m.get(4) && m.get(69));
    }
}
