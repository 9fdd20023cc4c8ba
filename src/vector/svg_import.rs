//! SVG import: usvg resolves the document (CSS, `style`, inheritance, `use`, nested
//! transforms, shapes to paths, units); we flatten its curves with kurbo and turn every
//! visible path into strokes, one per subpath unless asked to keep compound paths whole.
//! What cannot become a stroke (text without fonts, raster images) is named in the
//! report instead of disappearing silently.

use super::color::Rgb;
use super::stroke::Stroke;
use crate::error::{Error, Result};
use kurbo::{Affine, BezPath, PathEl, Point};
use serde::{Deserialize, Serialize};
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
    let tree = usvg::Tree::from_str(svg, &usvg::Options::default()).map_err(|e| Error::Svg(describe(&e)))?;
    let mut import = Import {
        strokes: Vec::new(),
        warnings: Vec::new(),
        width: tree.size().width() as f64,
        height: tree.size().height() as f64,
    };
    let mut walker = Walker { opts, out: &mut import, gradients: 0, points: 0 };
    walker.group(tree.root(), 1.0)?;
    let gradients = walker.gradients;
    let texts = count_elements(svg, "text");
    if texts > 0 {
        import.warnings.push(format!("{texts} <text> element(s) were left out: text is not converted to strokes (convert text to paths in your editor first)."));
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

/// Elements named `tag` in the document (usvg drops text without its font feature, so
/// we count them from the XML itself to report them).
fn count_elements(svg: &str, tag: &str) -> usize {
    usvg::roxmltree::Document::parse(svg)
        .map(|d| d.descendants().filter(|n| n.is_element() && n.tag_name().name() == tag).count())
        .unwrap_or(0)
}

struct Walker<'a> {
    opts: &'a ImportOptions,
    out: &'a mut Import,
    gradients: usize,
    points: usize,
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
        }

        let mut subpaths: Vec<(Vec<[f64; 2]>, bool)> = Vec::new();
        kurbo::flatten(bez, self.opts.tolerance, |el| match el {
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
        });
        self.points += subpaths.iter().map(|s| s.0.len()).sum::<usize>();
        if self.points > self.opts.max_points {
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
