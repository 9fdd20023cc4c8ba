//! SVG import of real-world constructs (SPEC 1, issue: shapes, paths, transforms, CSS,
//! inheritance, opacities, colours, compound paths, text report, bad input).

use patternsynth::vector::{parse_svg, ImportOptions, Rgb, Stroke};

fn parse(body: &str) -> Vec<Stroke> {
    let svg = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200" viewBox="0 0 200 200">{body}</svg>"#
    );
    parse_svg(&svg, &ImportOptions::default()).expect("parses").strokes
}

fn bounds(s: &Stroke) -> (f64, f64, f64, f64) {
    let b = s.bounds();
    (b.x0, b.y0, b.x1, b.y1)
}

fn close(a: (f64, f64, f64, f64), b: (f64, f64, f64, f64), tol: f64) -> bool {
    (a.0 - b.0).abs() < tol && (a.1 - b.1).abs() < tol && (a.2 - b.2).abs() < tol && (a.3 - b.3).abs() < tol
}

#[test]
fn basic_shapes_become_strokes_with_their_geometry() {
    let s = parse(
        r##"<rect x="10" y="20" width="30" height="40" fill="#f00"/>
           <circle cx="100" cy="100" r="10" fill="none" stroke="blue" stroke-width="2"/>
           <ellipse cx="50" cy="150" rx="20" ry="5" fill="green"/>
           <line x1="0" y1="0" x2="10" y2="10" stroke="black"/>
           <polyline points="0,50 10,60 20,50" fill="none" stroke="#123456"/>
           <polygon points="150,10 160,30 140,30" fill="gold"/>"##,
    );
    assert_eq!(s.len(), 6);
    assert!(close(bounds(&s[0]), (10.0, 20.0, 40.0, 60.0), 1e-3));
    assert_eq!(s[0].fill, Some(Rgb([255, 0, 0])));
    assert_eq!(s[0].stroke, None, "fill-only shapes keep no stroke");
    assert!(s[0].closed);
    assert!(close(bounds(&s[1]), (90.0, 90.0, 110.0, 110.0), 0.3));
    assert_eq!(s[1].stroke, Some(Rgb([0, 0, 255])));
    assert_eq!(s[1].fill, None);
    assert!((s[1].width - 2.0).abs() < 1e-6);
    assert!(s[1].points.len() >= 16, "circle flattened to a polygon");
    assert!(close(bounds(&s[2]), (30.0, 145.0, 70.0, 155.0), 0.3));
    assert_eq!(s[2].fill, Some(Rgb([0, 128, 0])));
    assert!(close(bounds(&s[3]), (0.0, 0.0, 10.0, 10.0), 1e-3));
    assert!(!s[3].closed);
    assert_eq!(s[4].stroke, Some(Rgb([0x12, 0x34, 0x56])));
    assert_eq!(s[4].points.len(), 3);
    assert_eq!(s[5].fill, Some(Rgb([255, 215, 0])));
    assert!(s[5].closed);
}

#[test]
fn every_path_command_absolute_and_relative() {
    let abs = parse(
        r#"<path d="M10 10 L20 10 H30 V20 C30 30 40 30 40 20 S50 10 50 20 Q60 30 70 20 T90 20 A10 10 0 0 1 110 20 Z" stroke="black" fill="none"/>"#,
    );
    let rel = parse(
        r#"<path d="m10 10 l10 0 h10 v10 c0 10 10 10 10 0 s10 -10 10 0 q10 10 20 0 t20 0 a10 10 0 0 1 20 0 z" stroke="black" fill="none"/>"#,
    );
    assert_eq!(abs.len(), 1);
    assert_eq!(rel.len(), 1);
    assert!(close(bounds(&abs[0]), bounds(&rel[0]), 1e-3));
    // The arc's top reaches y = 10 (centre (100, 20), radius 10).
    let (x0, y0, x1, _) = bounds(&abs[0]);
    assert!((x0 - 10.0).abs() < 1e-3 && (x1 - 110.0).abs() < 1e-3);
    assert!((y0 - 10.0).abs() < 0.3, "arc flattened: {y0}");
    assert!(abs[0].closed);
    // Flattening tolerance: every vertex of the arc part lies on the circle.
    for &[x, y] in abs[0].points.iter().filter(|p| p[0] > 90.0 && p[1] <= 20.0) {
        let r = ((x - 100.0).powi(2) + (y - 20.0).powi(2)).sqrt();
        assert!((r - 10.0).abs() < 0.3, "point ({x}, {y}) off the arc: r = {r}");
    }
}

#[test]
fn nested_transforms_compose() {
    let s = parse(
        r#"<g transform="translate(100 50)"><g transform="scale(2)"><rect x="0" y="0" width="10" height="5" fill="black"/></g></g>
           <g transform="rotate(90)"><rect x="0" y="-20" width="10" height="10" fill="black"/></g>
           <g transform="matrix(1 0 0 1 5 5)"><rect x="0" y="0" width="1" height="1" transform="translate(1 1)" fill="black"/></g>
           <g transform="translate(10 10) rotate(45)"><line x1="0" y1="0" x2="10" y2="0" stroke="black" stroke-width="1"/></g>
           <g transform="scale(3)"><line x1="0" y1="0" x2="1" y2="0" stroke="black" stroke-width="2"/></g>"#,
    );
    assert_eq!(s.len(), 5);
    assert!(close(bounds(&s[0]), (100.0, 50.0, 120.0, 60.0), 1e-3));
    // rotate(90) maps (x, y) to (-y, x): the square [0,10]x[-20,-10] goes to [10,20]x[0,10].
    assert!(close(bounds(&s[1]), (10.0, 0.0, 20.0, 10.0), 1e-3));
    assert!(close(bounds(&s[2]), (6.0, 6.0, 7.0, 7.0), 1e-3));
    let h = 10.0 / 2f64.sqrt();
    assert!(close(bounds(&s[3]), (10.0, 10.0, 10.0 + h, 10.0 + h), 1e-3));
    assert!((s[4].width - 6.0).abs() < 1e-6, "stroke width scales with the transform");
}

#[test]
fn style_css_inheritance_opacity_and_colours() {
    let s = parse(
        r##"<style>.hot { fill: #f80; }</style>
           <g fill="red" stroke="#00F" stroke-width="3" opacity="0.5">
             <rect width="5" height="5"/>
             <rect width="5" height="5" style="fill: none; stroke: rgb(0, 128, 0)"/>
             <rect width="5" height="5" class="hot" fill-opacity="0.25" stroke-opacity="0.75"/>
             <rect width="5" height="5" fill="cornflowerblue" stroke="none"/>
           </g>"##,
    );
    assert_eq!(s.len(), 4);
    assert_eq!((s[0].fill, s[0].stroke), (Some(Rgb([255, 0, 0])), Some(Rgb([0, 0, 255]))));
    assert!((s[0].width - 3.0).abs() < 1e-6);
    assert!((s[0].opacity - 0.5).abs() < 1e-3, "group opacity folded in");
    assert_eq!((s[1].fill, s[1].stroke), (None, Some(Rgb([0, 128, 0]))));
    assert_eq!(s[2].fill, Some(Rgb([255, 136, 0])), "CSS class and short hex");
    assert!((s[2].fill_opacity - 0.25).abs() < 1e-3 && (s[2].stroke_opacity - 0.75).abs() < 1e-3);
    assert_eq!((s[3].fill, s[3].stroke), (Some(Rgb([100, 149, 237])), None));
}

#[test]
fn compound_paths_split_by_default_and_kept_whole_on_request() {
    let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100"><path d="M0 0 H10 V10 Z M20 0 H30 V10 Z M40 0 L50 5" stroke="black" fill="none"/></svg>"#;
    let split = parse_svg(svg, &ImportOptions::default()).unwrap().strokes;
    assert_eq!(split.len(), 3);
    assert!(split[0].closed && split[1].closed && !split[2].closed);
    let whole = parse_svg(svg, &ImportOptions { split_subpaths: false, ..Default::default() }).unwrap().strokes;
    assert_eq!(whole.len(), 1);
    assert_eq!(whole[0].breaks.len(), 2);
    assert_eq!(whole[0].points.len(), split.iter().map(|s| s.points.len()).sum::<usize>());
}

#[test]
fn use_elements_are_resolved() {
    let s = parse(
        r##"<defs><circle id="c" r="3" fill="black"/></defs><use href="#c" x="10" y="10"/><use href="#c" x="30" y="10"/>"##,
    );
    assert_eq!(s.len(), 2);
    assert!(close(bounds(&s[1]), (27.0, 7.0, 33.0, 13.0), 0.2));
}

#[test]
fn text_is_reported_not_silently_lost() {
    let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><text x="1" y="5">Hi</text><rect width="2" height="2"/></svg>"#;
    let r = parse_svg(svg, &ImportOptions::default()).unwrap();
    assert_eq!(r.strokes.len(), 1);
    assert!(r.warnings.iter().any(|w| w.contains("1 <text>")), "{:?}", r.warnings);
}

#[test]
fn bad_and_hostile_input_gets_clear_errors() {
    for (svg, want) in [("", "not well-formed"), ("<svg", "not well-formed"), ("<html></html>", "")] {
        let e = parse_svg(svg, &ImportOptions::default()).expect_err(svg).to_string();
        assert!(e.starts_with("Could not read the SVG") && e.contains(want), "{svg:?}: {e}");
    }
    // No size at all: the document is sized by its content rather than failing.
    let sizeless = r#"<svg xmlns="http://www.w3.org/2000/svg"><rect width="1" height="1"/></svg>"#;
    assert_eq!(parse_svg(sizeless, &ImportOptions::default()).unwrap().strokes.len(), 1);
    // Entity expansion bombs are refused by the XML parser, not expanded.
    let bomb = r#"<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;"><!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;"><!ENTITY d "&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;"><!ENTITY e "&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;"><!ENTITY f "&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;">]><svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 1 1"><text>&f;&f;&f;&f;&f;&f;&f;&f;</text></svg>"#;
    let _ = parse_svg(bomb, &ImportOptions::default()); // must return, either way
                                                        // Deep nesting does not overflow the stack.
    let deep = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 1 1">{}<rect width="1" height="1"/>{}</svg>"#,
        "<g>".repeat(2000),
        "</g>".repeat(2000)
    );
    let _ = parse_svg(&deep, &ImportOptions::default());
    let e = parse_svg("<svg/>", &ImportOptions { tolerance: 0.0, ..Default::default() }).unwrap_err();
    assert!(e.to_string().contains("tolerance"));
}

#[test]
fn round_trip_through_our_own_export() {
    use patternsynth::vector::svg::to_svg;
    let mut a = Stroke::new(vec![[1.0, 2.0], [3.0, 4.0], [5.0, 2.0]], 1.5, Some(Rgb([10, 20, 30])));
    a.fill = Some(Rgb([200, 100, 0]));
    a.fill_opacity = 0.5;
    a.closed = true;
    let b = Stroke::new(vec![[10.0, 10.0], [20.0, 15.0]], 3.0, Some(Rgb([0, 0, 0])));
    let svg = to_svg(&[a.clone(), b.clone()], &[], 50.0, 40.0);
    let back = parse_svg(&svg, &ImportOptions::default()).unwrap();
    assert_eq!((back.width, back.height), (50.0, 40.0));
    assert_eq!(back.strokes.len(), 2);
    assert_eq!(back.strokes[0].points, a.points);
    assert_eq!((back.strokes[0].fill, back.strokes[0].stroke), (a.fill, a.stroke));
    assert!((back.strokes[0].fill_opacity - 0.5).abs() < 1e-3 && back.strokes[0].closed);
    assert_eq!(back.strokes[1].points, b.points);
    assert!((back.strokes[1].width - 3.0).abs() < 1e-6);
}

#[test]
fn hostile_documents_get_clear_errors_not_overflows() {
    use patternsynth::vector::{parse_svg, ImportOptions};
    let opts = ImportOptions::default();
    let wrap = |body: String| format!("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 100 100\">{body}</svg>");
    let nested = wrap(format!("{}<rect width='2' height='2'/>{}", "<g>".repeat(300), "</g>".repeat(300)));
    let e = parse_svg(&nested, &opts).unwrap_err().to_string();
    assert!(e.contains("nests 302 levels deep"), "{e}");
    // Just under the limit still imports (the resolver's stack holds it).
    let ok = wrap(format!("{}<rect width='2' height='2'/>{}", "<g>".repeat(97), "</g>".repeat(97)));
    assert_eq!(parse_svg(&ok, &opts).unwrap().strokes.len(), 1);
    let chain: String = (1..=150).map(|i| format!("<use id='u{i}' href='#u{}'/>", i - 1)).collect();
    let e =
        parse_svg(&wrap(format!("<defs><rect id='u0' width='1' height='1'/>{chain}</defs><use href='#u150'/>")), &opts);
    assert!(e.unwrap_err().to_string().contains("levels deep"));
    let far = wrap(
        "<circle r='1e20'/><path d='M0 0 C1e30 1e30 -1e30 1e30 10 10' stroke='#000'/><rect width='3' height='3'/>"
            .into(),
    );
    let tiny = ImportOptions { tolerance: 1e-300, ..ImportOptions::default() };
    let import = parse_svg(&far, &tiny).unwrap();
    assert_eq!(import.strokes.len(), 1);
    assert!(import.warnings.iter().any(|w| w.contains("2 shape(s) lie beyond")), "{:?}", import.warnings);
}

#[test]
fn holes_stay_with_their_outline_and_the_report_says_so() {
    let svg = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/fixtures/svg/constructs/holes.svg"))
        .unwrap();
    let r = parse_svg(&svg, &ImportOptions::default()).unwrap();
    // A frame (even-odd), a ring (non-zero, counter-wound hole), and a path holding a
    // framed square beside a separate small square.
    assert_eq!(r.strokes.len(), 4, "{:?}", r.strokes.iter().map(|s| s.bounds()).collect::<Vec<_>>());
    assert_eq!(r.strokes[0].breaks.len(), 1);
    assert_eq!(r.strokes[0].fill_rule, patternsynth::vector::FillRule::Evenodd);
    assert_eq!(r.strokes[1].breaks.len(), 1);
    assert_eq!(r.strokes[1].fill_rule, patternsynth::vector::FillRule::Nonzero);
    assert_eq!((r.strokes[2].breaks.len(), r.strokes[3].breaks.len()), (1, 0));
    assert!(close(bounds(&r.strokes[3]), (125.0, 3.0, 131.0, 9.0), 1e-6));
    assert!(r.warnings.iter().any(|w| w.starts_with("3 shape(s) with holes")), "{:?}", r.warnings);
    assert!(r.warnings.iter().any(|w| w.starts_with("1 compound path(s) were split")), "{:?}", r.warnings);
    // The export keeps each as one path with its fill rule.
    let svg = patternsynth::vector::svg::to_svg(&r.strokes, &[], r.width, r.height);
    assert_eq!(svg.matches("<path").count(), 4);
    assert_eq!(svg.matches("fill-rule=\"evenodd\"").count(), 1);
}

#[test]
fn small_documents_that_backtracking_or_quadratic_parsing_would_hang_import_as_they_should() {
    // Issue 26: a descendant chain of 20 groups, 40 times, over 95 nested groups (C(95,
    // 20) ways to place it) matches nothing; the chain that does match still applies.
    let chain = format!(".nomatch {}rect {{ fill: #ff0000 }}", "g ".repeat(20)).repeat(40);
    let body = format!(
        "<style>{chain} g g g rect.hit {{ fill: #00ff00 }}</style>{}<rect width='5' height='5'/><rect class='hit' width='5' height='5'/>{}",
        "<g>".repeat(95),
        "</g>".repeat(95)
    );
    let strokes = parse(&body);
    assert_eq!(strokes.len(), 2);
    assert_eq!(strokes[0].fill, Some(Rgb([0, 0, 0])), "no rule matches the first rect");
    assert_eq!(strokes[1].fill, Some(Rgb([0, 255, 0])));
    // A style attribute of 500,000 declarations: the last one wins.
    let style = format!("{}fill: #0000ff", "fill: #ff0000; ".repeat(500_000));
    let strokes = parse(&format!("<rect width='5' height='5' style='{style}'/>"));
    assert_eq!(strokes[0].fill, Some(Rgb([0, 0, 255])));
    // One rule of 2,000 declarations is refused with the limit named.
    let rule = format!(
        "<svg xmlns='http://www.w3.org/2000/svg'><style>rect {{ {} }}</style><rect width='5' height='5'/></svg>",
        "fill: red; ".repeat(2_000)
    );
    let err = parse_svg(&rule, &ImportOptions::default()).unwrap_err().to_string();
    assert!(err.contains("2000 declarations") && err.contains("limit is 1000"), "{err}");
}
