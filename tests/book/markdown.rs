//! Markdown and mdBook syntax as the book checks read it: code fences (`includes`,
//! `numbers`), mdBook's `{{#include}}` directives and their selectors, anchors, images
//! (`includes`).

/// An opening or closing code fence: (fence char, run length, info string).
pub fn fence(line: &str) -> Option<(char, usize, &str)> {
    let trimmed = line.trim_start();
    let c = trimmed.chars().next()?;
    if c != '`' && c != '~' {
        return None;
    }
    let len = trimmed.chars().take_while(|&x| x == c).count();
    (len >= 3).then(|| (c, len, trimmed[len..].trim()))
}

/// A `{{#name args}}` directive found in a line of Markdown.
#[derive(Debug, PartialEq, Eq)]
pub(crate) struct Directive<'a> {
    pub(crate) name: &'a str,
    pub(crate) args: &'a str,
}

/// All unescaped `{{#name args}}` directives in `line`, in order.
pub(crate) fn directives(line: &str) -> Vec<Directive<'_>> {
    let mut found = Vec::new();
    let mut rest = line;
    let mut offset = 0;
    while let Some(start) = rest.find("{{") {
        let abs = offset + start;
        let escaped = abs > 0 && line.as_bytes()[abs - 1] == b'\\';
        let after = &rest[start + 2..];
        let Some(end) = after.find("}}") else { break };
        let inner = after[..end].trim_start();
        if !escaped && let Some(body) = inner.strip_prefix('#') {
            let name_len = body
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .unwrap_or(body.len());
            let (name, args) = body.split_at(name_len);
            if !name.is_empty() {
                found.push(Directive {
                    name,
                    args: args.trim(),
                });
            }
        }
        let consumed = start + 2 + end + 2;
        offset += consumed;
        rest = &rest[consumed..];
    }
    found
}

/// What part of a file an include selects.
#[derive(Debug, PartialEq, Eq)]
pub(crate) enum Selector<'a> {
    All,
    Anchor(&'a str),
    /// 1-based, inclusive line numbers as mdBook reads them.
    Lines {
        start: Option<usize>,
        end: Option<usize>,
    },
}

/// Split `path[:anchor | :start[:end] | ::end]` the way mdBook does.
pub(crate) fn parse_include(args: &str) -> Result<(&str, Selector<'_>), String> {
    let (path, sel) = match args.split_once(':') {
        None => return Ok((args, Selector::All)),
        Some((path, sel)) => (path, sel.trim()),
    };
    if sel.is_empty() {
        return Ok((path, Selector::All));
    }
    let (first, second) = match sel.split_once(':') {
        None => (sel, None),
        Some((a, b)) => (a, Some(b)),
    };
    let number = |s: &str| -> Result<Option<usize>, String> {
        if s.is_empty() {
            Ok(None)
        } else {
            s.parse::<usize>()
                .map(Some)
                .map_err(|_| format!("bad line number `{s}` in `{args}`"))
        }
    };
    if !first.is_empty() && !first.starts_with(|c: char| c.is_ascii_digit()) {
        if second.is_some() {
            return Err(format!("anchor name with a `:` in `{args}`"));
        }
        return Ok((path, Selector::Anchor(first)));
    }
    let start = number(first)?;
    let end = match second {
        // `path:N` selects the single line N.
        None => start,
        Some(s) => number(s)?,
    };
    Ok((path, Selector::Lines { start, end }))
}

/// Does `text` contain `marker` immediately followed by the identifier `name`?
pub(crate) fn has_marker(text: &str, marker: &str, name: &str) -> bool {
    text.lines().any(|line| {
        let mut rest = line;
        while let Some(i) = rest.find(marker) {
            let after = rest[i + marker.len()..].trim_start();
            let ident_len = after
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == '-'))
                .unwrap_or(after.len());
            if &after[..ident_len] == name {
                return true;
            }
            rest = &rest[i + marker.len()..];
        }
        false
    })
}

/// The 1-based line on which an insta snapshot's content starts: the line after the
/// second `---`.
pub(crate) fn snapshot_body_start(text: &str) -> usize {
    text.lines()
        .enumerate()
        .filter(|(_, l)| l.trim_end() == "---")
        .nth(1)
        .map_or(1, |(i, _)| i + 2)
}

pub(crate) fn is_remote_or_absolute(target: &str) -> bool {
    target.is_empty()
        || target.starts_with('#')
        || target.starts_with('/')
        || target.starts_with("data:")
        || target.starts_with("mailto:")
        || target.contains("://")
        || target.starts_with("//")
}

/// Drop `#fragment` and `?query` from a link target.
pub(crate) fn strip_fragment(target: &str) -> &str {
    let end = target.find(['#', '?']).unwrap_or(target.len());
    &target[..end]
}

/// Remove inline code spans so that examples like `` `![x](y)` `` are ignored.
pub(crate) fn without_code_spans(line: &str) -> String {
    let mut out = String::with_capacity(line.len());
    let mut in_code = false;
    for c in line.chars() {
        if c == '`' {
            in_code = !in_code;
        } else if !in_code {
            out.push(c);
        }
    }
    out
}

/// Image targets in a line: `![alt](path "title")` and `<img ... src="path">`.
pub(crate) fn image_targets(line: &str) -> Vec<String> {
    let line = without_code_spans(line);
    let mut found = Vec::new();
    let mut rest = line.as_str();
    while let Some(i) = rest.find("![") {
        rest = &rest[i + 2..];
        let Some(close) = rest.find("](") else { break };
        let after = &rest[close + 2..];
        let Some(end) = after.find(')') else { break };
        let inside = after[..end].trim();
        let target = inside
            .strip_prefix('<')
            .and_then(|s| s.split_once('>').map(|(t, _)| t))
            .unwrap_or_else(|| inside.split_whitespace().next().unwrap_or(""));
        found.push(target.to_string());
        rest = &after[end..];
    }
    let lower = line.to_ascii_lowercase();
    let mut from = 0;
    while let Some(i) = lower[from..].find("<img") {
        let tag_start = from + i;
        let tag_end = lower[tag_start..]
            .find('>')
            .map_or(lower.len(), |e| tag_start + e);
        let tag = &line[tag_start..tag_end];
        let tag_lower = &lower[tag_start..tag_end];
        if let Some(s) = tag_lower.find("src=") {
            let value = &tag[s + 4..];
            let target = match value.chars().next() {
                Some(q @ ('"' | '\'')) => value[1..].split(q).next().unwrap_or(""),
                _ => value
                    .split_whitespace()
                    .next()
                    .unwrap_or("")
                    .trim_end_matches('/'),
            };
            found.push(target.to_string());
        }
        from = tag_end;
    }
    found
}

pub(crate) fn is_rust_info(info: &str) -> bool {
    info.split([',', ' ', '\t'])
        .next()
        .is_some_and(|lang| lang == "rust")
}

#[test]
fn include_syntax_is_parsed_like_mdbook() {
    assert_eq!(parse_include("a.rs"), Ok(("a.rs", Selector::All)));
    assert_eq!(parse_include("a.rs:x"), Ok(("a.rs", Selector::Anchor("x"))));
    assert_eq!(
        parse_include("a.rs:3"),
        Ok((
            "a.rs",
            Selector::Lines {
                start: Some(3),
                end: Some(3)
            }
        ))
    );
    assert_eq!(
        parse_include("a.rs::7"),
        Ok((
            "a.rs",
            Selector::Lines {
                start: None,
                end: Some(7)
            }
        ))
    );
    assert_eq!(
        parse_include("a.rs:2:"),
        Ok((
            "a.rs",
            Selector::Lines {
                start: Some(2),
                end: None
            }
        ))
    );
    assert_eq!(
        directives(r"x {{#include a.rs:b}} \{{#include c}} {{ #title T }}"),
        vec![
            Directive {
                name: "include",
                args: "a.rs:b"
            },
            Directive {
                name: "title",
                args: "T"
            },
        ]
    );
}
