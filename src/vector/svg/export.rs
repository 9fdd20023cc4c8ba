//! SVG output: a `<path>` per stroke, in drawing order, with a viewBox of the target;
//! strokes that are translated copies of one another (a pattern is mostly such copies)
//! are written once in `<defs>` and placed with `<use>`. Numbers are written finite and
//! short; nothing from the input reaches the XML except numbers and colours we format
//! ourselves, so the document is always well formed.

use crate::vector::stroke::{FillRule, Stroke};
use std::collections::HashMap;
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
    path_data_from(s, [0.0, 0.0])
}

/// `path_data` with `origin` subtracted from every point (a `<use>` at `origin` draws
/// it where `path_data` would, to the written thousandth).
fn path_data_from(s: &Stroke, origin: [f64; 2]) -> String {
    let mut d = String::new();
    let mut breaks = s.breaks.iter().peekable();
    for (i, p) in s.points.iter().enumerate() {
        let (x, y) = (p[0] - origin[0], p[1] - origin[1]);
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
        push_num(&mut d, x);
        d.push(' ');
        push_num(&mut d, y);
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
    format!("<path d=\"{}\"{}/>", path_data(s), paint(s))
}

/// A stroke's paint attributes (each with its leading space).
fn paint(s: &Stroke) -> String {
    let mut e = String::new();
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
    e
}

/// A whole SVG document of `width x height` user units. A stroke whose shape and paint
/// recur (translated, to the thousandth the document is written in) is defined once in
/// `<defs>`, relative to its first point, and each copy is a `<use>` there; the picture
/// is the same as with a `<path>` per stroke. (117 copies of a hand-drawn flower: a
/// tenth of the size.) With `classes` (one per stroke; empty: none), each definition and
/// path carries `class="c<k>"`, its stroke's class, so that a page or a tool can restyle
/// a class (`.c0 { stroke: teal }`) without knowing the layout.
pub fn to_svg(strokes: &[Stroke], classes: &[u32], width: f64, height: f64) -> String {
    let class = |i: usize| classes.get(i).map_or(String::new(), |k| format!(" class=\"c{k}\""));
    let (group, count) = recurring(strokes);
    let mut ids: HashMap<u32, usize> = HashMap::new();
    let mut defs = String::new();
    for (i, (s, &g)) in strokes.iter().zip(&group).enumerate() {
        if count[g as usize] > 1 && !ids.contains_key(&g) {
            let id = ids.len();
            let (d, paint) = (path_data_from(s, origin(s)), paint(s));
            let _ = writeln!(defs, "<path id=\"s{id}\"{} d=\"{d}\"{paint}/>", class(i));
            ids.insert(g, id);
        }
    }
    let mut out = String::with_capacity(128 + defs.len() + strokes.len() * 48);
    let _ = writeln!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">",
        w = num(width),
        h = num(height)
    );
    if !defs.is_empty() {
        let _ = write!(out, "<defs>\n{defs}</defs>\n");
    }
    for (i, (s, g)) in strokes.iter().zip(&group).enumerate() {
        match ids.get(g) {
            Some(id) => {
                let [x, y] = origin(s);
                let _ = write!(out, "<use xlink:href=\"#s{id}\" x=\"");
                push_num(&mut out, x);
                out.push_str("\" y=\"");
                push_num(&mut out, y);
                out.push_str("\"/>");
            }
            None => {
                let _ = write!(out, "<path{} d=\"{}\"{}/>", class(i), path_data(s), paint(s));
            }
        }
        out.push('\n');
    }
    out.push_str("</svg>\n");
    out
}

/// Where a stroke's copy is placed: its first point.
fn origin(s: &Stroke) -> [f64; 2] {
    s.points.first().copied().unwrap_or([0.0, 0.0])
}

/// Groups of strokes alike up to translation (the shape relative to the first point to
/// a millionth of a unit, so that float rounding in the translation does not part
/// copies; the subpaths; the paint as written): each stroke's group, and each group's
/// size. Hashed, with equality checked against the group's first stroke.
fn recurring(strokes: &[Stroke]) -> (Vec<u32>, Vec<u32>) {
    use std::hash::{Hash, Hasher};
    fn relative(s: &Stroke) -> impl Iterator<Item = (i64, i64)> + '_ {
        let [ox, oy] = origin(s);
        let micro = |v: f64| if v.is_finite() { (v * 1e6).round().clamp(-9e15, 9e15) as i64 } else { 0 };
        s.points.iter().map(move |p| (micro(p[0] - ox), micro(p[1] - oy)))
    }
    // The paint as written (`paint` formats it): colours, and numbers in thousandths.
    fn paint_key(s: &Stroke) -> impl Hash + Eq {
        let milli = |v: f64| if v.is_finite() { (v * 1000.0).round() as i64 } else { 0 };
        let fill = s.fill.map(|c| (c.0, milli(s.fill_opacity.min(1.0)), s.fill_rule == FillRule::Evenodd));
        let stroke = s.stroke.map(|c| (c.0, milli(s.width), milli(s.stroke_opacity.min(1.0))));
        (fill, stroke, milli(s.opacity.min(1.0)))
    }
    let alike = |a: &Stroke, b: &Stroke| {
        a.points.len() == b.points.len()
            && a.closed == b.closed
            && a.breaks == b.breaks
            && paint_key(a) == paint_key(b)
            && relative(a).eq(relative(b))
    };
    let mut by_hash: HashMap<u64, Vec<u32>> = HashMap::new();
    let (mut group, mut count, mut first) = (Vec::with_capacity(strokes.len()), Vec::new(), Vec::new());
    for (i, s) in strokes.iter().enumerate() {
        let mut h = std::collections::hash_map::DefaultHasher::new();
        relative(s).for_each(|p| p.hash(&mut h));
        (s.closed, &s.breaks, paint_key(s)).hash(&mut h);
        let candidates = by_hash.entry(h.finish()).or_default();
        let g = match candidates.iter().find(|&&g| alike(&strokes[first[g as usize]], s)) {
            Some(&g) => g,
            None => {
                let g = count.len() as u32;
                count.push(0);
                first.push(i);
                candidates.push(g);
                g
            }
        };
        count[g as usize] += 1;
        group.push(g);
    }
    (group, count)
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

    #[test]
    fn translated_copies_are_used_not_repeated() {
        let bar = |x: f64, y: f64| {
            Stroke::new(vec![[x, y], [x + 4.1234, y + 2.0], [x + 1.0, y + 7.5]], 2.0, Some(Rgb([1, 2, 3])))
        };
        let mut strokes: Vec<Stroke> = (0..30).map(|i| bar(10.0 * i as f64 + 0.1, 3.3 * i as f64)).collect();
        strokes.push(Stroke::new(vec![[0.0, 0.0], [5.0, 5.0]], 1.0, Some(Rgb([9, 9, 9]))));
        let svg = to_svg(&strokes, &[], 300.0, 100.0);
        assert_eq!(svg.matches("<use ").count(), 30);
        assert_eq!(svg.matches("<path ").count(), 2, "one definition and the stroke that does not recur");
        // The same coordinates as a path per stroke, once the uses are resolved.
        let back = crate::vector::parse_svg(&svg, &Default::default()).unwrap().strokes;
        assert_eq!(back.len(), strokes.len());
        for (a, b) in back.iter().zip(&strokes) {
            for (p, q) in a.points.iter().zip(&b.points) {
                assert!((p[0] - q[0]).abs() < 1e-3 && (p[1] - q[1]).abs() < 1e-3, "{p:?} {q:?}");
            }
        }
        // A different paint is another definition.
        strokes[0].width = 3.0;
        assert_eq!(to_svg(&strokes, &[], 300.0, 100.0).matches("<path ").count(), 3);
    }

    #[test]
    fn classes_are_written_on_definitions_and_paths() {
        let bar = |x: f64| Stroke::new(vec![[x, 0.0], [x + 4.0, 2.0]], 2.0, Some(Rgb([1, 2, 3])));
        let strokes = vec![bar(0.0), bar(10.0), Stroke::new(vec![[0.0, 9.0], [5.0, 5.0]], 1.0, Some(Rgb([9, 9, 9])))];
        let svg = to_svg(&strokes, &[0, 0, 1], 30.0, 10.0);
        assert!(svg.contains("<path id=\"s0\" class=\"c0\" d="), "{svg}");
        assert!(svg.contains("<path class=\"c1\" d="), "{svg}");
        assert_eq!(svg.matches("class=").count(), 2, "the uses inherit their definition's");
        // Read back as the same strokes, the classes ignored.
        assert_eq!(crate::vector::parse_svg(&svg, &Default::default()).unwrap().strokes.len(), 3);
    }
}
