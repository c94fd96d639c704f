//! CSV text for the report tables, written with the `csv` crate so that a field holding a comma,
//! a quote or a line break (a compound name, an error message) is quoted and never breaks a row.
//!
//! Input: `#` comment lines, a header and rows of already formatted fields; output: the file's text.

/// Build a CSV text: each comment as a `# ` line (line breaks inside a comment become spaces, so a
/// comment never spills into the table), then the header and the rows.
pub fn csv_text<I, R>(comments: &[String], header: &[&str], rows: I) -> String
where
    I: IntoIterator<Item = R>,
    R: IntoIterator<Item = String>,
{
    let mut out = String::new();
    for c in comments {
        out.push_str("# ");
        out.push_str(&c.replace(['\r', '\n'], " "));
        out.push('\n');
    }
    let mut w = csv::WriterBuilder::new().from_writer(Vec::new());
    // Writing to a Vec cannot fail (no I/O); a record of another length than the header is a bug
    // of the caller, caught by the tests of every table.
    let _ = w.write_record(header);
    for r in rows {
        let _ = w.write_record(r.into_iter().collect::<Vec<String>>());
    }
    let bytes = w.into_inner().unwrap_or_default();
    out.push_str(&String::from_utf8_lossy(&bytes));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn commas_quotes_and_line_breaks_stay_in_their_field() {
        let text = csv_text(
            &["made by a\ntest".to_string()],
            &["name", "value"],
            [
                vec!["a, b".to_string(), "1".to_string()],
                vec!["say \"hi\"\nthere".to_string(), "2".to_string()],
            ],
        );
        assert!(text.starts_with("# made by a test\n"), "{text}");
        let body: String = text.lines().skip(1).map(|l| format!("{l}\n")).collect();
        let mut rd = csv::Reader::from_reader(body.as_bytes());
        let rows: Vec<Vec<String>> = rd
            .records()
            .map(|r| r.unwrap().iter().map(str::to_string).collect())
            .collect();
        assert_eq!(rows[0], ["a, b", "1"]);
        assert_eq!(rows[1], ["say \"hi\"\nthere", "2"]);
    }
}
