//! The CSS cascade for the presentation properties the importer reads. An element's
//! declared value of a property comes from, lowest to highest: its presentation
//! attribute, matching `<style>` rules (by specificity, then source order), its `style`
//! attribute, and `!important` rules. Inheritance is the walker's job.

use super::selector::{Chain, Matcher};
use roxmltree::{Document, Node};
use simplecss::{AttributeOperator, Declaration, DeclarationTokenizer, PseudoClass, Selector, StyleSheet};

/// The properties the importer reads; others are not looked up.
const PROPERTIES: [&str; 14] = [
    "color",
    "display",
    "fill",
    "fill-opacity",
    "fill-rule",
    "font-size",
    "opacity",
    "stop-color",
    "stop-opacity",
    "stroke",
    "stroke-opacity",
    "stroke-width",
    "transform",
    "visibility",
];

/// The document's style sheet: every `<style>` element's rules, sorted by specificity
/// (stable, so source order breaks ties).
pub struct Sheet<'a> {
    rules: Vec<(Selector<'a>, Vec<Declaration<'a>>)>,
    /// Each rule's selector for linear matching (`None`: matched by simplecss).
    chains: Vec<Option<Chain>>,
    matcher: Matcher,
}

/// Declared values of one element: (property, value), at most one per property.
pub type Declared<'a> = Vec<(&'static str, &'a str)>;

impl<'a> Sheet<'a> {
    pub fn new(doc: &'a Document) -> Sheet<'a> {
        let mut sheet = StyleSheet::new();
        for node in doc.descendants().filter(|n| n.tag_name().name() == "style") {
            let css = node.attribute("type").is_none_or(|t| t.is_empty() || t == "text/css");
            if css {
                for text in node.children().filter_map(|c| c.text()) {
                    // Rule by rule: see `pieces`.
                    for rule in pieces(text, b'}') {
                        sheet.parse_more(rule);
                    }
                }
            }
        }
        // By specificity; rules of equal specificity keep their source order.
        let key = |s: &Selector| s.specificity().iter().fold(0.0, |k, &d| k * 256.0 + f64::from(d));
        let keys: Vec<f64> = sheet.rules.iter().map(|r| key(&r.selector)).collect();
        let mut rules: Vec<_> = sheet.rules.into_iter().map(|r| Some((r.selector, r.declarations))).collect();
        let rules: Vec<_> = crate::order::by_key(&keys).into_iter().filter_map(|i| rules[i].take()).collect();
        let chains = rules.iter().map(|(s, _)| Chain::of(s)).collect();
        Sheet { rules, chains, matcher: Matcher::default() }
    }

    /// The values `node` declares for the properties the importer reads.
    pub fn declared(&self, node: Node<'a, '_>) -> Declared<'a> {
        let mut out: Declared<'a> = Vec::new();
        for a in node.attributes().filter(|a| a.namespace().is_none()) {
            set(&mut out, a.name(), a.value());
        }
        let element = Element(node);
        let matched: Vec<&[Declaration<'a>]> = self
            .rules
            .iter()
            .zip(&self.chains)
            .enumerate()
            .filter(|(k, ((s, _), chain))| match chain {
                Some(c) => self.matcher.matches(*k, c, node),
                None => s.matches(&element),
            })
            .map(|(_, ((_, d), _))| d.as_slice())
            .collect();
        for d in matched.iter().flat_map(|d| d.iter()).filter(|d| !d.important) {
            set(&mut out, d.name, d.value);
        }
        if let Some(style) = node.attribute("style") {
            for d in pieces(style, b';').into_iter().filter_map(|p| DeclarationTokenizer::from(p).next()) {
                set(&mut out, d.name, d.value);
            }
        }
        for d in matched.iter().flat_map(|d| d.iter()).filter(|d| d.important) {
            set(&mut out, d.name, d.value);
        }
        out
    }
}

/// `text` cut after each `end` byte (`;` between declarations, or `}` closing a rule)
/// that stands outside strings, brackets, blocks and comments. simplecss reports where each declaration's value ends as an
/// error positioned by counting from the start of its text, so one text of `n`
/// declarations costs `n^2` (a `style` of 10,000 took 1.5 s, of 100,000 two minutes);
/// fed a rule or a declaration at a time, it stays linear.
pub(super) fn pieces(text: &str, end: u8) -> Vec<&str> {
    let bytes = text.as_bytes();
    let (mut out, mut start, mut depth, mut quote, mut i) = (Vec::new(), 0, 0i32, None, 0);
    while i < bytes.len() {
        let b = bytes[i];
        match quote {
            Some(_) if b == b'\\' => i += 1,
            Some(q) if b == q => quote = None,
            Some(_) => {}
            None if b == b'/' && bytes.get(i + 1) == Some(&b'*') => {
                i = text[i + 2..].find("*/").map_or(bytes.len(), |k| i + 2 + k + 1);
            }
            None if b == b'"' || b == b'\'' => quote = Some(b),
            None if matches!(b, b'(' | b'[' | b'{') => depth += 1,
            None if matches!(b, b')' | b']') || (b == b'}' && end != b'}') => depth -= 1,
            // A rule ends at the brace that closes it (an @media block's rules inside it).
            None if b == b'}' => {
                depth -= 1;
                if depth <= 0 {
                    out.push(&text[start..=i]);
                    start = i + 1;
                    depth = 0;
                }
            }
            None if b == end && depth <= 0 => {
                out.push(&text[start..=i]);
                start = i + 1;
            }
            None => {}
        }
        i += 1;
    }
    if start < bytes.len() {
        out.push(&text[start..]);
    }
    out
}

/// The declared value of `name`, if any.
pub fn get<'a>(declared: &Declared<'a>, name: &str) -> Option<&'a str> {
    declared.iter().find(|(n, _)| *n == name).map(|(_, v)| v.trim())
}

fn set<'a>(out: &mut Declared<'a>, name: &str, value: &'a str) {
    let Some(&name) = PROPERTIES.iter().find(|&&p| p == name) else { return };
    match out.iter_mut().find(|(n, _)| *n == name) {
        Some(slot) => slot.1 = value,
        None => out.push((name, value)),
    }
}

/// A roxmltree element as simplecss sees it.
pub(super) struct Element<'a, 'input>(pub(super) Node<'a, 'input>);

impl simplecss::Element for Element<'_, '_> {
    fn parent_element(&self) -> Option<Self> {
        self.0.parent_element().map(Element)
    }

    fn prev_sibling_element(&self) -> Option<Self> {
        self.0.prev_sibling_element().map(Element)
    }

    fn has_local_name(&self, name: &str) -> bool {
        self.0.tag_name().name() == name
    }

    fn attribute_matches(&self, local_name: &str, operator: AttributeOperator<'_>) -> bool {
        self.0.attribute(local_name).is_some_and(|v| operator.matches(v))
    }

    fn pseudo_class_matches(&self, class: PseudoClass<'_>) -> bool {
        matches!(class, PseudoClass::FirstChild) && self.0.prev_sibling_element().is_none()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pieces_cut_outside_strings_brackets_blocks_and_comments() {
        assert_eq!(
            pieces("fill:red; stroke:url('a;b'); /* x;y */ opacity:.5", b';'),
            vec!["fill:red;", " stroke:url('a;b');", " /* x;y */ opacity:.5"]
        );
        let css = "a { fill: red } @media print { b { fill: blue } } c{content:'}'}";
        assert_eq!(pieces(css, b'}'), vec!["a { fill: red }", " @media print { b { fill: blue } }", " c{content:'}'}"]);
    }

    #[test]
    fn attribute_then_rules_by_specificity_then_style_then_important() {
        let svg = r#"<svg xmlns="http://www.w3.org/2000/svg"><style>
            #a { fill: blue } rect { fill: red; stroke: green } .c { stroke: gold !important }
            </style><rect id="a" class="c" fill="black" stroke="black" style="stroke: pink; opacity: .5"/></svg>"#;
        let doc = Document::parse(svg).unwrap();
        let sheet = Sheet::new(&doc);
        let rect = doc.descendants().find(|n| n.tag_name().name() == "rect").unwrap();
        let d = sheet.declared(rect);
        assert_eq!(get(&d, "fill"), Some("blue"), "id beats type selector and attribute");
        assert_eq!(get(&d, "stroke"), Some("gold"), "!important beats the style attribute");
        assert_eq!(get(&d, "opacity"), Some(".5"));
        assert_eq!(get(&d, "id"), None, "only the properties the importer reads");
    }
}
