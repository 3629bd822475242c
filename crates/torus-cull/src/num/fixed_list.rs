//! The read side of a fixed-capacity list: the solver's roots, the torus's and every
//! solid's crossings and spans each hold their items in an array and a length, no
//! allocation. [`fixed_list!`] writes that side once (as a lane macro writes the same
//! operations for both precisions), so the five lists cannot drift apart in what they
//! offer or in their inlining.

/// For a list type `$list` whose items are `$field[..self.len]`: `as_slice` (its docs
/// given first), `iter`, `len`, `is_empty`, and `for item in &list`. The generic
/// parameters come in brackets, as they stand after `impl`; `$what` names the items in
/// the docs.
macro_rules! fixed_list {
    (
        $(#[$as_slice_doc:meta])*
        impl[$($generics:tt)*] $list:ty, $field:ident: [$item:ty], $what:literal
    ) => {
        impl<$($generics)*> $list {
            $(#[$as_slice_doc])*
            #[inline]
            #[must_use]
            pub fn as_slice(&self) -> &[$item] {
                &self.$field[..self.len]
            }

            #[doc = concat!("The ", $what, " by reference, in order (`for x in &list` says the same).")]
            #[inline]
            pub fn iter(&self) -> std::slice::Iter<'_, $item> {
                self.as_slice().iter()
            }

            #[doc = concat!("How many ", $what, ".")]
            #[inline]
            #[must_use]
            pub fn len(&self) -> usize {
                self.len
            }

            #[doc = concat!("No ", $what, " at all.")]
            #[inline]
            #[must_use]
            pub fn is_empty(&self) -> bool {
                self.len == 0
            }
        }

        impl<'a, $($generics)*> IntoIterator for &'a $list {
            type Item = &'a $item;
            type IntoIter = std::slice::Iter<'a, $item>;
            fn into_iter(self) -> Self::IntoIter {
                self.iter()
            }
        }
    };
}

pub(crate) use fixed_list;
