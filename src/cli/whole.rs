//! Whole-number flags as typed, negative ones included: [`Whole`].
//!
//! Clap reads `--threads -1` as a flag `-1` ("unexpected argument '-1' found") and a
//! `usize` flag's `-1` as "invalid digit found in string": neither names the range. So
//! `main` lets every flag take a leading '-' ([`negative_numbers`]), the whole-number
//! flags are parsed as a [`Whole`] (i128: every u64 and every negative number fits), and
//! each flag's own range check ([`Whole::within`]) answers with its name and range.

use std::fmt;
use std::str::FromStr;

/// A whole number as typed on the command line (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Whole(pub i128);

impl FromStr for Whole {
    type Err = String;

    fn from_str(s: &str) -> Result<Whole, String> {
        s.parse().map(Whole).map_err(|_| {
            format!(
                "'{}' is not a whole number",
                torus_cull_lab::number::Echo(s)
            )
        })
    }
}

impl fmt::Display for Whole {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.0)
    }
}

impl Whole {
    /// The value as a `T` in `lo ..= hi`, else `--FLAG V is invalid (allowed: lo ..= hi)`
    /// with `more` after the range (e.g. `; leave it out for …`).
    pub fn within<T>(self, flag: &str, (lo, hi): (T, T), more: &str) -> Result<T, String>
    where
        T: TryFrom<i128> + TryInto<i128> + Copy + fmt::Display,
    {
        // Every usize, u64 and u32 fits in i128: the fallbacks are never taken.
        let (l, h) = (
            lo.try_into().unwrap_or(i128::MIN),
            hi.try_into().unwrap_or(i128::MAX),
        );
        match T::try_from(self.0) {
            Ok(v) if (l..=h).contains(&self.0) => Ok(v),
            _ => Err(format!(
                "{flag} {} is invalid (allowed: {lo} ..= {hi}{more})",
                self.0
            )),
        }
    }

    /// A `--seed`: any u64.
    pub fn seed(self, flag: &str) -> Result<u64, String> {
        self.within(flag, (0, u64::MAX), "")
    }
}

/// `command` with every flag that takes a value accepting a leading '-' where the value
/// is a number, so that `-1` reaches the flag's range check (module docs): one setting
/// for every subcommand, not one per flag.
pub fn negative_numbers(command: clap::Command) -> clap::Command {
    // At every depth: `time gpu --workgroup -1` as `run --threads -1`.
    command.mut_subcommands(|sub| {
        negative_numbers(sub).mut_args(|arg| {
            if arg.get_action().takes_values() {
                arg.allow_negative_numbers(true)
            } else {
                arg
            }
        })
    })
}

#[cfg(test)]
mod tests {
    use super::Whole;

    #[test]
    fn a_negative_or_huge_value_names_the_flag_and_the_range() {
        let threads = |s: &str| {
            s.parse::<Whole>()
                .unwrap()
                .within("--threads", (1usize, 1024), "")
        };
        assert_eq!(threads("8"), Ok(8));
        assert_eq!(
            threads("-1"),
            Err("--threads -1 is invalid (allowed: 1 ..= 1024)".into())
        );
        assert!(threads("99999999999999999999999").is_err());
        assert_eq!(
            Whole(-1).seed("--seed").unwrap_err(),
            "--seed -1 is invalid (allowed: 0 ..= 18446744073709551615)"
        );
        assert_eq!(Whole(i128::from(u64::MAX)).seed("--seed"), Ok(u64::MAX));
        assert!("1.5".parse::<Whole>().is_err());
    }
}
