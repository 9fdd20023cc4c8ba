//! SVG output: one `<path>` per stroke, in drawing order, with a viewBox of the target.
//! Numbers are written finite and short; nothing from the input reaches the XML except
//! numbers and colours we format ourselves, so the document is always well formed.

use crate::vector::stroke::{FillRule, Stroke};
use std::fmt::Write;

/// Formats a coordinate with at most 3 decimals and no trailing zeros.
fn num(v: f64) -> String {
    let mut s = String::new();
    push_num(&mut s, v);
    s
}

/// Appends `v` with at most 3 decimals and no trailing zeros (a non-finite value as 0).
/// Integer arithmetic on thousandths: float formatting was most of the export's time,
/// and an output can hold millions of coordinates.
fn push_num(out: &mut String, v: f64) {
    let v = if v.is_finite() { v } else { 0.0 };
    let milli = (v * 1000.0).round();
    if milli.abs() >= 1e15 {
        // Beyond exact integers in an f64 (no coordinate the engine makes).
        let _ = write!(out, "{:.0}", v);
        return;
    }
    let milli = milli as i64;
    if milli < 0 {
        out.push('-');
    }
    let (int, frac) = (milli.unsigned_abs() / 1000, milli.unsigned_abs() % 1000);
    let _ = write!(out, "{int}");
    if frac != 0 {
        let digits = [b'0' + (frac / 100) as u8, b'0' + (frac / 10 % 10) as u8, b'0' + (frac % 10) as u8];
        let keep = if frac % 100 == 0 {
            1
        } else if frac % 10 == 0 {
            2
        } else {
            3
        };
        out.push('.');
        out.extend(digits[..keep].iter().map(|&d| d as char));
    }
}

/// The `d` attribute of a polyline (a dot becomes a zero-length segment, which round
/// caps paint as a dot).
pub fn path_data(s: &Stroke) -> String {
    let mut d = String::new();
    let mut breaks = s.breaks.iter().peekable();
    for (i, [x, y]) in s.points.iter().enumerate() {
        let starts = i == 0 || breaks.next_if_eq(&&i).is_some();
        if starts && i > 0 && s.closed {
            d.push_str(" Z");
        }
        d.push_str(if i == 0 {
            "M"
        } else if starts {
            " M"
        } else {
            " L"
        });
        push_num(&mut d, *x);
        d.push(' ');
        push_num(&mut d, *y);
    }
    if s.points.len() == 1 {
        d.push_str(" l0 0");
    }
    if s.closed {
        d.push_str(" Z");
    }
    d
}

/// A `<path>` element for one stroke.
pub fn path_element(s: &Stroke) -> String {
    let mut e = format!("<path d=\"{}\"", path_data(s));
    match s.fill {
        Some(c) => {
            let _ = write!(e, " fill=\"{}\"", c.to_hex());
            if s.fill_opacity < 1.0 {
                let _ = write!(e, " fill-opacity=\"{}\"", num(s.fill_opacity));
            }
            if s.fill_rule == FillRule::Evenodd {
                e.push_str(" fill-rule=\"evenodd\"");
            }
        }
        None => e.push_str(" fill=\"none\""),
    }
    match s.stroke {
        Some(c) => {
            let _ = write!(e, " stroke=\"{}\" stroke-width=\"{}\"", c.to_hex(), num(s.width));
            e.push_str(" stroke-linecap=\"round\" stroke-linejoin=\"round\"");
            if s.stroke_opacity < 1.0 {
                let _ = write!(e, " stroke-opacity=\"{}\"", num(s.stroke_opacity));
            }
        }
        None => e.push_str(" stroke=\"none\""),
    }
    if s.opacity < 1.0 {
        let _ = write!(e, " opacity=\"{}\"", num(s.opacity));
    }
    e.push_str("/>");
    e
}

/// A whole SVG document of `width x height` user units.
pub fn to_svg(strokes: &[Stroke], width: f64, height: f64) -> String {
    let mut out = String::with_capacity(64 + strokes.len() * 96);
    let _ = writeln!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">",
        w = num(width),
        h = num(height)
    );
    for s in strokes {
        out.push_str(&path_element(s));
        out.push('\n');
    }
    out.push_str("</svg>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vector::color::Rgb;

    #[test]
    fn writes_finite_short_numbers() {
        assert_eq!(num(1.0), "1");
        assert_eq!(num(-0.0001), "0");
        assert_eq!(num(2.50049), "2.5");
        assert_eq!(num(f64::NAN), "0");
        assert_eq!(num(-12.3456), "-12.346");
        assert_eq!(num(0.05), "0.05");
        assert_eq!(num(-0.0004), "0");
        assert_eq!(num(1234567.0001), "1234567");
        assert_eq!(num(1e300), format!("{:.0}", 1e300));
    }

    #[test]
    fn fill_only_and_stroke_only() {
        let mut s = Stroke::new(vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]], 2.0, None);
        s.fill = Some(Rgb([255, 0, 0]));
        s.closed = true;
        let e = path_element(&s);
        assert!(e.contains("fill=\"#ff0000\"") && e.contains("stroke=\"none\"") && e.contains(" Z\""));
        let t = Stroke::new(vec![[0.0, 0.0], [1.0, 0.0]], 2.0, Some(Rgb([0, 0, 255])));
        let e = path_element(&t);
        assert!(e.contains("fill=\"none\"") && e.contains("stroke=\"#0000ff\"") && e.contains("stroke-width=\"2\""));
    }
}
