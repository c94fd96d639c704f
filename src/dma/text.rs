//! Text layer of the readers: bytes → `String` (UTF-8 with or without BOM, UTF-16LE/BE with or
//! without BOM, else Latin-1/cp1252 via `encoding_rs`), delimiter and decimal-mark sniffing, splitting
//! lines into fields and reading numbers in either locale. Owns no format knowledge.

use encoding_rs::{Encoding, UTF_16BE, UTF_16LE, WINDOWS_1252};

/// Decoded text and the encoding it was read in.
#[derive(Debug, Clone)]
pub(crate) struct Decoded {
    /// The text, BOM removed.
    pub text: String,
    /// `UTF-8`, `UTF-8 BOM`, `UTF-16LE`, `UTF-16BE`, `windows-1252`.
    pub encoding: &'static str,
}

/// Decode a text export. Never fails: bytes that are valid in no Unicode encoding are read as
/// windows-1252 (a superset of the printable Latin-1 range), which maps every byte. Line ends come
/// out as `\n`: CRLF and lone CR (old Mac exports, whose lines would otherwise run together) alike.
pub(crate) fn decode(bytes: &[u8]) -> Decoded {
    let mut d = decode_text(bytes);
    if d.text.contains('\r') {
        d.text = d.text.replace("\r\n", "\n").replace('\r', "\n");
    }
    d
}

fn decode_text(bytes: &[u8]) -> Decoded {
    let utf16 = |enc: &'static Encoding, body: &[u8], name: &'static str| Decoded {
        text: enc.decode_without_bom_handling(body).0.into_owned(),
        encoding: name,
    };
    if let Some(body) = bytes.strip_prefix(&[0xEF, 0xBB, 0xBF]) {
        return Decoded {
            text: String::from_utf8_lossy(body).into_owned(),
            encoding: "UTF-8 BOM",
        };
    }
    if let Some(body) = bytes.strip_prefix(&[0xFF, 0xFE]) {
        return utf16(UTF_16LE, body, "UTF-16LE");
    }
    if let Some(body) = bytes.strip_prefix(&[0xFE, 0xFF]) {
        return utf16(UTF_16BE, body, "UTF-16BE");
    }
    // UTF-16 without BOM: ASCII text has a zero in every other byte.
    let n = bytes.len().min(4096) & !1;
    if n >= 4 {
        let zeros_odd = bytes[..n]
            .iter()
            .skip(1)
            .step_by(2)
            .filter(|&&b| b == 0)
            .count();
        let zeros_even = bytes[..n].iter().step_by(2).filter(|&&b| b == 0).count();
        if zeros_odd * 10 > n / 2 * 8 && zeros_even * 10 < zeros_odd {
            return utf16(UTF_16LE, bytes, "UTF-16LE");
        }
        if zeros_even * 10 > n / 2 * 8 && zeros_odd * 10 < zeros_even {
            return utf16(UTF_16BE, bytes, "UTF-16BE");
        }
    }
    match std::str::from_utf8(bytes) {
        Ok(s) => Decoded {
            text: s.to_string(),
            encoding: "UTF-8",
        },
        Err(_) => Decoded {
            text: WINDOWS_1252
                .decode_without_bom_handling(bytes)
                .0
                .into_owned(),
            encoding: "windows-1252",
        },
    }
}

/// Field separator of a delimited text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Delimiter {
    /// `\t`
    Tab,
    /// `;`
    Semicolon,
    /// `,`
    Comma,
    /// Runs of spaces or tabs.
    Whitespace,
}

impl Delimiter {
    /// Name for metadata.
    pub fn name(self) -> &'static str {
        match self {
            Delimiter::Tab => "tab",
            Delimiter::Semicolon => "semicolon",
            Delimiter::Comma => "comma",
            Delimiter::Whitespace => "whitespace",
        }
    }
}

/// Decimal mark of numbers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Decimal {
    /// `1.5`
    Point,
    /// `1,5`
    Comma,
}

/// Split one line into trimmed fields (surrounding double quotes removed).
pub fn split(line: &str, d: Delimiter) -> Vec<String> {
    let unquote = |s: &str| {
        let t = s.trim();
        if t.len() >= 2 && t.starts_with('"') && t.ends_with('"') {
            t[1..t.len() - 1].replace("\"\"", "\"")
        } else {
            t.to_string()
        }
    };
    match d {
        Delimiter::Whitespace => line.split_whitespace().map(unquote).collect(),
        Delimiter::Tab => line.split('\t').map(unquote).collect(),
        Delimiter::Semicolon => line.split(';').map(unquote).collect(),
        Delimiter::Comma => split_quoted(line, ',').iter().map(|s| unquote(s)).collect(),
    }
}

fn split_quoted(line: &str, sep: char) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut quoted = false;
    for c in line.chars() {
        if c == '"' {
            quoted = !quoted;
            cur.push(c);
        } else if c == sep && !quoted {
            out.push(std::mem::take(&mut cur));
        } else {
            cur.push(c);
        }
    }
    out.push(cur);
    out
}

/// Read a number written with the given decimal mark; `None` if the text is not a number.
/// `NaN`/`nan` reads as NaN (a measured NaN is kept and flagged, not dropped).
pub(crate) fn parse_number(s: &str, dec: Decimal) -> Option<f64> {
    let t = s.trim();
    if t.is_empty() {
        return None;
    }
    let first = t.as_bytes()[0];
    if !(first.is_ascii_digit() || matches!(first, b'-' | b'+' | b'.' | b',' | b'N' | b'n')) {
        return None;
    }
    if t.eq_ignore_ascii_case("nan") {
        return Some(f64::NAN);
    }
    if first == b'N' || first == b'n' {
        return None;
    }
    let v = match dec {
        Decimal::Point => t.parse::<f64>().ok()?,
        Decimal::Comma => {
            if t.contains('.') {
                return None;
            }
            t.replacen(',', ".", 1).parse::<f64>().ok()?
        }
    };
    // Rust also accepts "inf" and "infinity"; the digit check above already keeps those out.
    Some(v)
}

/// Text that marks a missing value in exports (`---` in EPLEXOR, empty cells elsewhere).
pub(crate) fn is_missing_marker(s: &str) -> bool {
    let t = s.trim();
    t.is_empty()
        || (t.len() >= 2 && t.chars().all(|c| c == '-'))
        || t.eq_ignore_ascii_case("n/a")
        || t.eq_ignore_ascii_case("na")
}

/// Sniff the delimiter and decimal mark from the lines of a table. The first delimiter (in the order
/// tab, semicolon, comma, whitespace) that splits at least half the non-empty lines into two or more
/// fields, with one field count dominating, wins. The decimal mark is a comma if numbers like `1,5`
/// occur in fields and no `1.5`, and the delimiter is not a comma.
pub(crate) fn sniff(lines: &[&str]) -> (Delimiter, Decimal) {
    let sample: Vec<&str> = lines
        .iter()
        .copied()
        .filter(|l| !l.trim().is_empty())
        .take(200)
        .collect();
    let mut chosen = Delimiter::Whitespace;
    for d in [
        Delimiter::Tab,
        Delimiter::Semicolon,
        Delimiter::Comma,
        Delimiter::Whitespace,
    ] {
        let counts: Vec<usize> = sample.iter().map(|l| split(l, d).len()).collect();
        let multi = counts.iter().filter(|&&c| c >= 2).count();
        if sample.is_empty() || multi * 2 < sample.len() {
            continue;
        }
        let mut freq = std::collections::HashMap::new();
        for &c in counts.iter().filter(|&&c| c >= 2) {
            *freq.entry(c).or_insert(0usize) += 1;
        }
        let modal = freq.values().copied().max().unwrap_or(0);
        if modal * 2 >= multi {
            chosen = d;
            break;
        }
    }
    let dec = if chosen == Delimiter::Comma {
        Decimal::Point
    } else {
        sniff_decimal(&sample, chosen)
    };
    (chosen, dec)
}

/// The decimal mark of lines split at a known delimiter: comma when more numeric cells carry a
/// comma alone than a point alone.
pub(crate) fn sniff_decimal(lines: &[&str], delim: Delimiter) -> Decimal {
    let (mut comma, mut point) = (0usize, 0usize);
    for l in lines.iter().filter(|l| !l.trim().is_empty()).take(200) {
        for f in split(l, delim) {
            let t = f.trim();
            let numeric = t
                .chars()
                .all(|c| c.is_ascii_digit() || matches!(c, '-' | '+' | 'e' | 'E' | '.' | ','));
            if numeric && t.chars().any(|c| c.is_ascii_digit()) {
                if t.contains(',') && !t.contains('.') {
                    comma += 1;
                } else if t.contains('.') && !t.contains(',') {
                    point += 1;
                }
            }
        }
    }
    if comma > point {
        Decimal::Comma
    } else {
        Decimal::Point
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decodes_every_encoding_to_the_same_text() {
        let s = "T [°C]\tE' [MPa]\n-5,5\t1,5E+03\n";
        let mut le = vec![0xFF, 0xFE];
        let mut be = vec![0xFE, 0xFF];
        for u in s.encode_utf16() {
            le.extend_from_slice(&u.to_le_bytes());
            be.extend_from_slice(&u.to_be_bytes());
        }
        let latin1: Vec<u8> = s.chars().map(|c| c as u32 as u8).collect();
        let mut bom = vec![0xEF, 0xBB, 0xBF];
        bom.extend_from_slice(s.as_bytes());
        for (bytes, enc) in [
            (le.clone(), "UTF-16LE"),
            (be, "UTF-16BE"),
            (latin1, "windows-1252"),
            (bom, "UTF-8 BOM"),
            (s.as_bytes().to_vec(), "UTF-8"),
            (le[2..].to_vec(), "UTF-16LE"),
        ] {
            let d = decode(&bytes);
            assert_eq!(d.text, s, "{enc}");
            assert_eq!(d.encoding, enc);
        }
    }

    #[test]
    fn sniffs_delimiters_and_decimal_marks() {
        let semi = ["f;E'", "Hz;MPa", "0,1;8097,17", "1;8781,7"];
        assert_eq!(sniff(&semi), (Delimiter::Semicolon, Decimal::Comma));
        let comma = ["f,E'", "Hz,MPa", "0.1,8097.17"];
        assert_eq!(sniff(&comma), (Delimiter::Comma, Decimal::Point));
        let ws = ["  f   E'", "  [Hz]  [MPa]", "  1.0e-1  2.9e3"];
        assert_eq!(sniff(&ws), (Delimiter::Whitespace, Decimal::Point));
        assert_eq!(parse_number("1,5E+03", Decimal::Comma), Some(1500.0));
        assert_eq!(parse_number("1.5", Decimal::Comma), None);
        assert_eq!(parse_number("inf", Decimal::Point), None);
        assert!(parse_number("NaN", Decimal::Point).unwrap().is_nan());
    }
}
