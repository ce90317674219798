//! Names of the vocabulary the CLI and the Python package share (discrepancy kinds and
//! methods, battery levels): one error type for a name that is not one of them, naming the
//! value given and the choices, so every interface says the same thing.

use std::fmt;

/// A name that is not one of the choices of its vocabulary.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct UnknownName {
    /// What was being named (`kind`, `method`, `level`).
    pub what: &'static str,
    /// The name given.
    pub given: String,
    /// Every valid name, in the order the message lists them.
    pub choices: &'static [&'static str],
}

impl UnknownName {
    /// The error for `given`, not one of `choices` of `what`.
    pub fn new(what: &'static str, given: &str, choices: &'static [&'static str]) -> Self {
        UnknownName {
            what,
            given: given.to_string(),
            choices,
        }
    }
}

impl fmt::Display for UnknownName {
    /// `unknown kind 'l3'; use l2star, cd, wd or gl2`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "unknown {} '{}'; use ", self.what, self.given)?;
        match self.choices {
            [] => write!(f, "nothing (no choices)"),
            [only] => write!(f, "{only}"),
            [init @ .., last] => write!(f, "{} or {last}", init.join(", ")),
        }
    }
}

impl std::error::Error for UnknownName {}

/// The entry of `choices` (name, value) called `given`, or the error naming them all.
pub fn parse_name<T: Copy>(
    what: &'static str,
    given: &str,
    names: &'static [&'static str],
    values: &[T],
) -> Result<T, UnknownName> {
    names
        .iter()
        .position(|n| *n == given)
        .map(|i| values[i])
        .ok_or_else(|| UnknownName::new(what, given, names))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_message_names_the_value_and_every_choice() {
        let e = UnknownName::new("kind", "l3", &["l2star", "cd", "wd", "gl2"]);
        assert_eq!(
            e.to_string(),
            "unknown kind 'l3'; use l2star, cd, wd or gl2"
        );
        assert_eq!(
            UnknownName::new("pairs", "x", &["first", "all"]).to_string(),
            "unknown pairs 'x'; use first or all"
        );
        assert_eq!(
            UnknownName::new("mode", "x", &["only"]).to_string(),
            "unknown mode 'x'; use only"
        );
    }

    #[test]
    fn names_map_to_their_own_values() {
        let names = &["a", "b", "c"];
        assert_eq!(parse_name("letter", "b", names, &[1, 2, 3]), Ok(2));
        assert_eq!(parse_name("letter", "c", names, &[1, 2, 3]), Ok(3));
        let e = parse_name("letter", "B", names, &[1, 2, 3]).unwrap_err();
        assert_eq!((e.what, e.given.as_str()), ("letter", "B"));
    }
}
