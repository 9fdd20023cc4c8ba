//! The stroke: the unit the vector engine classifies, places and draws.

use super::color::Rgb;
use crate::error::{invalid, Result};
use kurbo::{Point, Rect};
use serde::{Deserialize, Serialize};

fn one() -> f64 {
    1.0
}

fn pen() -> Option<Rgb> {
    Some(Rgb([0, 0, 0]))
}

/// A stroke whose bounding box is less than this many pen widths across is a dot.
pub const DOT: f64 = 4.0;

/// How a compound stroke's subpaths fill: SVG's `fill-rule`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum FillRule {
    #[default]
    Nonzero,
    Evenodd,
}

impl FillRule {
    fn is_nonzero(&self) -> bool {
        *self == FillRule::Nonzero
    }
}

/// A polyline with its paint. Curves are flattened before they get here.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Stroke {
    #[serde(default)]
    pub points: Vec<[f64; 2]>,
    #[serde(default)]
    pub width: f64,
    /// The pen's colour; none for a shape only filled. Given no paint at all (a caller's
    /// `{ points, width }`), a black pen: with none, such a drawing came back as an SVG
    /// of invisible paths. `null` says none.
    #[serde(default = "pen")]
    pub stroke: Option<Rgb>,
    #[serde(default)]
    pub fill: Option<Rgb>,
    /// Opacity of the whole element (group opacities folded in).
    #[serde(default = "one")]
    pub opacity: f64,
    #[serde(default = "one")]
    pub stroke_opacity: f64,
    #[serde(default = "one")]
    pub fill_opacity: f64,
    /// A closed outline (`Z`): matters for fills and for drawing the last segment.
    #[serde(default)]
    pub closed: bool,
    /// For a compound path kept whole: indices into `points` where a new subpath
    /// starts (after the first). Empty for an ordinary polyline.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub breaks: Vec<usize>,
    /// Which areas of a compound stroke are holes.
    #[serde(default, skip_serializing_if = "FillRule::is_nonzero")]
    pub fill_rule: FillRule,
}

impl Stroke {
    pub fn new(points: Vec<[f64; 2]>, width: f64, stroke: Option<Rgb>) -> Self {
        Stroke {
            points,
            width,
            stroke,
            fill: None,
            opacity: 1.0,
            stroke_opacity: 1.0,
            fill_opacity: 1.0,
            closed: false,
            breaks: Vec::new(),
            fill_rule: FillRule::Nonzero,
        }
    }

    /// Bounding box of the path (not of the painted area).
    pub fn bounds(&self) -> Rect {
        let mut it = self.points.iter();
        let Some(&[x, y]) = it.next() else {
            return Rect::ZERO;
        };
        it.fold(Rect::new(x, y, x, y), |r, &[x, y]| r.union_pt(Point::new(x, y)))
    }

    /// The reference point (SPEC 1.2, Choice): the centre of the bounding box.
    pub fn reference_point(&self) -> Point {
        self.bounds().center()
    }

    /// Whether the stroke is a dot: a tap of the pen, whose turn is the pen's.
    pub fn is_dot(&self) -> bool {
        self.bounds().size().to_vec2().hypot() < DOT * self.width
    }

    /// The same stroke moved by `(dx, dy)`.
    pub fn translated(&self, dx: f64, dy: f64) -> Stroke {
        let mut s = self.clone();
        for p in &mut s.points {
            p[0] += dx;
            p[1] += dy;
        }
        s
    }

    /// Rejects what the engines cannot use, with the stroke's index in the message.
    pub fn validate(&self, index: usize) -> Result<()> {
        if self.points.is_empty() {
            return invalid(format!("Stroke {index} has no points."));
        }
        if self.points.iter().flatten().any(|v| !v.is_finite()) {
            return invalid(format!("Stroke {index} has a coordinate that is not a finite number."));
        }
        if self.breaks.iter().any(|&b| b == 0 || b >= self.points.len()) {
            return invalid(format!("Stroke {index} has a subpath break outside its points."));
        }
        if !self.width.is_finite() || self.width < 0.0 {
            return invalid(format!("Stroke {index} has a width that is negative or not a number."));
        }
        for (name, v) in
            [("opacity", self.opacity), ("strokeOpacity", self.stroke_opacity), ("fillOpacity", self.fill_opacity)]
        {
            if !(0.0..=1.0).contains(&v) {
                return invalid(format!("Stroke {index} has {name} {v}; it must be in [0, 1]."));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reference_point_is_bbox_centre() {
        let s = Stroke::new(vec![[0.0, 0.0], [4.0, 2.0], [1.0, 6.0]], 1.0, None);
        assert_eq!(s.reference_point(), Point::new(2.0, 3.0));
    }

    #[test]
    fn validate_rejects_nan_and_empty() {
        assert!(Stroke::new(vec![], 1.0, None).validate(0).is_err());
        assert!(Stroke::new(vec![[f64::NAN, 0.0]], 1.0, None).validate(0).is_err());
        assert!(Stroke::new(vec![[0.0, 0.0]], -1.0, None).validate(0).is_err());
        assert!(Stroke::new(vec![[0.0, 0.0]], 1.0, None).validate(0).is_ok());
    }
}
