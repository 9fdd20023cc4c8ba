//! Basic shapes and path data to Bézier paths in the element's user space, and the
//! length units they are measured in.

use kurbo::{Arc, BezPath, Ellipse, Point, Shape, Vec2};
use roxmltree::Node;
use std::str::FromStr;
use svgtypes::{Length, LengthUnit, PathParser, PathSegment, SimplePathSegment, SimplifyingPathParser};

/// Largest coordinate, radius or length accepted, in user units. Beyond it a shape is
/// left out (and reported): no drawing has it, and curves that large would flatten to
/// more points than memory holds, or take minutes to convert.
pub const MAX_COORD: f64 = 1e7;

/// A shape whose geometry lies beyond `MAX_COORD`.
#[derive(Debug, PartialEq)]
pub struct OutOfRange;

/// Which viewport dimension a percentage refers to.
#[derive(Clone, Copy)]
pub enum Axis {
    X,
    Y,
    /// The normalised diagonal, sqrt((w² + h²) / 2), for radii and widths.
    Both,
}

/// What lengths are resolved against: the nearest viewport and the font size (for `em`).
#[derive(Clone, Copy, Debug)]
pub struct Units {
    pub viewport: (f64, f64),
    pub font_size: f64,
}

impl Units {
    /// A length in user units (`None` if unparsable).
    pub fn length(&self, value: &str, axis: Axis) -> Option<f64> {
        let l = Length::from_str(value.trim()).ok()?;
        let (w, h) = self.viewport;
        let v = match l.unit {
            LengthUnit::None | LengthUnit::Px => l.number,
            LengthUnit::Em => l.number * self.font_size,
            LengthUnit::Ex => l.number * self.font_size / 2.0,
            LengthUnit::In => l.number * 96.0,
            LengthUnit::Cm => l.number * 96.0 / 2.54,
            LengthUnit::Mm => l.number * 96.0 / 25.4,
            LengthUnit::Pt => l.number * 4.0 / 3.0,
            LengthUnit::Pc => l.number * 16.0,
            LengthUnit::Percent => {
                let base = match axis {
                    Axis::X => w,
                    Axis::Y => h,
                    Axis::Both => ((w * w + h * h) / 2.0).sqrt(),
                };
                l.number / 100.0 * base
            }
        };
        v.is_finite().then_some(v)
    }

    /// The attribute `name` of `node` as a length, or `default`.
    pub fn attr(&self, node: Node, name: &str, axis: Axis, default: f64) -> f64 {
        node.attribute(name).and_then(|v| self.length(v, axis)).unwrap_or(default)
    }
}

/// The outline of a shape element in its own user space, or `None` when it draws
/// nothing (a zero radius, an empty `d`, an element that is not a shape).
pub fn outline(node: Node, units: &Units) -> Result<Option<BezPath>, OutOfRange> {
    // Every length a basic shape reads, checked before any curve is made.
    for name in ["x", "y", "width", "height", "rx", "ry", "r", "cx", "cy", "x1", "y1", "x2", "y2"] {
        if node.attribute(name).and_then(|v| units.length(v, Axis::Both)).is_some_and(|v| v.abs() > MAX_COORD) {
            return Err(OutOfRange);
        }
    }
    Ok(shape(node, units)?.filter(|p| !p.elements().is_empty()))
}

fn shape(node: Node, units: &Units) -> Result<Option<BezPath>, OutOfRange> {
    let len = |name, axis| units.attr(node, name, axis, 0.0);
    let none = Ok(None);
    let path = match node.tag_name().name() {
        "path" => match node.attribute("d") {
            Some(d) => path_data(d)?,
            None => return none,
        },
        "rect" => {
            let (x, y, w, h) = (len("x", Axis::X), len("y", Axis::Y), len("width", Axis::X), len("height", Axis::Y));
            if !(w > 0.0 && h > 0.0) {
                return none;
            }
            let rx = node.attribute("rx").and_then(|v| units.length(v, Axis::X));
            let ry = node.attribute("ry").and_then(|v| units.length(v, Axis::Y));
            let (rx, ry) = match (rx, ry) {
                (None, None) => (0.0, 0.0),
                (Some(r), None) | (None, Some(r)) => (r, r),
                (Some(a), Some(b)) => (a, b),
            };
            rounded_rect(x, y, w, h, rx.clamp(0.0, w / 2.0), ry.clamp(0.0, h / 2.0))
        }
        "circle" => {
            let r = len("r", Axis::Both);
            if !(r > 0.0 && r.is_finite()) {
                return none;
            }
            Ellipse::new((len("cx", Axis::X), len("cy", Axis::Y)), (r, r), 0.0).to_path(1e-3)
        }
        "ellipse" => {
            let rx = node.attribute("rx").and_then(|v| units.length(v, Axis::X));
            let ry = node.attribute("ry").and_then(|v| units.length(v, Axis::Y));
            let (rx, ry) = match (rx, ry) {
                (Some(a), Some(b)) => (a, b),
                (Some(r), None) | (None, Some(r)) => (r, r),
                (None, None) => return none,
            };
            if !(rx > 0.0 && ry > 0.0) {
                return none;
            }
            Ellipse::new((len("cx", Axis::X), len("cy", Axis::Y)), (rx, ry), 0.0).to_path(1e-3)
        }
        "line" => {
            let mut p = BezPath::new();
            p.move_to((len("x1", Axis::X), len("y1", Axis::Y)));
            p.line_to((len("x2", Axis::X), len("y2", Axis::Y)));
            p
        }
        name @ ("polyline" | "polygon") => {
            let mut p = BezPath::new();
            let Some(points) = node.attribute("points") else { return none };
            for (i, (x, y)) in svgtypes::PointsParser::from(points).enumerate() {
                if !(x.abs() <= MAX_COORD && y.abs() <= MAX_COORD) {
                    return Err(OutOfRange);
                }
                if i == 0 {
                    p.move_to((x, y));
                } else {
                    p.line_to((x, y));
                }
            }
            if p.elements().len() < 2 {
                return none;
            }
            if name == "polygon" {
                p.close_path();
            }
            p
        }
        _ => return none,
    };
    Ok(Some(path))
}

/// Path data as far as it is valid (SVG renders a path up to its first error).
pub fn path_data(d: &str) -> Result<BezPath, OutOfRange> {
    check_range(d)?;
    let mut p = BezPath::new();
    for segment in SimplifyingPathParser::from(d) {
        match segment {
            Ok(SimplePathSegment::MoveTo { x, y }) => p.move_to((x, y)),
            Ok(SimplePathSegment::LineTo { x, y }) => p.line_to((x, y)),
            Ok(SimplePathSegment::CurveTo { x1, y1, x2, y2, x, y }) => p.curve_to((x1, y1), (x2, y2), (x, y)),
            Ok(SimplePathSegment::Quadratic { x1, y1, x, y }) => p.quad_to((x1, y1), (x, y)),
            Ok(SimplePathSegment::ClosePath) => p.close_path(),
            Err(_) => break,
        }
    }
    Ok(p)
}

/// Checks every absolute coordinate and arc radius of path data against `MAX_COORD`
/// before the arcs are converted (their cost grows with the radius).
fn check_range(d: &str) -> Result<(), OutOfRange> {
    let (mut x, mut y, mut start) = (0.0f64, 0.0f64, (0.0f64, 0.0f64));
    let far = |v: f64| v.is_nan() || v.abs() > MAX_COORD;
    for segment in PathParser::from(d) {
        let Ok(segment) = segment else { break };
        let base = |abs: bool, x0: f64, y0: f64| if abs { (0.0, 0.0) } else { (x0, y0) };
        let (bx, by) = base(segment.is_abs(), x, y);
        let (nx, ny, extra) = match segment {
            PathSegment::MoveTo { x: px, y: py, .. } | PathSegment::LineTo { x: px, y: py, .. } => {
                (bx + px, by + py, 0.0)
            }
            PathSegment::HorizontalLineTo { x: px, .. } => (bx + px, y, 0.0),
            PathSegment::VerticalLineTo { y: py, .. } => (x, by + py, 0.0),
            PathSegment::CurveTo { x1, y1, x2, y2, x: px, y: py, .. } => {
                (bx + px, by + py, [x1, y1, x2, y2].iter().fold(0.0f64, |m, v| m.max(v.abs())))
            }
            PathSegment::SmoothCurveTo { x2, y2, x: px, y: py, .. } => (bx + px, by + py, x2.abs().max(y2.abs())),
            PathSegment::Quadratic { x1, y1, x: px, y: py, .. } => (bx + px, by + py, x1.abs().max(y1.abs())),
            PathSegment::SmoothQuadratic { x: px, y: py, .. } => (bx + px, by + py, 0.0),
            PathSegment::EllipticalArc { rx, ry, x: px, y: py, .. } => (bx + px, by + py, rx.abs().max(ry.abs())),
            PathSegment::ClosePath { .. } => (start.0, start.1, 0.0),
        };
        if far(nx) || far(ny) || far(extra) {
            return Err(OutOfRange);
        }
        if matches!(segment, PathSegment::MoveTo { .. }) {
            start = (nx, ny);
        }
        (x, y) = (nx, ny);
    }
    Ok(())
}

/// A rectangle with elliptical corners of radii `rx`, `ry` (already clamped).
fn rounded_rect(x: f64, y: f64, w: f64, h: f64, rx: f64, ry: f64) -> BezPath {
    let mut p = BezPath::new();
    if rx <= 0.0 || ry <= 0.0 {
        p.move_to((x, y));
        p.line_to((x + w, y));
        p.line_to((x + w, y + h));
        p.line_to((x, y + h));
        p.close_path();
        return p;
    }
    use std::f64::consts::FRAC_PI_2;
    let corner = |p: &mut BezPath, cx: f64, cy: f64, start: f64| {
        let arc = Arc::new(Point::new(cx, cy), Vec2::new(rx, ry), start, FRAC_PI_2, 0.0);
        arc.append_iter(1e-3).skip(1).for_each(|el| p.push(el));
    };
    p.move_to((x + rx, y));
    p.line_to((x + w - rx, y));
    corner(&mut p, x + w - rx, y + ry, -FRAC_PI_2);
    p.line_to((x + w, y + h - ry));
    corner(&mut p, x + w - rx, y + h - ry, 0.0);
    p.line_to((x + rx, y + h));
    corner(&mut p, x + rx, y + h - ry, FRAC_PI_2);
    p.line_to((x, y + ry));
    corner(&mut p, x + rx, y + ry, 2.0 * FRAC_PI_2);
    p.close_path();
    p
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units() {
        let u = Units { viewport: (200.0, 100.0), font_size: 10.0 };
        assert_eq!(u.length("1in", Axis::X), Some(96.0));
        assert_eq!(u.length("50%", Axis::X), Some(100.0));
        assert_eq!(u.length("50%", Axis::Y), Some(50.0));
        assert_eq!(u.length("2em", Axis::X), Some(20.0));
        assert_eq!(u.length("3pt", Axis::X), Some(4.0));
        assert_eq!(u.length("wide", Axis::X), None);
    }

    #[test]
    fn far_geometry_is_refused_before_curves_are_made() {
        assert_eq!(path_data("M0 0 A1e300 1e300 0 0 1 1e300 0"), Err(OutOfRange));
        let many: String = std::iter::repeat_n(" l9e6 0", 3).collect();
        assert_eq!(path_data(&format!("M0 0{many}")), Err(OutOfRange), "relative moves add up");
        assert!(path_data("M0 0 a5 5 0 0 1 10 0 h-10 z").is_ok());
    }

    #[test]
    fn rounded_corners_stay_inside_the_rect() {
        let p = rounded_rect(0.0, 0.0, 10.0, 6.0, 3.0, 2.0);
        let b = p.bounding_box();
        assert!((b.x0 - 0.0).abs() < 1e-9 && (b.x1 - 10.0).abs() < 1e-9 && (b.y1 - 6.0).abs() < 1e-9);
        assert!(!p.contains(Point::new(0.2, 0.2)), "the corner is cut");
        assert!(p.contains(Point::new(5.0, 3.0)));
    }
}
