//! `named_enum!`: one declaration for a lab enum with stable
//! names (the scenes, the workload cases, the printed culls). It writes the enum and its
//! [`torus_cull::Named`] impl (`KIND`, `ALL` in declaration order, `name`) from a table of
//! `Variant = "name"` rows, so a name is written once, beside its variant.

/// Declares an enum and implements [`torus_cull::Named`] for it: `KIND` is the literal after
/// the enum's name, `ALL` lists the variants in the order written, and `name` gives each
/// variant's string.
///
/// ```ignore
/// named_enum! {
///     /// A colour.
///     #[derive(Debug, Clone, Copy, PartialEq)]
///     pub enum Colour: "colour" {
///         /// Red.
///         Red = "red",
///         /// Dark green.
///         DarkGreen = "dark_green",
///     }
/// }
/// ```
macro_rules! named_enum {
    (
        $(#[$meta:meta])*
        $vis:vis enum $name:ident: $kind:literal {
            $($(#[$variant_meta:meta])* $variant:ident = $string:literal,)+
        }
    ) => {
        $(#[$meta])*
        $vis enum $name {
            $($(#[$variant_meta])* $variant,)+
        }

        impl ::torus_cull::Named for $name {
            const KIND: &'static str = $kind;
            const ALL: &'static [$name] = &[$($name::$variant),+];

            fn name(self) -> &'static str {
                match self {
                    $($name::$variant => $string,)+
                }
            }
        }
    };
}

pub(crate) use named_enum;
