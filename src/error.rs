//! The one error type every engine returns. Messages are written for the person using the
//! page: they say what was wrong and what to do, never a Rust type name.

use std::fmt;

#[derive(Debug, Clone, PartialEq)]
pub enum Error {
    /// The caller's input cannot be used as given (empty, NaN, out of range...).
    InvalidInput(String),
    /// The request would need more memory or time than the documented caps allow.
    TooLarge(String),
    /// The SVG could not be read.
    Svg(String),
    /// An image could not be decoded or encoded.
    Image(String),
    /// The progress callback asked to stop.
    Cancelled,
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::InvalidInput(m) => write!(f, "{m}"),
            Error::TooLarge(m) => write!(f, "{m}"),
            Error::Svg(m) => write!(f, "Could not read the SVG: {m}"),
            Error::Image(m) => write!(f, "Could not read the image: {m}"),
            Error::Cancelled => write!(f, "Cancelled"),
        }
    }
}

impl std::error::Error for Error {}

pub type Result<T> = std::result::Result<T, Error>;

/// Shorthand for an `InvalidInput` error.
pub(crate) fn invalid<T>(msg: impl Into<String>) -> Result<T> {
    Err(Error::InvalidInput(msg.into()))
}

/// A byte count for a message, in megabytes (2^20 bytes) to one decimal, so that a
/// size just over a limit does not read as the limit itself ("32.4 MB; the limit is
/// 32.0 MB") and every message uses one unit.
pub fn megabytes(bytes: u64) -> String {
    format!("{:.1} MB", bytes as f64 / (1u64 << 20) as f64)
}

/// A value the caller gave, quoted for a message: whole when short, else its start and
/// its length (a 10 MB string must not come back as a 10 MB message).
pub fn quoted(s: &str) -> String {
    const SHOWN: usize = 24;
    if s.chars().count() <= 2 * SHOWN {
        return format!("'{s}'");
    }
    let start: String = s.chars().take(SHOWN).collect();
    format!("'{start}…' ({} characters)", s.chars().count())
}

#[cfg(test)]
mod tests {
    #[test]
    fn long_values_are_cut_in_messages() {
        assert_eq!(super::quoted("#12345"), "'#12345'");
        let long = "x".repeat(10_000_000);
        let q = super::quoted(&long);
        assert!(q.len() < 60 && q.ends_with("(10000000 characters)"), "{q}");
    }
}
