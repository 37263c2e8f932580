//! Numbers as the book and its sources print them (shared by `quotes` and `numbers`):
//! a value and the unit of its last digit, the numbers of a table cell, the lines of
//! an anchored region.

/// A number as a chapter or a fragment prints it: its value and the size of one
/// unit of its last digit (0.01 for "4.96", 1e-6 for "3.7e-5", 1e-6 for
/// `3.7\cdot 10^{-5}`). Digits may be grouped by single spaces ("10 939").
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Printed {
    pub(crate) value: f64,
    pub(crate) unit: f64,
}

/// The number at the start of `text`, and the rest of the text after it.
pub(crate) fn printed(text: &str) -> Option<(Printed, &str)> {
    let bytes = text.as_bytes();
    let mut i = 0;
    let mut digits = String::new();
    if bytes.first() == Some(&b'-') || text.starts_with('−') {
        digits.push('-');
        i += if bytes[0] == b'-' {
            1
        } else {
            '−'.len_utf8()
        };
    }
    let start = i;
    while i < bytes.len() {
        let c = bytes[i];
        if c.is_ascii_digit() {
            digits.push(c as char);
            i += 1;
        } else if c == b' '
            && i > start
            && bytes.len() >= i + 4
            && bytes[i + 1..i + 4].iter().all(u8::is_ascii_digit)
            && bytes.get(i + 4).is_none_or(|b| !b.is_ascii_digit())
        {
            i += 1; // a digit group: "10 939"
        } else {
            break;
        }
    }
    if i == start {
        return None;
    }
    let mut decimals = 0i32;
    if bytes.get(i) == Some(&b'.') && bytes.get(i + 1).is_some_and(u8::is_ascii_digit) {
        digits.push('.');
        i += 1;
        while let Some(c) = bytes.get(i).filter(|c| c.is_ascii_digit()) {
            digits.push(*c as char);
            decimals += 1;
            i += 1;
        }
    }
    let mut exponent = 0i32;
    let rest = &text[i..];
    let exp_text = if let Some(r) = rest.strip_prefix('e') {
        Some((r, ""))
    } else {
        let power = rest
            .strip_prefix("\\cdot 10^")
            .or_else(|| rest.strip_prefix("\\cdot10^"));
        // `10^{-5}`, or `10^8` with a single digit.
        power.map(|r| r.strip_prefix('{').map_or((r, "\u{0}"), |r| (r, "}")))
    };
    let mut rest = rest;
    if let Some((r, close)) = exp_text {
        let single = close == "\u{0}";
        let end = r
            .char_indices()
            .find(|&(k, c)| {
                !(c.is_ascii_digit() || (k == 0 && c == '-')) || (single && k == 1)
            })
            .map_or(r.len(), |(k, _)| k);
        let close = if single { "" } else { close };
        if let Ok(e) = r[..end].parse::<i32>()
            && r[end..].starts_with(close)
        {
            exponent = e;
            rest = &r[end + close.len()..];
        }
    }
    let mantissa: f64 = digits.parse().ok()?;
    let scale = 10f64.powi(exponent);
    Some((
        Printed {
            value: mantissa * scale,
            unit: scale * 10f64.powi(-decimals),
        },
        rest,
    ))
}

/// Every number in a table cell, in order ("12 (4.96%)" holds 12 and 4.96).
pub(crate) fn numbers(cell: &str) -> Vec<Printed> {
    let mut out = Vec::new();
    let mut rest = cell;
    while !rest.is_empty() {
        let at_start = rest.len() == cell.len()
            || !cell.as_bytes()[cell.len() - rest.len() - 1].is_ascii_alphanumeric();
        match printed(rest).filter(|_| at_start) {
            Some((p, after)) => {
                out.push(p);
                rest = after;
            }
            None => {
                let next = rest.chars().next().map_or(1, char::len_utf8);
                rest = &rest[next..];
            }
        }
    }
    out
}

/// The lines between `ANCHOR: name` and `ANCHOR_END: name` of `text`, other anchor
/// lines left out (what mdBook includes).
pub(crate) fn anchored_lines(text: &str, name: &str) -> Option<Vec<String>> {
    let marker = |line: &str, m: &str| {
        line.split_once(m)
            .is_some_and(|(_, r)| r.trim().trim_end_matches("-->").trim() == name)
    };
    let mut lines = text.lines();
    lines.by_ref().find(|l| marker(l, "ANCHOR:"))?;
    let mut out = Vec::new();
    for line in lines {
        if marker(line, "ANCHOR_END:") {
            return Some(out);
        }
        if !line.contains("ANCHOR:") && !line.contains("ANCHOR_END:") {
            out.push(line.to_string());
        }
    }
    None
}

/// The cells of a Markdown table row.
pub(crate) fn cells(line: &str) -> Vec<String> {
    let inner = line.trim().trim_start_matches('|').trim_end_matches('|');
    inner.split('|').map(|c| c.trim().to_string()).collect()
}

/// Does a source's number support a stated one? They agree, each rounded as
/// printed, and the source is printed at least as finely as the statement: `1e4`
/// in code does not support a stated 5008.
///
/// Printed to the same digits, they must be equal: 2797 does not support 2798. A
/// finer source may itself be rounded from the value the page rounds, so it gets
/// half its own unit more (a snapshot's 2.165 of 2.1649 supports a stated 2.16).
pub(crate) fn supports(source: Printed, stated: Printed) -> bool {
    let finer = if source.unit < stated.unit {
        0.5 * source.unit
    } else {
        0.0
    };
    let slack = 0.5 * stated.unit + finer;
    (source.value - stated.value).abs() <= slack * (1.0 + 1e-9)
}
