//! RGB colours as the API carries them: `'#rrggbb'` strings in JS, three bytes here.

use serde::{Deserialize, Deserializer, Serialize, Serializer};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Rgb(pub [u8; 3]);

impl Rgb {
    /// Euclidean distance in RGB, 0..=441.7.
    pub fn distance(self, other: Rgb) -> f64 {
        let d: f64 = (0..3).map(|i| (self.0[i] as f64 - other.0[i] as f64).powi(2)).sum();
        d.sqrt()
    }

    pub fn to_hex(self) -> String {
        format!("#{:02x}{:02x}{:02x}", self.0[0], self.0[1], self.0[2])
    }

    /// Parses `#rgb`, `#rrggbb` (case-insensitive). Named colours are resolved by the SVG
    /// importer; the JS API takes hex only, so a typo is an error and not a silent black.
    pub fn from_hex(s: &str) -> Option<Rgb> {
        let h = s.trim().strip_prefix('#')?;
        let digit = |c: u8| (c as char).to_digit(16).map(|d| d as u8);
        let b = h.as_bytes();
        match b.len() {
            3 => Some(Rgb([digit(b[0])? * 17, digit(b[1])? * 17, digit(b[2])? * 17])),
            6 => {
                let byte = |i: usize| Some(digit(b[i])? * 16 + digit(b[i + 1])?);
                Some(Rgb([byte(0)?, byte(2)?, byte(4)?]))
            }
            _ => None,
        }
    }
}

/// Distance between two optional colours: none matches only none.
pub fn paint_distance(a: Option<Rgb>, b: Option<Rgb>) -> f64 {
    match (a, b) {
        (None, None) => 0.0,
        (Some(x), Some(y)) => x.distance(y),
        _ => f64::INFINITY,
    }
}

impl Serialize for Rgb {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&self.to_hex())
    }
}

impl<'de> Deserialize<'de> for Rgb {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let s = String::deserialize(d)?;
        Rgb::from_hex(&s).ok_or_else(|| {
            serde::de::Error::custom(format!("colour {} is not of the form '#rrggbb'", crate::error::quoted(&s)))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hex_round_trip_and_short_form() {
        assert_eq!(Rgb::from_hex("#0a0B0c"), Some(Rgb([10, 11, 12])));
        assert_eq!(Rgb::from_hex("#f80"), Some(Rgb([255, 136, 0])));
        assert_eq!(Rgb([1, 2, 255]).to_hex(), "#0102ff");
        assert_eq!(Rgb::from_hex("red"), None);
        assert_eq!(Rgb::from_hex("#12345"), None);
    }

    #[test]
    fn none_matches_only_none() {
        assert_eq!(paint_distance(None, None), 0.0);
        assert!(paint_distance(None, Some(Rgb([0, 0, 0]))).is_infinite());
        assert!((paint_distance(Some(Rgb([0, 0, 0])), Some(Rgb([3, 4, 0]))) - 5.0).abs() < 1e-12);
    }
}
