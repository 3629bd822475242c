//! The words of the f64 finish pass's records: what the host asks of it for a ray
//! ([`Instruction`], word 7 going in) and what it did ([`Status`], word 7 coming out), with
//! the names the generated WGSL header gives them.

/// A `#[repr(u32)]` enum of a finished record's word 7, with `ALL` (every variant, in
/// order) and `name` (its constant's name) for the generated header
/// (`TORUS_F64_<NAME>`).
macro_rules! word_enum {
    (
        $(#[$doc:meta])*
        enum $name:ident {
            $($(#[$vdoc:meta])* $variant:ident = $code:literal => $header:literal,)*
        }
    ) => {
        $(#[$doc])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq)]
        #[repr(u32)]
        pub(crate) enum $name {
            $($(#[$vdoc])* $variant = $code,)*
        }

        impl $name {
            /// Every value, for the generated header (`TORUS_F64_<NAME>`).
            pub(crate) const ALL: [$name; [$($code),*].len()] = [$($name::$variant),*];

            /// The header's name.
            pub(crate) fn name(self) -> &'static str {
                match self {
                    $($name::$variant => $header,)*
                }
            }
        }
    };
}

word_enum! {
    /// What the host asks of the pass for one ray (word 7 of its finished record).
    enum Instruction {
        /// Finish it where the f32 kernel escalated it.
        Follow = 0 => "FOLLOW",
        /// Finish it whatever the f32 kernel wrote (an origin the host did not send).
        Always = 1 => "ALWAYS",
        /// The host answers it (a range f32 cannot clip, or an answer the host already
        /// has).
        Host = 2 => "HOST",
        /// A ray from a surface point ([`crate::Ray::from_surface`]): finish it, its own root
        /// divided out, where the f32 kernel escalated its literal ray.
        SurfaceFollow = 3 => "SURFACE_FOLLOW",
        /// A ray from a surface point the host did not send (it goes into the tube, or its
        /// origin is far): finish it whatever the kernel wrote.
        SurfaceAlways = 4 => "SURFACE_ALWAYS",
    }
}

word_enum! {
    /// What the pass did with one ray (word 7 of its finished record).
    enum Status {
        /// The f32 kernel proved it; the pass did nothing.
        Proved = 0 => "STATUS_PROVED",
        /// A hit from the outside (`d·n < 0`).
        Front = 1 => "STATUS_FRONT",
        /// A hit from the inside of the solid, or exactly tangent.
        Back = 2 => "STATUS_BACK",
        /// No hit in range.
        Miss = 3 => "STATUS_MISS",
        /// Handed back to the host.
        Host = 4 => "STATUS_HOST",
    }
}

impl Status {
    pub(crate) fn of(word: f32) -> Option<Status> {
        Status::ALL.into_iter().find(|s| *s as u32 as f32 == word)
    }
}
