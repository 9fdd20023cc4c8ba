//! CSS selector matching in time linear in the document.
//!
//! Matched right to left by backtracking (as simplecss does), a chain of descendant
//! combinators tries every way of placing its compounds on the element's ancestors:
//! `.nomatch g g g g g g rect` on a rect inside 95 nested groups is C(95, 6), about 1e9
//! tries, from a 400-byte document. Here, as browsers' style engines do, each answer
//! "compound `i` matches element `e`" and "some ancestor-or-self of `e` matches
//! compound `i`" is remembered, so each (compound, element) pair is decided once.
//!
//! The selectors come parsed by simplecss (which also gives their specificity); its
//! parts are private, so a selector is read back from its text form into compounds.

use roxmltree::{Node, NodeId};
use simplecss::{AttributeOperator, Selector, SelectorToken, SelectorTokenizer};
use std::cell::RefCell;
use std::collections::{HashMap, HashSet};

/// A test of one element: what a compound selector is made of.
#[derive(Clone, Debug)]
enum Test {
    Type(String),
    /// An attribute that exists, equals, holds the word, or starts with the value and a
    /// dash (`class` and `id` selectors are attribute tests).
    Attribute(String, Op),
    FirstChild,
    /// A pseudo-class a static document never has (`:hover`, `:lang()`).
    Never,
}

#[derive(Clone, Debug)]
enum Op {
    Exists,
    Matches(String),
    Contains(String),
    StartsWith(String),
}

/// How a compound relates to the one on its left.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Combinator {
    None,
    Descendant,
    Child,
    Adjacent,
}

/// A selector as its compounds, left to right, each with the combinator on its left.
#[derive(Clone, Debug)]
pub struct Chain(Vec<(Combinator, Vec<Test>)>);

impl Chain {
    /// The chain of `selector`, or `None` when its text form does not read back.
    pub fn of(selector: &Selector) -> Option<Chain> {
        let text = selector.to_string();
        let mut compounds: Vec<(Combinator, Vec<Test>)> = vec![(Combinator::None, Vec::new())];
        for token in SelectorTokenizer::from(text.as_str()) {
            let test = match token.ok()? {
                SelectorToken::UniversalSelector => continue,
                SelectorToken::TypeSelector(t) => Test::Type(t.to_string()),
                SelectorToken::ClassSelector(c) => Test::Attribute("class".into(), Op::Contains(c.into())),
                SelectorToken::IdSelector(i) => Test::Attribute("id".into(), Op::Matches(i.into())),
                SelectorToken::AttributeSelector(name, op) => Test::Attribute(
                    name.into(),
                    match op {
                        AttributeOperator::Exists => Op::Exists,
                        AttributeOperator::Matches(v) => Op::Matches(v.into()),
                        AttributeOperator::Contains(v) => Op::Contains(v.into()),
                        AttributeOperator::StartsWith(v) => Op::StartsWith(v.into()),
                    },
                ),
                SelectorToken::PseudoClass("first-child") => Test::FirstChild,
                SelectorToken::PseudoClass(_) | SelectorToken::LangPseudoClass(_) => Test::Never,
                SelectorToken::DescendantCombinator => {
                    compounds.push((Combinator::Descendant, Vec::new()));
                    continue;
                }
                SelectorToken::ChildCombinator => {
                    compounds.push((Combinator::Child, Vec::new()));
                    continue;
                }
                SelectorToken::AdjacentCombinator => {
                    compounds.push((Combinator::Adjacent, Vec::new()));
                    continue;
                }
            };
            compounds.last_mut().expect("one at least").1.push(test);
        }
        Some(Chain(compounds))
    }
}

/// An attribute value past this many bytes is split into a set of its words once, so
/// that `~=` and class tests against it take constant time: a `class` of 60,000 words
/// tested by 2,000 rules of 100 classes is 1.2e10 word comparisons scanned each time.
const WORD_SET_BYTES: usize = 256;

/// Matches chains against the elements of one document, remembering every answer.
#[derive(Default)]
pub struct Matcher {
    /// (chain, compound, element, ancestor-or-self?) -> answer.
    memo: RefCell<HashMap<(usize, usize, NodeId, bool), bool>>,
    /// The words of long attribute values, by element and attribute name.
    words: RefCell<HashMap<(NodeId, String), HashSet<String>>>,
}

impl Matcher {
    /// Whether `node` matches `chain` (number `key` among the document's chains).
    pub fn matches(&self, key: usize, chain: &Chain, node: Node) -> bool {
        self.compound(key, chain, chain.0.len() - 1, node)
    }

    /// Whether `node` passes every test of a compound.
    fn passes(&self, tests: &[Test], node: Node) -> bool {
        tests.iter().all(|t| match t {
            Test::Type(name) => node.tag_name().name() == name,
            Test::Attribute(name, Op::Contains(word)) => node.attribute(name.as_str()).is_some_and(|v| {
                // Words are whitespace-separated (simplecss splits at spaces only).
                if v.len() <= WORD_SET_BYTES {
                    return v.split_ascii_whitespace().any(|w| w == word);
                }
                let mut words = self.words.borrow_mut();
                let set = words
                    .entry((node.id(), name.clone()))
                    .or_insert_with(|| v.split_ascii_whitespace().map(str::to_string).collect());
                set.contains(word.as_str())
            }),
            Test::Attribute(name, op) => node.attribute(name.as_str()).is_some_and(|v| {
                let op = match op {
                    Op::Exists => AttributeOperator::Exists,
                    Op::Matches(s) => AttributeOperator::Matches(s),
                    Op::Contains(s) => AttributeOperator::Contains(s),
                    Op::StartsWith(s) => AttributeOperator::StartsWith(s),
                };
                op.matches(v)
            }),
            Test::FirstChild => node.prev_sibling_element().is_none(),
            Test::Never => false,
        })
    }

    /// Whether compound `i` (and the chain left of it) matches `node`.
    fn compound(&self, key: usize, chain: &Chain, i: usize, node: Node) -> bool {
        let (combinator, tests) = &chain.0[i];
        if !self.passes(tests, node) {
            return false;
        }
        match combinator {
            Combinator::None => true,
            Combinator::Child => node.parent_element().is_some_and(|p| self.remembered(key, chain, i - 1, p, false)),
            Combinator::Adjacent => {
                node.prev_sibling_element().is_some_and(|p| self.remembered(key, chain, i - 1, p, false))
            }
            Combinator::Descendant => {
                node.parent_element().is_some_and(|p| self.remembered(key, chain, i - 1, p, true))
            }
        }
    }

    /// `compound(i, node)`, or with `up` whether `node` or one of its ancestors
    /// matches it, remembered.
    fn remembered(&self, key: usize, chain: &Chain, i: usize, node: Node, up: bool) -> bool {
        if let Some(&known) = self.memo.borrow().get(&(key, i, node.id(), up)) {
            return known;
        }
        // Walk up first without recursing (deep documents would otherwise recurse once
        // per level), then fill the answers in from the top down.
        let answer = if up {
            let mut path = vec![node];
            while let Some(p) = path.last().and_then(|n| n.parent_element()) {
                if self.memo.borrow().contains_key(&(key, i, p.id(), true)) {
                    path.push(p);
                    break;
                }
                path.push(p);
            }
            let mut above = false;
            for &n in path.iter().rev() {
                let known = self.memo.borrow().get(&(key, i, n.id(), true)).copied();
                above = match known {
                    Some(k) => k,
                    None => above || self.compound(key, chain, i, n),
                };
                self.memo.borrow_mut().insert((key, i, n.id(), true), above);
            }
            above
        } else {
            self.compound(key, chain, i, node)
        };
        self.memo.borrow_mut().insert((key, i, node.id(), up), answer);
        answer
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use roxmltree::Document;

    fn check(svg: &str, selector: &str) {
        let doc = Document::parse(svg).unwrap();
        let s = Selector::parse(selector).unwrap();
        let chain = Chain::of(&s).unwrap();
        let m = Matcher::default();
        for n in doc.descendants().filter(|n| n.is_element()) {
            let theirs = s.matches(&super::super::style::Element(n));
            assert_eq!(m.matches(0, &chain, n), theirs, "{selector} on {:?}", n.tag_name().name());
        }
    }

    #[test]
    fn agrees_with_backtracking_on_every_combinator() {
        let svg = r#"<svg xmlns="http://www.w3.org/2000/svg"><g class="a b" id="x"><g><rect/><circle lang="en-us"/></g>
            <path class="b"/><rect data-k="v"/></g><g class="c"><rect/></g></svg>"#;
        for s in [
            "rect",
            "g rect",
            ".a rect",
            ".a > rect",
            ".a > g > rect",
            "g g rect",
            "svg > g.c rect",
            "path + rect",
            "g + g rect",
            "#x rect:first-child",
            "[data-k=v]",
            "[lang|=en]",
            ".b",
            "*",
            "rect:hover",
            ".nomatch g rect",
        ] {
            check(svg, s);
        }
    }

    #[test]
    fn a_long_descendant_chain_over_deep_nesting_is_linear() {
        let depth = 400;
        let svg = format!(
            r#"<svg xmlns="http://www.w3.org/2000/svg">{}<rect/>{}</svg>"#,
            "<g>".repeat(depth),
            "</g>".repeat(depth)
        );
        let doc = Document::parse(&svg).unwrap();
        let s = Selector::parse(".nomatch g g g g g g g g g g g g g g g g g g g g rect").unwrap();
        let chain = Chain::of(&s).unwrap();
        let m = Matcher::default();
        let rect = doc.descendants().find(|n| n.tag_name().name() == "rect").unwrap();
        assert!(!m.matches(0, &chain, rect));
        // Each (compound, element) pair decided once: about 21 x 400 answers, not C(400, 20).
        assert!(m.memo.borrow().len() < 3 * 21 * (depth + 2), "{}", m.memo.borrow().len());
    }

    #[test]
    fn a_long_class_list_is_split_once() {
        let classes: Vec<String> = (0..5000).map(|k| format!("c{k}")).collect();
        let svg = format!(r#"<svg xmlns="http://www.w3.org/2000/svg"><rect class="{}"/></svg>"#, classes.join(" \t"));
        let doc = Document::parse(&svg).unwrap();
        let rect = doc.descendants().find(|n| n.tag_name().name() == "rect").unwrap();
        let m = Matcher::default();
        let compound = |ks: &[usize]| ks.iter().map(|k| format!(".c{k}")).collect::<String>();
        for (key, (ks, want)) in
            [(vec![0, 17, 4999], true), (vec![1, 2, 3, 4], true), (vec![3, 5000], false), (vec![12, 49999], false)]
                .into_iter()
                .enumerate()
        {
            let chain = Chain::of(&Selector::parse(&compound(&ks)).unwrap()).unwrap();
            assert_eq!(m.matches(key, &chain, rect), want, "{ks:?}");
        }
        assert_eq!(m.words.borrow().len(), 1, "one word set for the one long attribute");
    }
}
