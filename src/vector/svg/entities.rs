//! How much text a document's internal entities expand to, measured on the source
//! before the XML parser expands them.
//!
//! roxmltree expands `&name;` references into the text and attribute values it keeps,
//! and detects reference loops, but not size: a 1 MB entity referenced 4,500 times
//! is 4.5 GB of text from a 1 MB file. Here the internal subset's general entities
//! (`<!ENTITY name "value">`) are read, each one's expanded length computed from the
//! references in its value (memoised; a loop counts as nothing more, roxmltree refuses
//! it), and the references in the rest of the document summed. The scan is linear in
//! the source. It overestimates only where a reference sits in a comment or a CDATA
//! section (which no parser expands).

use std::collections::HashMap;

/// The costliest entity of a document: its name, expanded length and references.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Costliest {
    pub name: String,
    pub bytes: u64,
    pub references: u64,
}

/// The bytes the entity references of `svg` expand to in all (saturating), and the
/// entity that contributes most. Zero for a document without an internal subset.
pub fn expansion(svg: &str) -> (u64, Option<Costliest>) {
    let Some((entities, body)) = internal_subset(svg) else { return (0, None) };
    if entities.is_empty() {
        return (0, None);
    }
    let mut sizes: HashMap<&str, u64> = HashMap::new();
    for name in entities.keys() {
        expanded(name, &entities, &mut sizes, &mut Vec::new());
    }
    let mut counts: HashMap<&str, u64> = HashMap::new();
    for name in references(body) {
        if entities.contains_key(name) {
            *counts.entry(name).or_default() += 1;
        }
    }
    let mut total = 0u64;
    let mut costliest: Option<Costliest> = None;
    for (name, references) in counts {
        let bytes = sizes[name];
        let cost = bytes.saturating_mul(references);
        total = total.saturating_add(cost);
        if costliest.as_ref().is_none_or(|c| cost > c.bytes.saturating_mul(c.references)) {
            costliest = Some(Costliest { name: name.to_string(), bytes, references });
        }
    }
    (total, costliest)
}

/// The internal subset's general entities (name to literal value), and the source
/// after the DOCTYPE.
fn internal_subset(svg: &str) -> Option<(HashMap<&str, &str>, &str)> {
    let start = svg.find("<!DOCTYPE")?;
    let open = start + svg[start..].find(['[', '>'])?;
    if svg.as_bytes()[open] != b'[' {
        return None;
    }
    let mut entities = HashMap::new();
    let mut at = open + 1;
    // Declarations until `]`: quoted values may hold `]` and `>`, so walk them.
    loop {
        let rest = &svg[at..];
        let next = rest.find(['<', ']'])?;
        at += next;
        if svg.as_bytes()[at] == b']' {
            let end = at + svg[at..].find('>')? + 1;
            return Some((entities, &svg[end..]));
        }
        let decl = &svg[at..];
        let close = declaration_end(decl)?;
        if let Some(body) = decl.strip_prefix("<!ENTITY") {
            if let Some((name, value)) = entity(&body[..close - "<!ENTITY".len()]) {
                entities.entry(name).or_insert(value);
            }
        }
        at += close + 1;
    }
}

/// The index of the `>` that ends the markup declaration at the start of `decl`,
/// skipping quoted strings and comments.
fn declaration_end(decl: &str) -> Option<usize> {
    if decl.starts_with("<!--") {
        return decl.find("-->").map(|i| i + 2);
    }
    let bytes = decl.as_bytes();
    let mut i = 1;
    while i < bytes.len() {
        match bytes[i] {
            b'>' => return Some(i),
            q @ (b'"' | b'\'') => i += 1 + decl[i + 1..].find(q as char)?,
            _ => {}
        }
        i += 1;
    }
    None
}

/// `name "value"` of a general entity declaration (parameter entities, `% name`, and
/// external ones, `SYSTEM ...`, are not expanded into the document by roxmltree).
fn entity(decl: &str) -> Option<(&str, &str)> {
    let decl = decl.trim_start();
    if decl.starts_with('%') {
        return None;
    }
    let name_end = decl.find(|c: char| c.is_whitespace())?;
    let (name, rest) = decl.split_at(name_end);
    let rest = rest.trim_start();
    let quote = rest.chars().next().filter(|c| *c == '"' || *c == '\'')?;
    let value = &rest[1..];
    Some((name, &value[..value.find(quote)?]))
}

/// The names of the `&name;` references in `text` (character references left out).
fn references(text: &str) -> impl Iterator<Item = &str> {
    text.match_indices('&').filter_map(move |(i, _)| {
        let rest = &text[i + 1..];
        let end = rest.find(';')?;
        let name = &rest[..end];
        let valid = !name.is_empty()
            && !name.starts_with('#')
            && name.chars().all(|c| c.is_alphanumeric() || matches!(c, '_' | '-' | '.' | ':'));
        valid.then_some(name)
    })
}

/// The expanded length of entity `name`, memoised in `sizes`; `open` holds the entities
/// being expanded (a reference back to one of them adds nothing).
fn expanded<'a>(
    name: &'a str,
    entities: &HashMap<&'a str, &'a str>,
    sizes: &mut HashMap<&'a str, u64>,
    open: &mut Vec<&'a str>,
) -> u64 {
    if let Some(&n) = sizes.get(name) {
        return n;
    }
    let Some(&value) = entities.get(name) else { return 0 };
    if open.contains(&name) || open.len() > 64 {
        return 0;
    }
    open.push(name);
    let mut bytes = value.len() as u64;
    for inner in references(value) {
        if entities.contains_key(inner) {
            let reference = inner.len() as u64 + 2;
            bytes = bytes.saturating_sub(reference).saturating_add(expanded(inner, entities, sizes, open));
        }
    }
    open.pop();
    sizes.insert(name, bytes);
    bytes
}

#[cfg(test)]
mod tests {
    use super::*;

    fn doc(entities: &str, body: &str) -> String {
        format!("<?xml version=\"1.0\"?><!DOCTYPE svg [{entities}]><svg>{body}</svg>")
    }

    #[test]
    fn counts_each_reference_at_its_expanded_length() {
        let svg =
            doc("<!ENTITY big \"xxxxxxxxxx\"><!ENTITY two '&big;&big;'>", "<text>&big;&two;&two;&amp;&#38;</text>");
        let (total, costliest) = expansion(&svg);
        assert_eq!(total, 10 + 2 * 20);
        assert_eq!(costliest, Some(Costliest { name: "two".into(), bytes: 20, references: 2 }));
    }

    #[test]
    fn nested_entities_multiply_and_loops_end() {
        let mut decls = "<!ENTITY l0 \"lol\">".to_string();
        for k in 1..10 {
            decls += &format!("<!ENTITY l{k} \"{}\">", format!("&l{};", k - 1).repeat(10));
        }
        assert_eq!(expansion(&doc(&decls, "&l9;")).0, 3 * 10u64.pow(9));
        let looped = doc("<!ENTITY a \"x&b;\"><!ENTITY b \"y&a;\">", "&a;");
        assert!(expansion(&looped).0 < 10);
    }

    #[test]
    fn quoted_brackets_comments_and_parameter_entities() {
        let svg = doc("<!-- ] > --><!ENTITY % p \"zzzz\"><!ENTITY e 'a]>b'>", "&e;&p;");
        assert_eq!(expansion(&svg).0, 4);
        assert_eq!(expansion("<svg>&e;</svg>").0, 0);
        assert_eq!(expansion("<!DOCTYPE svg><svg/>").0, 0);
    }
}
