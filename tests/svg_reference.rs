//! Our SVG import against usvg, the reference resolver, on real documents: icons from
//! simple-icons (compound paths with holes), geopattern backgrounds (percentages,
//! opacities, transforms, `<use>`-free repeats) and svg-patterns tiles
//! (tests/fixtures/svg, collected by collect.mjs), and hand-written `constructs`
//! (symbols, nested viewports, the CSS cascade, gradients, visibility, holes). Each visible shape must come out as
//! one stroke with the same box, paints, stroke width and opacity.

use patternsynth::vector::{parse_svg, ImportOptions, Rgb, Stroke};
use std::path::Path;

struct Reference {
    bounds: [f64; 4],
    fill: Option<Rgb>,
    stroke: Option<Rgb>,
    width: f64,
    opacity: f64,
}

fn color(p: &usvg::Paint) -> Rgb {
    match p {
        usvg::Paint::Color(c) => Rgb([c.red, c.green, c.blue]),
        usvg::Paint::LinearGradient(g) => {
            g.stops().first().map_or(Rgb([128; 3]), |s| Rgb([s.color().red, s.color().green, s.color().blue]))
        }
        usvg::Paint::RadialGradient(g) => {
            g.stops().first().map_or(Rgb([128; 3]), |s| Rgb([s.color().red, s.color().green, s.color().blue]))
        }
        usvg::Paint::Pattern(_) => Rgb([128; 3]),
    }
}

fn walk(g: &usvg::Group, opacity: f64, out: &mut Vec<Reference>) {
    for node in g.children() {
        match node {
            usvg::Node::Group(child) => walk(child, opacity * child.opacity().get() as f64, out),
            usvg::Node::Path(p) if p.is_visible() => {
                let Some(b) = p.data().clone().transform(p.abs_transform()).and_then(|d| d.compute_tight_bounds())
                else {
                    continue;
                };
                let t = p.abs_transform();
                // usvg keeps a fill on shapes without area (`<line>`), which paints
                // nothing; we drop it, as a browser shows it.
                let fill = p.fill().filter(|_| b.width() > 0.0 && b.height() > 0.0);
                if fill.is_none() && p.stroke().is_none() {
                    continue;
                }
                out.push(Reference {
                    bounds: [b.left(), b.top(), b.right(), b.bottom()].map(f64::from),
                    fill: fill.map(|f| color(f.paint())),
                    stroke: p.stroke().map(|s| color(s.paint())),
                    width: p
                        .stroke()
                        .map_or(0.0, |s| s.width().get() as f64 * ((t.sx * t.sy - t.kx * t.ky).abs() as f64).sqrt()),
                    opacity,
                });
            }
            _ => {}
        }
    }
}

fn check(file: &Path) -> Result<usize, String> {
    let svg = std::fs::read_to_string(file).unwrap();
    let tree = usvg::Tree::from_str(&svg, &usvg::Options::default()).map_err(|e| e.to_string())?;
    let mut want = Vec::new();
    walk(tree.root(), 1.0, &mut want);
    let ours = parse_svg(&svg, &ImportOptions { split_subpaths: false, tolerance: 0.05, ..Default::default() })
        .map_err(|e| e.to_string())?;
    let got: Vec<&Stroke> = ours.strokes.iter().collect();
    let size = tree.size();
    if (ours.width - size.width() as f64).abs() > 1e-3 || (ours.height - size.height() as f64).abs() > 1e-3 {
        return Err(format!("size {}x{} against {:?}", ours.width, ours.height, tree.size()));
    }
    if got.len() != want.len() {
        let ours: Vec<_> = got.iter().map(|s| (s.bounds().x0, s.fill, s.stroke)).collect();
        let theirs: Vec<_> = want.iter().map(|r| (r.bounds[0], r.fill, r.stroke)).collect();
        return Err(format!("{} strokes against {} paths: {ours:?} against {theirs:?}", got.len(), want.len()));
    }
    let diagonal = (ours.width.hypot(ours.height)).max(1.0);
    for (i, (s, r)) in got.iter().zip(&want).enumerate() {
        let b = s.bounds();
        let ours = [b.x0, b.y0, b.x1, b.y1];
        let off = ours.iter().zip(&r.bounds).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
        if off > 0.1 + 1e-3 * diagonal {
            return Err(format!("shape {i}: box {ours:?} against {:?}", r.bounds));
        }
        if (s.fill, s.stroke) != (r.fill, r.stroke) {
            return Err(format!("shape {i}: paints {:?}/{:?} against {:?}/{:?}", s.fill, s.stroke, r.fill, r.stroke));
        }
        if s.stroke.is_some() && (s.width - r.width).abs() > 1e-3 * r.width.max(1.0) {
            return Err(format!("shape {i}: stroke width {} against {}", s.width, r.width));
        }
        if (s.opacity - r.opacity).abs() > 1e-3 {
            return Err(format!("shape {i}: opacity {} against {}", s.opacity, r.opacity));
        }
    }
    Ok(got.len())
}

#[test]
fn real_documents_import_as_usvg_resolves_them() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/svg");
    let (mut files, mut shapes, mut failures) = (0, 0, Vec::new());
    for dir in ["simple-icons", "geopattern", "svg-patterns", "constructs"] {
        let mut entries: Vec<_> = std::fs::read_dir(root.join(dir)).unwrap().map(|e| e.unwrap().path()).collect();
        entries.sort();
        for file in entries.iter().filter(|f| f.extension().is_some_and(|e| e == "svg")) {
            files += 1;
            match check(file) {
                Ok(n) => shapes += n,
                Err(e) => failures.push(format!("{}: {e}", file.display())),
            }
        }
    }
    assert!(files >= 70, "fixtures missing: {files}");
    assert!(failures.is_empty(), "{} of {files} differ:\n{}", failures.len(), failures.join("\n"));
    println!("{files} documents, {shapes} shapes agree with usvg");
}
