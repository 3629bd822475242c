//! The solver's common path on lanes: the nearest root of a depressed quartic per lane,
//! the scalar solver's steps (the resolvent's greatest root, Ferrari's split, the
//! nearest-root pick) on any [`crate::num::Real`], with the rare careful cases flagged for
//! the scalar solver instead of taken.

mod nearest;
mod resolvent;

pub(crate) use nearest::nearest_root;
