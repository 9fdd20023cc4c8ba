//! SVG import: usvg resolves the document (CSS, `style`, inheritance, `use`, nested
//! transforms, shapes to paths, units); we flatten its curves with kurbo and turn every
//! visible path into strokes, one per subpath unless asked to keep compound paths whole.
//! What cannot become a stroke (text without fonts, raster images) is named in the
//! report instead of disappearing silently.

use super::color::Rgb;
use super::stroke::Stroke;
use super::svg_budget;
use crate::error::{Error, Result};
use kurbo::{Affine, BezPath, PathEl, Point};
use serde::{Deserialize, Serialize};
use usvg::roxmltree;
use usvg::tiny_skia_path::PathSegment;

#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase", default, deny_unknown_fields)]
pub struct ImportOptions {
    /// Maximum distance between a curve and its flattened polyline, in user units.
    pub tolerance: f64,
    /// One stroke per subpath (default) or one per compound path.
    pub split_subpaths: bool,
    /// Refuse documents whose flattened strokes hold more points than this.
    pub max_points: usize,
}

impl Default for ImportOptions {
    fn default() -> Self {
        ImportOptions { tolerance: 0.25, split_subpaths: true, max_points: 2_000_000 }
    }
}

/// The strokes found and what was left out.
#[derive(Clone, Debug, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Import {
    pub strokes: Vec<Stroke>,
    pub warnings: Vec<String>,
    pub width: f64,
    pub height: f64,
}

/// Largest coordinate (and stroke width) kept, in user units after transforms.
pub const MAX_COORD: f64 = 1e7;
/// The flattening tolerance is at least this fraction of a path's extent.
const MIN_RELATIVE_TOLERANCE: f64 = 1e-6;

/// The extent (largest side of the control-point box) of a path whose every point is
/// finite and within `MAX_COORD`, or `None`.
fn extent(bez: &BezPath) -> Option<f64> {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for el in bez.elements() {
        let pts: &[Point] = match el {
            PathEl::MoveTo(a) | PathEl::LineTo(a) => std::slice::from_ref(a),
            PathEl::QuadTo(a, b) => &[*a, *b],
            PathEl::CurveTo(a, b, c) => &[*a, *b, *c],
            PathEl::ClosePath => &[],
        };
        for p in pts {
            if !(p.x.abs() <= MAX_COORD && p.y.abs() <= MAX_COORD) {
                return None;
            }
            lo = [lo[0].min(p.x), lo[1].min(p.y)];
            hi = [hi[0].max(p.x), hi[1].max(p.y)];
        }
    }
    Some((hi[0] - lo[0]).max(hi[1] - lo[1]).max(0.0))
}

/// Largest SVG source accepted (bytes): a drawing, not a data dump.
pub const MAX_SVG_BYTES: usize = 32 << 20;

pub fn parse_svg(svg: &str, opts: &ImportOptions) -> Result<Import> {
    if svg.len() > MAX_SVG_BYTES {
        return Err(Error::TooLarge(format!(
            "The SVG is {} MB; the limit is {} MB.",
            svg.len() >> 20,
            MAX_SVG_BYTES >> 20
        )));
    }
    if !(opts.tolerance.is_finite() && opts.tolerance > 0.0) {
        return Err(Error::InvalidInput("The flattening tolerance must be a positive number.".into()));
    }
    svg_budget::check_source(svg)?;
    let xml = roxmltree::ParsingOptions { allow_dtd: true, ..Default::default() };
    let doc = roxmltree::Document::parse_with_options(svg, xml)
        .map_err(|e| Error::Svg(describe(&usvg::Error::ParsingFailed(e))))?;
    let shape = svg_budget::measure(&doc);
    svg_budget::check(&shape)?;
    let tree = usvg::Tree::from_xmltree(&doc, &usvg::Options::default()).map_err(|e| Error::Svg(describe(&e)))?;
    let mut import = Import {
        strokes: Vec::new(),
        warnings: Vec::new(),
        width: tree.size().width() as f64,
        height: tree.size().height() as f64,
    };
    let mut walker = Walker { opts, out: &mut import, gradients: 0, points: 0, out_of_range: 0 };
    walker.group(tree.root(), 1.0)?;
    let (gradients, out_of_range) = (walker.gradients, walker.out_of_range);
    let texts = shape.texts;
    if texts > 0 {
        import.warnings.push(format!("{texts} <text> element(s) were left out: text is not converted to strokes (convert text to paths in your editor first)."));
    }
    if out_of_range > 0 {
        import.warnings.push(format!(
            "{out_of_range} shape(s) lie beyond ±{MAX_COORD:e} units (after their transforms) and were left out."
        ));
    }
    if gradients > 0 {
        import.warnings.push(format!("{gradients} gradient or pattern paint(s) were replaced by a single colour."));
    }
    Ok(import)
}

fn describe(e: &usvg::Error) -> String {
    match e {
        usvg::Error::NotAnUtf8Str => "it is not UTF-8 text.".into(),
        usvg::Error::InvalidSize => {
            "it has no usable size (give the root <svg> a width and height or a viewBox).".into()
        }
        usvg::Error::ElementsLimitReached => "it has more than a million elements.".into(),
        usvg::Error::ParsingFailed(x) => format!("it is not well-formed XML ({x})."),
        other => other.to_string(),
    }
}

struct Walker<'a> {
    opts: &'a ImportOptions,
    out: &'a mut Import,
    gradients: usize,
    points: usize,
    /// Paths left out for coordinates or widths beyond `MAX_COORD`.
    out_of_range: usize,
}

impl Walker<'_> {
    fn group(&mut self, g: &usvg::Group, opacity: f64) -> Result<()> {
        for node in g.children() {
            match node {
                usvg::Node::Group(child) => self.group(child, opacity * child.opacity().get() as f64)?,
                usvg::Node::Path(p) if p.is_visible() => self.path(p, opacity)?,
                usvg::Node::Image(_) => self.out.warnings.push("An embedded raster image was left out.".into()),
                _ => {}
            }
        }
        Ok(())
    }

    fn paint(&mut self, paint: &usvg::Paint) -> Rgb {
        match paint {
            usvg::Paint::Color(c) => Rgb([c.red, c.green, c.blue]),
            usvg::Paint::LinearGradient(g) => self.first_stop(g.stops()),
            usvg::Paint::RadialGradient(g) => self.first_stop(g.stops()),
            usvg::Paint::Pattern(_) => {
                self.gradients += 1;
                Rgb([128, 128, 128])
            }
        }
    }

    fn first_stop(&mut self, stops: &[usvg::Stop]) -> Rgb {
        self.gradients += 1;
        stops.first().map(|s| Rgb([s.color().red, s.color().green, s.color().blue])).unwrap_or(Rgb([128, 128, 128]))
    }

    fn path(&mut self, p: &usvg::Path, opacity: f64) -> Result<()> {
        let t = p.abs_transform();
        let affine = Affine::new([t.sx, t.ky, t.kx, t.sy, t.tx, t.ty].map(|v| v as f64));
        let mut bez = BezPath::new();
        let pt = |q: usvg::tiny_skia_path::Point| Point::new(q.x as f64, q.y as f64);
        for seg in p.data().segments() {
            match seg {
                PathSegment::MoveTo(a) => bez.move_to(pt(a)),
                PathSegment::LineTo(a) => bez.line_to(pt(a)),
                PathSegment::QuadTo(a, b) => bez.quad_to(pt(a), pt(b)),
                PathSegment::CubicTo(a, b, c) => bez.curve_to(pt(a), pt(b), pt(c)),
                PathSegment::Close => bez.close_path(),
            }
        }
        bez.apply_affine(affine);

        // Geometry that no drawing has (a radius of 1e20, scale(1e15)) is left out with a
        // warning: flattening it would need more points than memory holds.
        let extent = match extent(&bez) {
            Some(e) => e,
            None => {
                self.out_of_range += 1;
                return Ok(());
            }
        };

        let mut template = Stroke::new(Vec::new(), 0.0, None);
        template.opacity = opacity.clamp(0.0, 1.0);
        if let Some(f) = p.fill() {
            template.fill = Some(self.paint(f.paint()));
            template.fill_opacity = f.opacity().get() as f64;
        }
        if let Some(s) = p.stroke() {
            template.stroke = Some(self.paint(s.paint()));
            template.stroke_opacity = s.opacity().get() as f64;
            // A non-uniform scale has no single width: use the geometric mean.
            template.width = s.width().get() as f64 * affine.determinant().abs().sqrt();
            if !(template.width.is_finite() && template.width <= MAX_COORD) {
                self.out_of_range += 1;
                return Ok(());
            }
        }

        // The tolerance is relative to the path's size too, so that a tiny tolerance on a
        // large path cannot ask for billions of points; the point cap is checked as the
        // points come, before they are stored.
        let tolerance = self.opts.tolerance.max(extent * MIN_RELATIVE_TOLERANCE);
        let budget = self.opts.max_points.saturating_sub(self.points);
        let mut count = 0usize;
        let mut subpaths: Vec<(Vec<[f64; 2]>, bool)> = Vec::new();
        kurbo::flatten(bez, tolerance, |el| {
            count += 1;
            if count > budget {
                return;
            }
            match el {
                PathEl::MoveTo(a) => subpaths.push((vec![[a.x, a.y]], false)),
                PathEl::LineTo(a) => {
                    if let Some((pts, _)) = subpaths.last_mut() {
                        pts.push([a.x, a.y]);
                    }
                }
                PathEl::ClosePath => {
                    if let Some((pts, closed)) = subpaths.last_mut() {
                        *closed = true;
                        // The closing point repeats the start: drop it, `closed` redraws it.
                        if pts.len() > 1 && pts.first() == pts.last() {
                            pts.pop();
                        }
                    }
                }
                _ => {}
            }
        });
        self.points += subpaths.iter().map(|s| s.0.len()).sum::<usize>();
        if count > budget {
            return Err(Error::TooLarge(format!(
                "The SVG flattens to more than {} points; raise the tolerance or simplify it.",
                self.opts.max_points
            )));
        }
        if self.opts.split_subpaths {
            for (points, closed) in subpaths {
                self.out.strokes.push(Stroke { points, closed, ..template.clone() });
            }
        } else if !subpaths.is_empty() {
            let mut whole = template;
            whole.closed = subpaths.iter().any(|s| s.1);
            for (points, _) in subpaths {
                if !whole.points.is_empty() {
                    whole.breaks.push(whole.points.len());
                }
                whole.points.extend(points);
            }
            self.out.strokes.push(whole);
        }
        Ok(())
    }
}
