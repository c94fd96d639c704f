//! Citations of the math notes point at something that exists.
//!
//! The code cites its math as `docs/MATH.md §N` (or `§N.M` for a subsection). This test reads every
//! source and documentation file of the repository (src/, tests/ without tests/data/, benches/,
//! examples/, tools/, README.md, and docs/ but for MATH.md and ARCHITECTURE.md) and fails if
//! - a citation names a section that docs/MATH.md does not have (a `## §N …` heading, or a
//!   `### N.M …` heading for §N.M);
//! - a file cites a MATH.md anywhere but in docs/ (a bare `MATH.md`, or the design notes outside the
//!   repository), or any path under the shared design folder (a file in docs/ may link it as
//!   `](MATH.md)`, relative to itself);
//! - docs/MATH.md's own sections are not numbered §1, §2, … without gaps or repeats (sections are
//!   added at the end, never renumbered, so that old citations stay right).
//!
//! Only the standard library is used, so the checks also run as a plain `rustc --test` of this file.

use std::fs;
use std::path::{Path, PathBuf};

const CITE: &str = "docs/MATH.md";

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Section numbers (`§N` headings) and subsection numbers (`N.M` headings) of a MATH.md text.
fn headings(math: &str) -> (Vec<u32>, Vec<(u32, u32)>) {
    let mut sections = Vec::new();
    let mut subsections = Vec::new();
    for line in math.lines() {
        if let Some(rest) = line.strip_prefix("## §") {
            let num: String = rest.chars().take_while(|c| c.is_ascii_digit()).collect();
            if let Ok(n) = num.parse() {
                sections.push(n);
            }
        } else if let Some(rest) = line.strip_prefix("### ") {
            let mut parts = rest.split_whitespace().next().unwrap_or("").split('.');
            if let (Some(a), Some(b)) = (parts.next(), parts.next()) {
                if let (Ok(a), Ok(b)) = (a.parse(), b.parse()) {
                    subsections.push((a, b));
                }
            }
        }
    }
    (sections, subsections)
}

/// A cited section: §N or §N.M.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Cited {
    Section(u32),
    Subsection(u32, u32),
}

/// Parse `§N` or `§N.M` at the start of `s`; returns the citation and the bytes consumed.
fn parse_section(s: &str) -> Option<(Cited, usize)> {
    let rest = s.strip_prefix('§')?;
    let major: String = rest.chars().take_while(|c| c.is_ascii_digit()).collect();
    let n: u32 = major.parse().ok()?;
    let mut used = '§'.len_utf8() + major.len();
    let after = &rest[major.len()..];
    // `§3.6` is a subsection; `§3.` at the end of a sentence is not.
    if let Some(tail) = after.strip_prefix('.') {
        let minor: String = tail.chars().take_while(|c| c.is_ascii_digit()).collect();
        if let Ok(m) = minor.parse() {
            used += 1 + minor.len();
            return Some((Cited::Subsection(n, m), used));
        }
    }
    Some((Cited::Section(n), used))
}

/// Every problem found in one file's text, as "LINE: message".
fn problems(text: &str, sections: &[u32], subsections: &[(u32, u32)]) -> Vec<String> {
    let mut out = Vec::new();
    for (no, line) in text.lines().enumerate() {
        let line_no = no + 1;
        // Citations outside the repository.
        for bad in ["/work/shared", "shared/design", "shared/seed"] {
            if line.contains(bad) {
                out.push(format!(
                    "{line_no}: cites `{bad}`, which is not in the repository"
                ));
            }
        }
        let mut start = 0;
        while let Some(pos) = line[start..].find("MATH.md") {
            let at = start + pos;
            start = at + "MATH.md".len();
            if !line[..at].ends_with("docs/") {
                out.push(format!(
                    "{line_no}: cites a MATH.md outside docs/ (write `{CITE} §N`)"
                ));
                continue;
            }
            // `docs/MATH.md §N[, §M …]`: every § number that follows, separated only by spaces,
            // commas, semicolons, dashes or "and"/"to", is a citation.
            // A bare `docs/MATH.md` (the whole file) is a valid citation too.
            let mut rest = &line[start..];
            loop {
                let trimmed = rest.trim_start_matches(|c: char| {
                    c == ' ' || c == ',' || c == ';' || c == '–' || c == '-'
                });
                let trimmed = trimmed
                    .strip_prefix("and ")
                    .or_else(|| trimmed.strip_prefix("to "))
                    .unwrap_or(trimmed);
                match parse_section(trimmed) {
                    Some((cited, used)) => {
                        let exists = match cited {
                            Cited::Section(n) => sections.contains(&n),
                            Cited::Subsection(n, m) => subsections.contains(&(n, m)),
                        };
                        if !exists {
                            out.push(format!(
                                "{line_no}: cites {cited:?} of {CITE}, which has no such section"
                            ));
                        }
                        rest = &trimmed[used..];
                    }
                    None => break,
                }
            }
        }
    }
    out
}

/// The files whose text is checked, relative to the repository root.
fn checked_files(root: &Path) -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let Ok(entries) = fs::read_dir(dir) else {
            return;
        };
        let mut entries: Vec<_> = entries.flatten().map(|e| e.path()).collect();
        entries.sort();
        for p in entries {
            if p.is_dir() {
                // fixtures are data, not citations
                if p.file_name().is_some_and(|n| n == "data")
                    && p.parent().is_some_and(|d| d.ends_with("tests"))
                {
                    continue;
                }
                walk(&p, out);
            } else if p
                .extension()
                .and_then(|e| e.to_str())
                .is_some_and(|e| matches!(e, "rs" | "py" | "md" | "toml" | "sh"))
            {
                out.push(p);
            }
        }
    }
    let mut out = Vec::new();
    for dir in ["src", "tests", "benches", "examples", "tools"] {
        walk(&root.join(dir), &mut out);
    }
    out.push(root.join("README.md"));
    // the user guide and the development log (issue 31) carry what the README used to
    for doc in ["USER_GUIDE.md", "DEVLOG.md"] {
        out.push(root.join("docs").join(doc));
    }
    out
}

#[test]
fn math_notes_are_numbered_without_gaps() {
    let math = fs::read_to_string(root().join(CITE)).expect("docs/MATH.md exists");
    let (sections, _) = headings(&math);
    let expected: Vec<u32> = (1..=sections.len() as u32).collect();
    assert_eq!(sections, expected, "the `## §N` headings of {CITE}");
    // §1–§6 are the sections the code cited before the notes were in the repository.
    assert!(sections.len() >= 6);
}

#[test]
fn every_math_citation_points_at_an_existing_section() {
    let root = root();
    let math = fs::read_to_string(root.join(CITE)).expect("docs/MATH.md exists");
    let (sections, subsections) = headings(&math);
    let this_file = root.join("tests").join("docs_links.rs");
    let mut all = Vec::new();
    let mut cited = 0usize;
    for path in checked_files(&root) {
        if path == this_file {
            continue; // it spells out the patterns it looks for
        }
        let Ok(mut text) = fs::read_to_string(&path) else {
            continue; // not UTF-8: not source
        };
        if path.parent() == Some(root.join("docs").as_path()) {
            // a link relative to the file itself
            text = text.replace("](MATH.md", "](docs/MATH.md");
        }
        cited += text.matches(CITE).count();
        let rel = path
            .strip_prefix(&root)
            .unwrap_or(&path)
            .display()
            .to_string();
        all.extend(
            problems(&text, &sections, &subsections)
                .into_iter()
                .map(|p| format!("{rel}:{p}")),
        );
    }
    assert!(all.is_empty(), "bad citations:\n{}", all.join("\n"));
    // The code cites the notes in ~60 places; finding none means the scan looked in the wrong place.
    assert!(cited >= 40, "only {cited} citations of {CITE} found");
}

#[test]
fn the_checker_catches_bad_citations() {
    // Independent of the repository's files: made-up lines against made-up headings.
    let math = "## §1 One\n### 1.1 Sub\n## §2 Two\n";
    let (s, sub) = headings(math);
    assert_eq!(s, vec![1, 2]);
    assert_eq!(sub, vec![(1, 1)]);
    let ok = [
        "// docs/MATH.md §1",
        "// (docs/MATH.md §2; see also …)",
        "// docs/MATH.md §1.1 and §2",
        "// docs/MATH.md §1, §2.",
        "// the whole of docs/MATH.md",
    ];
    for line in ok {
        assert!(problems(line, &s, &sub).is_empty(), "{line}");
    }
    let bad = [
        "// docs/MATH.md §3",
        "// docs/MATH.md §1, §7",
        "// docs/MATH.md §1.2",
        "// MATH.md §1",
        "// /work/shared/design/MATH.md §1",
        "// see shared/design/ARCHITECTURE.md",
    ];
    for line in bad {
        assert!(!problems(line, &s, &sub).is_empty(), "{line}");
    }
}
