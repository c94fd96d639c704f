//! One error or warning line, capped in length ([`cap_line`]): shared by the scenes' results and the
//! run's outcome, below both.
//!
//! Input: a line of text; output: the same line cut to [`MAX_LINE_BYTES`] with a note of what was cut.

/// Longest error or warning line kept in outcomes and reports, in bytes (a 30 MB line in an input
/// must not become a 30 MB line in index.html).
pub const MAX_LINE_BYTES: usize = 600;

/// `s` cut to [`MAX_LINE_BYTES`] (at a character boundary) with a note of what was cut.
pub fn cap_line(s: &str) -> String {
    if s.len() <= MAX_LINE_BYTES {
        return s.to_string();
    }
    let mut end = MAX_LINE_BYTES;
    while !s.is_char_boundary(end) {
        end -= 1;
    }
    format!("{}… ({} more bytes cut)", &s[..end], s.len() - end)
}
