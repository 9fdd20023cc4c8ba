//! What an SVG document will make the parser and the resolver do, measured before they
//! run, so a hostile document gets a clear refusal instead of a stack overflow or a hang.
//!
//! Four costs are not bounded by the document's size alone:
//! - **Depth.** The importer resolves the tree recursively, one stack frame chain per
//!   nesting level and per reference hop (`<use>`, `href`); a few thousand levels
//!   overflow the wasm stack, and that kills the instance, not just the call.
//! - **Attributes per element.** roxmltree compares each attribute of an element with
//!   every other one (duplicate check), which is quadratic in attributes per element.
//! - **CSS.** The importer matches every style-sheet rule against every element it
//!   draws, including the copies `<use>` makes: rules x elements selector matches
//!   (each in time linear in the chain, `selector`); and the CSS parser's work on one
//!   rule is quadratic in its declarations.
//! - **Entities.** References to internal entities expand into the parsed text
//!   (`entities`): a few of them nested are gigabytes.

use crate::error::megabytes;
use crate::error::{Error, Result};
use roxmltree::{Document, Node};
use std::collections::HashMap;

/// Deepest nesting accepted, counting element levels and reference hops together.
/// Real drawings stay below 30; the resolver's stack holds well over twice this.
pub const MAX_DEPTH: u32 = 100;
/// Attribute comparisons the XML parser may make (about a second in wasm).
pub const MAX_ATTRIBUTE_PAIRS: u64 = 20_000_000;
/// Style-sheet rules accepted: far beyond any drawing's, and every rule is matched
/// against every element drawn.
pub const MAX_CSS_RULES: u64 = 2_000;
/// CSS selector matches the resolver may make (rules x elements, after `<use>` copies).
pub const MAX_CSS_MATCHES: u64 = 20_000_000;
/// Declarations in one style-sheet rule: simplecss's parse of a rule is quadratic in
/// them (10,000 take 1.5 s; 1,000, 15 ms), and no drawing's rule holds a hundred.
pub const MAX_CSS_DECLARATIONS: u64 = 1_000;
/// Elements after `<use>` expansion.
pub const MAX_EXPANDED_ELEMENTS: u64 = 1_000_000;

/// Attribute comparisons roxmltree's duplicate check will make: the sum over start
/// tags of n(n-1)/2, with n the `=` signs between `<name` and the tag's end. Counting
/// `=` inside values too only overestimates. Linear in the source, run before parsing.
pub fn attribute_pairs(svg: &str) -> u64 {
    let bytes = svg.as_bytes();
    let (mut pairs, mut i) = (0u64, 0);
    while i < bytes.len() {
        if bytes[i] == b'<' && bytes.get(i + 1).is_some_and(|c| c.is_ascii_alphabetic() || *c == b'_' || *c == b':') {
            let mut n = 0u64;
            i += 1;
            while i < bytes.len() && bytes[i] != b'>' && bytes[i] != b'<' {
                n += u64::from(bytes[i] == b'=');
                i += 1;
            }
            pairs = pairs.saturating_add(n * n.saturating_sub(1) / 2);
        } else {
            i += 1;
        }
    }
    pairs
}

/// Text the document's entity references may expand to (as much as the largest
/// document accepted).
pub const MAX_ENTITY_TEXT: u64 = super::import::MAX_SVG_BYTES as u64;

/// Refuses a source whose attribute check alone would take seconds, or whose entities
/// expand past `MAX_ENTITY_TEXT`.
pub fn check_source(svg: &str) -> Result<()> {
    if let (total, Some(e)) = super::entities::expansion(svg) {
        if total > MAX_ENTITY_TEXT {
            return Err(Error::TooLarge(format!(
                "The SVG's entities expand to {} of text (`&{};`, {}, is used {} times); the limit is {}.",
                megabytes(total),
                e.name,
                megabytes(e.bytes),
                e.references,
                megabytes(MAX_ENTITY_TEXT)
            )));
        }
    }
    let pairs = attribute_pairs(svg);
    if pairs > MAX_ATTRIBUTE_PAIRS {
        return Err(Error::TooLarge(format!(
            "The SVG has elements with thousands of attributes ({pairs} attribute pairs to check; the limit is {MAX_ATTRIBUTE_PAIRS})."
        )));
    }
    Ok(())
}

/// The shape of a parsed document, as far as the resolver's cost goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shape {
    /// Longest chain of nesting levels and reference hops.
    pub depth: u32,
    /// Elements after `<use>` copies (saturating).
    pub expanded: u64,
    /// Style-sheet rules (one per selector of a comma list).
    pub css_rules: u64,
    /// The most declarations (`;`-separated) in one block of a style sheet.
    pub css_declarations: u64,
    /// `<text>` elements (left out without fonts; reported).
    pub texts: usize,
}

/// Measures `doc` without recursion: an explicit-stack post-order walk over elements,
/// their child elements and the elements they reference. A reference cycle counts as
/// a leaf here (the importer draws nothing for a recursive reference).
pub fn measure(doc: &Document) -> Shape {
    let nodes: Vec<Node> = doc.descendants().filter(|n| n.is_element()).collect();
    let index: HashMap<_, usize> = nodes.iter().enumerate().map(|(i, n)| (n.id(), i)).collect();
    let by_id: HashMap<&str, usize> =
        nodes.iter().enumerate().filter_map(|(i, n)| n.attribute("id").map(|id| (id, i))).collect();

    // Edges: child elements, then references; `copies` marks the edges the importer expands
    // into new elements (a `<use>`'s target), the others it converts once.
    let mut edges: Vec<Vec<(usize, bool)>> = vec![Vec::new(); nodes.len()];
    let mut css_rules = 0;
    let mut css_declarations = 0;
    let mut texts = 0;
    for (i, n) in nodes.iter().enumerate() {
        let is_use = n.tag_name().name() == "use";
        edges[i].extend(n.children().filter_map(|c| index.get(&c.id())).map(|&c| (c, true)));
        for a in n.attributes() {
            let value = a.value();
            let target = if a.name() == "href" { value.strip_prefix('#') } else { None };
            let targets = target.into_iter().chain(url_refs(value));
            for t in targets.filter_map(|t| by_id.get(t)) {
                edges[i].push((*t, is_use && a.name() == "href"));
            }
        }
        match n.tag_name().name() {
            "style" => {
                css_rules += n.text().map(count_rules).unwrap_or(0);
                css_declarations = css_declarations.max(n.text().map(most_declarations).unwrap_or(0));
            }
            "text" => texts += 1,
            _ => {}
        }
    }

    const NEW: u8 = 0;
    const OPEN: u8 = 1;
    const DONE: u8 = 2;
    let mut state = vec![NEW; nodes.len()];
    let mut depth = vec![0u32; nodes.len()];
    let mut size = vec![0u64; nodes.len()];
    let (mut max_depth, mut expanded) = (0, 0u64);
    for root in 0..nodes.len() {
        if state[root] != NEW {
            continue;
        }
        let mut stack = vec![(root, 0usize)];
        state[root] = OPEN;
        while let Some(&mut (n, ref mut next)) = stack.last_mut() {
            if let Some(&(m, _)) = edges[n].get(*next) {
                *next += 1;
                if state[m] == NEW {
                    state[m] = OPEN;
                    stack.push((m, 0));
                }
                continue;
            }
            // All edges done: a cycle's open targets count as leaves.
            let (mut d, mut s) = (0u32, 1u64);
            for &(m, copies) in &edges[n] {
                if state[m] == DONE {
                    d = d.max(depth[m]);
                    if copies {
                        s = s.saturating_add(size[m]);
                    }
                }
            }
            depth[n] = d + 1;
            size[n] = s;
            state[n] = DONE;
            stack.pop();
        }
        max_depth = max_depth.max(depth[root]);
        expanded = expanded.max(size[root]);
    }
    Shape { depth: max_depth, expanded, css_rules, css_declarations, texts }
}

/// Refuses a document whose resolution would overflow the stack or take minutes.
pub fn check(shape: &Shape) -> Result<()> {
    if shape.depth > MAX_DEPTH {
        return Err(Error::TooLarge(format!(
            "The SVG nests {} levels deep (groups inside groups, or <use> and url(#...) references in a chain); the limit is {MAX_DEPTH}.",
            shape.depth
        )));
    }
    if shape.expanded > MAX_EXPANDED_ELEMENTS {
        return Err(Error::TooLarge(format!(
            "The SVG's <use> copies expand to more than {MAX_EXPANDED_ELEMENTS} elements."
        )));
    }
    if shape.css_rules > MAX_CSS_RULES {
        return Err(Error::TooLarge(format!(
            "The SVG's style sheet has {} rules; the limit is {MAX_CSS_RULES}: inline the styles or remove unused rules.",
            shape.css_rules
        )));
    }
    if shape.css_declarations > MAX_CSS_DECLARATIONS {
        return Err(Error::TooLarge(format!(
            "The SVG's style sheet has a rule of {} declarations; the limit is {MAX_CSS_DECLARATIONS}.",
            shape.css_declarations
        )));
    }
    let matches = shape.expanded.saturating_mul(shape.css_rules);
    if matches > MAX_CSS_MATCHES {
        return Err(Error::TooLarge(format!(
            "The SVG's style sheet has {} rules for {} elements ({matches} selector matches; the limit is {MAX_CSS_MATCHES}): inline the styles or remove unused rules.",
            shape.css_rules, shape.expanded
        )));
    }
    Ok(())
}

/// The ids in `url(#id)` references of an attribute value.
fn url_refs(value: &str) -> impl Iterator<Item = &str> {
    value.split("url(").skip(1).filter_map(|rest| {
        let rest = rest.trim_start().trim_start_matches(['"', '\'']).strip_prefix('#')?;
        rest.split([')', '"', '\'']).next()
    })
}

/// The most `;` in one block of a sheet (strings and comments not special-cased: an
/// overestimate).
fn most_declarations(css: &str) -> u64 {
    let (mut most, mut here) = (0u64, 0u64);
    for c in css.bytes() {
        match c {
            b'{' | b'}' => here = 0,
            b';' => {
                here += 1;
                most = most.max(here);
            }
            _ => {}
        }
    }
    most
}

/// Style rules in a sheet: one per selector of each block (`a, b { }` is two), as the
/// resolver stores them. Comments and strings are not special-cased: an overestimate.
fn count_rules(css: &str) -> u64 {
    let (mut rules, mut selectors, mut level) = (0u64, 1u64, 0u32);
    for c in css.chars() {
        match c {
            '{' => {
                if level == 0 {
                    rules += selectors;
                }
                level += 1;
            }
            '}' => {
                level = level.saturating_sub(1);
                selectors = 1;
            }
            ',' if level == 0 => selectors += 1,
            _ => {}
        }
    }
    rules
}

#[cfg(test)]
mod tests {
    use super::*;
    use roxmltree::Document;

    fn shape(svg: &str) -> Shape {
        measure(&Document::parse(svg).unwrap())
    }

    #[test]
    fn depth_counts_levels_and_reference_hops() {
        let nested = format!("<svg>{}<rect/>{}</svg>", "<g>".repeat(10), "</g>".repeat(10));
        assert_eq!(shape(&nested).depth, 12);
        let chain: String = (1..=20).map(|i| format!("<use id='u{i}' href='#u{}'/>", i - 1)).collect();
        let s = shape(&format!("<svg><rect id='u0'/>{chain}</svg>"));
        assert_eq!(s.depth, 22);
        assert_eq!(s.expanded, 1 + 21 + 20 * 21 / 2, "each use copies the chain below it");
        let clip = "<svg><clipPath id='c'><rect clip-path='url(#d)'/></clipPath><clipPath id='d'><rect/></clipPath><g clip-path=\"url('#c')\"/></svg>";
        assert_eq!(shape(clip).depth, 6, "svg, g, clipPath, rect, clipPath, rect");
    }

    #[test]
    fn cycles_terminate() {
        let s = shape("<svg><use id='a' href='#b'/><use id='b' href='#a'/><g id='c' fill='url(#c)'/></svg>");
        assert!(s.depth <= 3, "{s:?}");
    }

    #[test]
    fn css_rules_and_attribute_pairs() {
        assert_eq!(count_rules(".a{fill:red} .b, .c {stroke:blue} @media x { .d {} }"), 4);
        assert_eq!(most_declarations(".a{fill:red;stroke:blue;} .b{opacity:1}"), 2);
        let long = format!("<svg><style>.a{{{}}}</style></svg>", "fill:red;".repeat(1_001));
        let err = check(&shape(&long)).unwrap_err().to_string();
        assert!(err.contains("1001 declarations") && err.contains("limit is 1000"), "{err}");
        assert_eq!(attribute_pairs("<svg a='1' b='2' c='3'><g x='1'/></svg>"), 3);
        let many: String = (0..7000).map(|i| format!(" a{i}='1'")).collect();
        assert!(check_source(&format!("<svg{many}/>")).is_err());
    }
}
