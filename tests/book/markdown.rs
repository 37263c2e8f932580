//! Markdown helpers shared by the book checks (`includes`, `numbers`).

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
