//! CSV text for the report tables, written with the `csv` crate so that a field holding a comma,
//! a quote or a line break (a compound name, an error message) is quoted and never breaks a row.
//!
//! Every field passes through [`cell`]: a text that a spreadsheet would run as a formula
//! (starting with `=`, `+`, `-`, `@`, tab or CR; OWASP's CSV-injection guidance) gets a leading `'`,
//! while numbers (`-1.5e3`, `+2`, `NaN`, and lists of them: `-40 -30`) stay numbers; control characters other than a line break
//! are shown escaped (`\u{1b}`), so no escape sequence reaches a terminal or a viewer.
//!
//! Input: a header and rows of already formatted fields; output: the file's text — one header row
//! and the rows, no comment lines (what a table says about itself is its sidecar,
//! crate::report::csv_meta).

use std::borrow::Cow;

/// A field made safe for spreadsheets and terminals (see the module doc).
pub fn cell(field: &str) -> Cow<'_, str> {
    // A number, or a list of numbers (`-40 -30 -20`), calls nothing: it stays as it is.
    let numbers = !field.trim().is_empty()
        && !field.starts_with(char::is_whitespace)
        && field.split_whitespace().all(|w| w.parse::<f64>().is_ok());
    let formula = field.starts_with(['=', '+', '-', '@', '\t', '\r']) && !numbers;
    match (formula, escape_controls(field)) {
        (false, f) => f,
        (true, f) => format!("'{f}").into(),
    }
}

/// Control characters other than a line break shown escaped (`\u{1b}`).
fn escape_controls(text: &str) -> Cow<'_, str> {
    if !text.chars().any(|c| c.is_control() && c != '\n') {
        return text.into();
    }
    let mut out = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        if c.is_control() && c != '\n' {
            out.extend(c.escape_unicode());
        } else {
            out.push(c);
        }
    }
    out.into()
}

/// Build a CSV text: the header, then the rows.
pub fn csv_text<I, R>(header: &[&str], rows: I) -> String
where
    I: IntoIterator<Item = R>,
    R: IntoIterator<Item = String>,
{
    let mut w = csv::WriterBuilder::new().from_writer(Vec::new());
    // Writing to a Vec cannot fail (no I/O); a record of another length than the header is a bug
    // of the caller, caught by the tests of every table.
    let _ = w.write_record(
        header
            .iter()
            .map(|h| cell(h).into_owned())
            .collect::<Vec<_>>(),
    );
    for r in rows {
        let r: Vec<String> = r.into_iter().map(|f| cell(&f).into_owned()).collect();
        let _ = w.write_record(&r);
    }
    let bytes = w.into_inner().unwrap_or_default();
    String::from_utf8_lossy(&bytes).into_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn commas_quotes_and_line_breaks_stay_in_their_field() {
        let text = csv_text(
            &["name", "value"],
            [
                vec!["a, b".to_string(), "1".to_string()],
                vec!["say \"hi\"\nthere".to_string(), "2".to_string()],
            ],
        );
        assert!(text.starts_with("name,value\n"), "{text}");
        let mut rd = csv::Reader::from_reader(text.as_bytes());
        let rows: Vec<Vec<String>> = rd
            .records()
            .map(|r| r.unwrap().iter().map(str::to_string).collect())
            .collect();
        assert_eq!(rows[0], ["a, b", "1"]);
        assert_eq!(rows[1], ["say \"hi\"\nthere", "2"]);
    }

    #[test]
    fn formulas_are_neutralised_numbers_stay_numbers_controls_are_escaped() {
        for f in [
            "=1+2",
            "+SUM(A1)",
            "-2+3",
            "@cmd",
            "\tx",
            "\t1",
            "\rx",
            "-",
            "-1 =A1",
            "=HYPERLINK(\"x\")",
        ] {
            let c = cell(f);
            assert!(c.starts_with('\''), "{f:?} -> {c:?}");
        }
        for n in [
            "-1.5e3",
            "+2",
            "-0",
            "NaN",
            "inf",
            "-inf",
            "12",
            "0.5",
            "-40 -30 -20",
        ] {
            assert_eq!(cell(n), n);
        }
        assert_eq!(cell("a\u{1b}[31mb"), "a\\u{1b}[31mb");
        assert_eq!(cell("plain text"), "plain text");
    }
}
