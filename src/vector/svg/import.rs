//! SVG import: resolves the document (CSS cascade, inheritance, `<use>` and `<symbol>`,
//! nested viewports and transforms, shapes and units), flattens curves with kurbo, and
//! turns every visible shape into strokes: one per group of subpaths that neither
//! contain nor cross one another (`compound`), so holes stay with their outline. What
//! cannot become a stroke (text without fonts, raster images, gradients) is named in
//! the report instead of disappearing silently.

use super::budget;
use super::compound;
use super::shape::{self, Axis, Units};
use super::style::{self, Declared, Sheet};
use crate::error::{Error, Result};
use crate::vector::color::Rgb;
use crate::vector::stroke::{FillRule, Stroke};
use kurbo::{Affine, BezPath, PathEl, Point};
use roxmltree::{Document, Node, NodeId};
use serde::{Deserialize, Serialize};
use std::collections::HashMap;
use std::str::FromStr;

#[derive(Clone, Debug, Deserialize)]
#[serde(rename_all = "camelCase", default, deny_unknown_fields)]
pub struct ImportOptions {
    /// Maximum distance between a curve and its flattened polyline, in user units.
    pub tolerance: f64,
    /// Split compound paths into their separate parts (default), or keep each path
    /// whole as one stroke.
    pub split_subpaths: bool,
    /// Refuse documents whose flattened strokes hold more points than this.
    pub max_points: usize,
}

impl Default for ImportOptions {
    fn default() -> Self {
        ImportOptions { tolerance: 0.25, split_subpaths: true, max_points: 2_000_000 }
    }
}

/// The strokes found and what was left out or merged.
#[derive(Clone, Debug, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Import {
    pub strokes: Vec<Stroke>,
    pub warnings: Vec<String>,
    pub width: f64,
    pub height: f64,
}

pub use super::shape::MAX_COORD;
/// The flattening tolerance is at least this fraction of a path's extent.
const MIN_RELATIVE_TOLERANCE: f64 = 1e-6;
/// Largest SVG source accepted (bytes): a drawing, not a data dump.
pub const MAX_SVG_BYTES: usize = 32 << 20;
const SVG_NS: &str = "http://www.w3.org/2000/svg";
const GREY: Rgb = Rgb([128, 128, 128]);

pub fn parse_svg(svg: &str, opts: &ImportOptions) -> Result<Import> {
    if svg.len() > MAX_SVG_BYTES {
        return Err(Error::TooLarge(format!(
            "The SVG is {}; the limit is {}.",
            crate::error::megabytes(svg.len() as u64),
            crate::error::megabytes(MAX_SVG_BYTES as u64)
        )));
    }
    if !(opts.tolerance.is_finite() && opts.tolerance > 0.0) {
        return Err(Error::InvalidInput("The flattening tolerance must be a positive number.".into()));
    }
    budget::check_source(svg)?;
    let xml = roxmltree::ParsingOptions { allow_dtd: true, nodes_limit: 4_000_000, ..Default::default() };
    let doc =
        Document::parse_with_options(svg, xml).map_err(|e| Error::Svg(format!("it is not well-formed XML ({e}).")))?;
    let root = doc.root_element();
    if root.tag_name().name() != "svg" || !is_svg(root) {
        return Err(Error::Svg(format!("its root element is <{}>, not <svg>.", root.tag_name().name())));
    }
    let shape = budget::measure(&doc);
    budget::check(&shape)?;

    let sheet = Sheet::new(&doc);
    let by_id = doc.descendants().filter_map(|n| Some((n.attribute("id")?, n))).collect();
    let mut walker =
        Walker { opts, sheet, by_id, using: Vec::new(), out: Vec::new(), points: 0, report: Report::default() };
    let declared = walker.sheet.declared(root);
    let base = Context::initial();
    let mut ctx = base.inherit(&declared);
    let size = root_size(root, &ctx.units);
    let (w, h) = size.unwrap_or((100.0, 100.0));
    if !matches!(style::get(&declared, "display"), Some("none")) {
        walker.viewport(root, &mut ctx, 0.0, 0.0, w, h)?;
    }
    let Walker { out: strokes, report, .. } = walker;
    // No size at all: the content's extent (as browsers show a sizeless SVG).
    let (width, height) = size.unwrap_or_else(|| {
        let right = strokes.iter().map(|s| s.bounds().x1).fold(1.0, f64::max);
        let bottom = strokes.iter().map(|s| s.bounds().y1).fold(1.0, f64::max);
        (right, bottom)
    });
    let warnings = report.warnings(shape.texts);
    Ok(Import { strokes, warnings, width, height })
}

fn is_svg(n: Node) -> bool {
    n.is_element() && matches!(n.tag_name().namespace(), None | Some(SVG_NS))
}

/// What the import left out, replaced or merged, counted for the report.
#[derive(Default)]
struct Report {
    images: usize,
    paint_servers: usize,
    out_of_range: usize,
    /// Paths split into several strokes, and compound groups kept whole.
    split: usize,
    kept_whole: usize,
}

impl Report {
    fn warnings(&self, texts: usize) -> Vec<String> {
        let mut w = Vec::new();
        if texts > 0 {
            w.push(format!("{texts} <text> element(s) were left out: text is not converted to strokes (convert text to paths in your editor first)."));
        }
        if self.images > 0 {
            w.push(format!("{} embedded raster image(s) were left out.", self.images));
        }
        if self.out_of_range > 0 {
            w.push(format!(
                "{} shape(s) lie beyond ±{MAX_COORD:e} units (after their transforms) and were left out.",
                self.out_of_range
            ));
        }
        if self.paint_servers > 0 {
            w.push(format!("{} gradient or pattern paint(s) were replaced by a single colour.", self.paint_servers));
        }
        if self.kept_whole > 0 {
            w.push(format!(
                "{} shape(s) with holes or crossing parts were kept whole, each as one element with its fill rule.",
                self.kept_whole
            ));
        }
        if self.split > 0 {
            w.push(format!("{} compound path(s) were split into their separate parts.", self.split));
        }
        w
    }
}

/// A paint as specified, resolved at the shape that uses it.
#[derive(Clone, Debug)]
enum Paint {
    None,
    Color(Rgb, f64),
    CurrentColor,
    /// A gradient or pattern (by id), with its fallback.
    Server(String, Option<Box<Paint>>),
}

/// The inherited state and the element's own transform and opacity.
#[derive(Clone, Debug)]
struct Context {
    transform: Affine,
    /// Group opacities folded together.
    opacity: f64,
    fill: Paint,
    stroke: Paint,
    fill_opacity: f64,
    stroke_opacity: f64,
    stroke_width: f64,
    fill_rule: FillRule,
    visible: bool,
    color: Rgb,
    units: Units,
}

impl Context {
    fn initial() -> Context {
        Context {
            transform: Affine::IDENTITY,
            opacity: 1.0,
            fill: Paint::Color(Rgb([0, 0, 0]), 1.0),
            stroke: Paint::None,
            fill_opacity: 1.0,
            stroke_opacity: 1.0,
            stroke_width: 1.0,
            fill_rule: FillRule::Nonzero,
            visible: true,
            color: Rgb([0, 0, 0]),
            units: Units { viewport: (100.0, 100.0), font_size: 16.0 },
        }
    }

    /// This context as a child element with `declared` values sees it (`em` in the
    /// child's font size is the parent's).
    fn inherit(&self, declared: &Declared) -> Context {
        let parent_units = self.units;
        let mut c = self.clone();
        let get = |name| style::get(declared, name).filter(|v| *v != "inherit");
        if let Some(v) = get("font-size").and_then(|v| parent_units.length(v, Axis::Y)) {
            if v > 0.0 {
                c.units.font_size = v;
            }
        }
        if let Some(col) = get("color").and_then(|v| svgtypes::Color::from_str(v).ok()) {
            c.color = Rgb([col.red, col.green, col.blue]);
        }
        if let Some(p) = get("fill").and_then(parse_paint) {
            c.fill = p;
        }
        if let Some(p) = get("stroke").and_then(parse_paint) {
            c.stroke = p;
        }
        if let Some(v) = get("fill-opacity").and_then(opacity) {
            c.fill_opacity = v;
        }
        if let Some(v) = get("stroke-opacity").and_then(opacity) {
            c.stroke_opacity = v;
        }
        if let Some(v) = get("stroke-width").and_then(|v| c.units.length(v, Axis::Both)) {
            if v >= 0.0 {
                c.stroke_width = v;
            }
        }
        match get("fill-rule") {
            Some("evenodd") => c.fill_rule = FillRule::Evenodd,
            Some("nonzero") => c.fill_rule = FillRule::Nonzero,
            _ => {}
        }
        match get("visibility") {
            Some("hidden" | "collapse") => c.visible = false,
            Some("visible") => c.visible = true,
            _ => {}
        }
        // Not inherited: applied to this element only.
        if let Some(v) = style::get(declared, "opacity").and_then(opacity) {
            c.opacity *= v;
        }
        if let Some(t) = style::get(declared, "transform").and_then(|v| svgtypes::Transform::from_str(v).ok()) {
            c.transform *= Affine::new([t.a, t.b, t.c, t.d, t.e, t.f]);
        }
        c
    }
}

fn opacity(v: &str) -> Option<f64> {
    let l = svgtypes::Length::from_str(v).ok()?;
    let v = match l.unit {
        svgtypes::LengthUnit::Percent => l.number / 100.0,
        svgtypes::LengthUnit::None => l.number,
        _ => return None,
    };
    v.is_finite().then(|| v.clamp(0.0, 1.0))
}

fn parse_paint(v: &str) -> Option<Paint> {
    let color = |c: svgtypes::Color| Paint::Color(Rgb([c.red, c.green, c.blue]), f64::from(c.alpha) / 255.0);
    Some(match svgtypes::Paint::from_str(v).ok()? {
        svgtypes::Paint::None => Paint::None,
        svgtypes::Paint::CurrentColor => Paint::CurrentColor,
        svgtypes::Paint::Color(c) => color(c),
        svgtypes::Paint::FuncIRI(id, fallback) => Paint::Server(
            id.to_string(),
            fallback.map(|f| {
                Box::new(match f {
                    svgtypes::PaintFallback::None => Paint::None,
                    svgtypes::PaintFallback::CurrentColor => Paint::CurrentColor,
                    svgtypes::PaintFallback::Color(c) => color(c),
                })
            }),
        ),
        // `inherit` keeps the parent's; context paints only mean something in markers.
        _ => return None,
    })
}

/// The root's size in user units, from `width` and `height` (or the viewBox's aspect).
fn root_size(root: Node, units: &Units) -> Option<(f64, f64)> {
    let len = |name, axis| {
        root.attribute(name)
            .filter(|v| !v.trim().ends_with('%'))
            .and_then(|v| units.length(v, axis))
            .filter(|v| *v > 0.0)
    };
    let vb = viewbox(root);
    match (len("width", Axis::X), len("height", Axis::Y), vb) {
        (Some(w), Some(h), _) => Some((w, h)),
        (Some(w), None, Some(v)) => Some((w, w * v[3] / v[2])),
        (None, Some(h), Some(v)) => Some((h * v[2] / v[3], h)),
        (None, None, Some(v)) => Some((v[2], v[3])),
        _ => None,
    }
}

/// The `viewBox` as `[x, y, w, h]`, when valid.
fn viewbox(n: Node) -> Option<[f64; 4]> {
    let v = svgtypes::ViewBox::from_str(n.attribute("viewBox")?).ok()?;
    (v.w > 0.0 && v.h > 0.0).then_some([v.x, v.y, v.w, v.h])
}

/// The transform from `n`'s viewBox to a `w x h` viewport (`preserveAspectRatio`).
fn viewbox_transform(n: Node, w: f64, h: f64) -> Affine {
    let Some([vx, vy, vw, vh]) = viewbox(n) else { return Affine::IDENTITY };
    let aspect = n
        .attribute("preserveAspectRatio")
        .and_then(|v| svgtypes::AspectRatio::from_str(v).ok())
        .unwrap_or(svgtypes::AspectRatio { defer: false, align: svgtypes::Align::XMidYMid, slice: false });
    let (sx, sy) = (w / vw, h / vh);
    if aspect.align == svgtypes::Align::None {
        return Affine::new([sx, 0.0, 0.0, sy, -vx * sx, -vy * sy]);
    }
    let s = if aspect.slice { sx.max(sy) } else { sx.min(sy) };
    use svgtypes::Align::*;
    let fx = match aspect.align {
        XMinYMin | XMinYMid | XMinYMax => 0.0,
        XMidYMin | XMidYMid | XMidYMax => 0.5,
        _ => 1.0,
    };
    let fy = match aspect.align {
        XMinYMin | XMidYMin | XMaxYMin => 0.0,
        XMinYMid | XMidYMid | XMaxYMid => 0.5,
        _ => 1.0,
    };
    let (dx, dy) = ((w - vw * s) * fx, (h - vh * s) * fy);
    Affine::new([s, 0.0, 0.0, s, dx - vx * s, dy - vy * s])
}

struct Walker<'a, 'input> {
    opts: &'a ImportOptions,
    sheet: Sheet<'a>,
    by_id: HashMap<&'a str, Node<'a, 'input>>,
    /// The `<use>` targets being expanded, to drop recursive references.
    using: Vec<NodeId>,
    out: Vec<Stroke>,
    /// Points in `out` so far, against `max_points`.
    points: usize,
    report: Report,
}

impl<'a, 'input> Walker<'a, 'input> {
    fn children(&mut self, node: Node<'a, 'input>, ctx: &Context) -> Result<()> {
        for child in node.children().filter(|c| is_svg(*c)) {
            self.element(child, ctx)?;
        }
        Ok(())
    }

    /// Renders one element (depth is bounded by `budget::check`).
    fn element(&mut self, node: Node<'a, 'input>, parent: &Context) -> Result<()> {
        let name = node.tag_name().name();
        let rendered = matches!(
            name,
            "g" | "a"
                | "svg"
                | "switch"
                | "use"
                | "path"
                | "rect"
                | "circle"
                | "ellipse"
                | "line"
                | "polyline"
                | "polygon"
                | "image"
        );
        if !rendered {
            return Ok(());
        }
        let declared = self.sheet.declared(node);
        if matches!(style::get(&declared, "display"), Some("none")) {
            return Ok(());
        }
        let mut ctx = parent.inherit(&declared);
        match name {
            "g" | "a" => self.children(node, &ctx),
            "switch" => match node.children().find(|c| is_svg(*c)) {
                Some(first) => self.element(first, &ctx),
                None => Ok(()),
            },
            "svg" => {
                let u = ctx.units;
                let (x, y) = (u.attr(node, "x", Axis::X, 0.0), u.attr(node, "y", Axis::Y, 0.0));
                let (w, h) =
                    (u.attr(node, "width", Axis::X, u.viewport.0), u.attr(node, "height", Axis::Y, u.viewport.1));
                self.viewport(node, &mut ctx, x, y, w, h)
            }
            "use" => self.use_element(node, ctx),
            "image" => {
                self.report.images += 1;
                Ok(())
            }
            _ => self.shape(node, &ctx),
        }
    }

    /// Renders the children of `svg` (an `<svg>` or `<symbol>`) in a new viewport at
    /// (x, y) of size w x h, through its viewBox.
    fn viewport(&mut self, svg: Node<'a, 'input>, ctx: &mut Context, x: f64, y: f64, w: f64, h: f64) -> Result<()> {
        if !(w > 0.0 && h > 0.0) {
            return Ok(());
        }
        ctx.transform = ctx.transform * Affine::translate((x, y)) * viewbox_transform(svg, w, h);
        ctx.units.viewport = viewbox(svg).map(|v| (v[2], v[3])).unwrap_or((w, h));
        self.children(svg, ctx)
    }

    fn use_element(&mut self, node: Node<'a, 'input>, mut ctx: Context) -> Result<()> {
        let href = node.attribute(("http://www.w3.org/1999/xlink", "href")).or_else(|| node.attribute("href"));
        let Some(target) = href.and_then(|h| h.trim().strip_prefix('#')).and_then(|id| self.by_id.get(id).copied())
        else {
            return Ok(());
        };
        // A reference to itself or to an element that contains it draws nothing.
        if self.using.contains(&target.id()) || node.ancestors().any(|a| a == target) || !is_svg(target) {
            return Ok(());
        }
        let u = ctx.units;
        let (x, y) = (u.attr(node, "x", Axis::X, 0.0), u.attr(node, "y", Axis::Y, 0.0));
        self.using.push(target.id());
        let result = match target.tag_name().name() {
            "symbol" | "svg" => {
                let declared = self.sheet.declared(target);
                if matches!(style::get(&declared, "display"), Some("none")) && target.tag_name().name() == "svg" {
                    Ok(())
                } else {
                    let mut inner = ctx.inherit(&declared);
                    let size = |name, axis, default| {
                        node.attribute(name)
                            .or(target.attribute(name))
                            .and_then(|v| u.length(v, axis))
                            .unwrap_or(default)
                    };
                    let (w, h) = (size("width", Axis::X, u.viewport.0), size("height", Axis::Y, u.viewport.1));
                    let (tx, ty) = if target.tag_name().name() == "svg" {
                        (u.attr(target, "x", Axis::X, 0.0), u.attr(target, "y", Axis::Y, 0.0))
                    } else {
                        (0.0, 0.0)
                    };
                    self.viewport(target, &mut inner, x + tx, y + ty, w, h)
                }
            }
            _ => {
                ctx.transform *= Affine::translate((x, y));
                self.element(target, &ctx)
            }
        };
        self.using.pop();
        result
    }

    /// The colour and opacity a paint resolves to at a shape, or `None` for no paint.
    fn paint(&mut self, paint: &Paint, ctx: &Context) -> Option<(Rgb, f64)> {
        match paint {
            Paint::None => None,
            Paint::Color(c, a) => Some((*c, *a)),
            Paint::CurrentColor => Some((ctx.color, 1.0)),
            Paint::Server(id, fallback) => match self.by_id.get(id.as_str()).copied() {
                Some(server) if matches!(server.tag_name().name(), "linearGradient" | "radialGradient" | "pattern") => {
                    self.report.paint_servers += 1;
                    Some(self.first_stop(server).unwrap_or((GREY, 1.0)))
                }
                _ => fallback.as_deref().and_then(|f| self.paint(f, ctx)),
            },
        }
    }

    /// A gradient's first stop colour, following `href` to the gradient that holds the
    /// stops (at most a few hops: gradients reuse each other's stops).
    fn first_stop(&self, mut gradient: Node<'a, 'input>) -> Option<(Rgb, f64)> {
        for _ in 0..8 {
            if let Some(stop) = gradient.children().find(|c| c.tag_name().name() == "stop") {
                let d = self.sheet.declared(stop);
                let c = style::get(&d, "stop-color").and_then(|v| svgtypes::Color::from_str(v).ok());
                let c = c.unwrap_or(svgtypes::Color::black());
                let a = style::get(&d, "stop-opacity").and_then(opacity).unwrap_or(1.0) * f64::from(c.alpha) / 255.0;
                return Some((Rgb([c.red, c.green, c.blue]), a));
            }
            let href = gradient.attribute(("http://www.w3.org/1999/xlink", "href")).or(gradient.attribute("href"))?;
            gradient = *self.by_id.get(href.trim().strip_prefix('#')?)?;
        }
        None
    }

    fn shape(&mut self, node: Node<'a, 'input>, ctx: &Context) -> Result<()> {
        if !ctx.visible {
            return Ok(());
        }
        let local = match shape::outline(node, &ctx.units) {
            Ok(Some(bez)) => bez,
            Ok(None) => return Ok(()),
            Err(shape::OutOfRange) => {
                self.report.out_of_range += 1;
                return Ok(());
            }
        };
        // Geometry that no drawing has (a radius of 1e20, scale(1e15)) is left out with a
        // warning: flattening it would need more points than memory holds.
        let Some(extent) = extent(&local, ctx.transform) else {
            self.report.out_of_range += 1;
            return Ok(());
        };
        let mut template = Stroke::new(Vec::new(), 0.0, None);
        template.opacity = ctx.opacity.clamp(0.0, 1.0);
        template.fill_rule = ctx.fill_rule;
        let is_line = node.tag_name().name() == "line";
        if let Some((c, a)) = if is_line { None } else { self.paint(&ctx.fill, ctx) } {
            template.fill = Some(c);
            template.fill_opacity = (ctx.fill_opacity * a).clamp(0.0, 1.0);
        }
        if let Some((c, a)) = self.paint(&ctx.stroke, ctx) {
            if ctx.stroke_width > 0.0 {
                template.stroke = Some(c);
                template.stroke_opacity = (ctx.stroke_opacity * a).clamp(0.0, 1.0);
                // A non-uniform scale has no single width: use the geometric mean.
                template.width = ctx.stroke_width * ctx.transform.determinant().abs().sqrt();
                if !(template.width.is_finite() && template.width <= MAX_COORD) {
                    self.report.out_of_range += 1;
                    return Ok(());
                }
            }
        }
        if template.fill.is_none() && template.stroke.is_none() {
            return Ok(());
        }
        let subpaths = self.flatten(local, ctx.transform, extent)?;
        self.push(subpaths, ctx.transform, template);
        Ok(())
    }

    /// Flattens a path into (points, closed) subpaths, checking the point cap as the
    /// points come. The tolerance is relative to the path's size too, so that a tiny
    /// tolerance on a large path cannot ask for billions of points.
    ///
    /// The path is flattened in its own user space (the points are transformed when
    /// pushed), so that copies of one shape (by `<use>` or a group's translation) get the
    /// very same points, and so classify as one shape: flattened where they lie, rounding
    /// would subdivide some copies differently.
    fn flatten(&mut self, local: BezPath, transform: Affine, extent: f64) -> Result<Vec<(Vec<[f64; 2]>, bool)>> {
        let tolerance = self.opts.tolerance.max(extent * MIN_RELATIVE_TOLERANCE);
        // In local units: divided by the transform's largest stretch.
        let [a, b, c, d, ..] = transform.as_coeffs();
        let sum = a * a + b * b + c * c + d * d;
        let det = a * d - b * c;
        let stretch = ((sum + (sum * sum - 4.0 * det * det).max(0.0).sqrt()) / 2.0).sqrt();
        let tolerance = if stretch > 0.0 && stretch.is_finite() { tolerance / stretch } else { tolerance };

        let budget = self.opts.max_points.saturating_sub(self.points);
        let mut count = 0usize;
        let mut subpaths: Vec<(Vec<[f64; 2]>, bool)> = Vec::new();
        kurbo::flatten(local, tolerance, |el| {
            count += 1;
            if count > budget {
                return;
            }
            match el {
                PathEl::MoveTo(a) => {
                    // A move with nothing drawn after it paints nothing.
                    if subpaths.last().is_some_and(|(p, closed)| p.len() == 1 && !closed) {
                        subpaths.pop();
                    }
                    subpaths.push((vec![[a.x, a.y]], false));
                }
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
        if subpaths.last().is_some_and(|(p, closed)| p.len() == 1 && !closed) {
            subpaths.pop();
        }
        self.points += subpaths.iter().map(|s| s.0.len()).sum::<usize>();
        if count > budget {
            return Err(Error::TooLarge(format!(
                "The SVG flattens to more than {} points; raise the tolerance or simplify it.",
                self.opts.max_points
            )));
        }
        Ok(subpaths)
    }

    /// Adds a shape's subpaths (in its user space) as strokes under `transform`: its
    /// separate parts one stroke each (holes and crossing parts with their outline), or
    /// the whole path as one. Parts are told apart before the transform, for the same
    /// reason as `flatten`: a part that touches another (a cut-out on the edge of its
    /// frame) must be judged alike in every copy.
    fn push(&mut self, mut subpaths: Vec<(Vec<[f64; 2]>, bool)>, transform: Affine, template: Stroke) {
        if subpaths.is_empty() {
            return;
        }
        let groups = if self.opts.split_subpaths {
            compound::groups(&subpaths, template.fill.is_some())
        } else {
            vec![(0..subpaths.len()).collect()]
        };
        for (points, _) in &mut subpaths {
            for p in points.iter_mut() {
                let q = transform * Point::new(p[0], p[1]);
                *p = [q.x, q.y];
            }
        }
        if groups.len() > 1 {
            self.report.split += 1;
        }
        self.report.kept_whole += groups.iter().filter(|g| g.len() > 1 && self.opts.split_subpaths).count();
        let mut subpaths: Vec<Option<(Vec<[f64; 2]>, bool)>> = subpaths.into_iter().map(Some).collect();
        for group in groups {
            let mut whole = template.clone();
            for i in group {
                let Some((points, closed)) = subpaths[i].take() else { continue };
                if !whole.points.is_empty() {
                    whole.breaks.push(whole.points.len());
                }
                whole.closed |= closed;
                whole.points.extend(points);
            }
            self.out.push(whole);
        }
    }
}

/// The extent (largest side of the control-point box) of a path under `transform`, when
/// every transformed point is finite and within `MAX_COORD`; else `None`.
fn extent(bez: &BezPath, transform: Affine) -> Option<f64> {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for el in bez.elements() {
        let pts: &[Point] = match el {
            PathEl::MoveTo(a) | PathEl::LineTo(a) => std::slice::from_ref(a),
            PathEl::QuadTo(a, b) => &[*a, *b],
            PathEl::CurveTo(a, b, c) => &[*a, *b, *c],
            PathEl::ClosePath => &[],
        };
        for &p in pts {
            let p = transform * p;
            if !(p.x.abs() <= MAX_COORD && p.y.abs() <= MAX_COORD) {
                return None;
            }
            lo = [lo[0].min(p.x), lo[1].min(p.y)];
            hi = [hi[0].max(p.x), hi[1].max(p.y)];
        }
    }
    Some((hi[0] - lo[0]).max(hi[1] - lo[1]).max(0.0))
}
