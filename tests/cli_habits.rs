//! Ecosystem habits (issue 17 item 5): shell completions and man pages produced by the binary name
//! every subcommand; every `--help` lists the exit codes.

use clap::CommandFactory;
use std::process::Command;

fn viscoroll(args: &[&str]) -> (Option<i32>, String, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_viscoroll"))
        .args(args)
        .output()
        .unwrap();
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// The subcommands, from the parser's own definition (not from the outputs under test).
fn subcommands() -> Vec<String> {
    let names: Vec<String> = viscoroll::cli::Cli::command()
        .get_subcommands()
        .map(|c| c.get_name().to_string())
        .collect();
    // The ones a user of this wave expects to exist (a renamed or lost subcommand fails here).
    for n in [
        "run",
        "fit",
        "export",
        "convert",
        "roll",
        "completions",
        "man",
    ] {
        assert!(names.iter().any(|m| m == n), "{n} missing from {names:?}");
    }
    names
}

#[test]
fn completion_scripts_name_every_subcommand() {
    let names = subcommands();
    for shell in ["bash", "zsh", "fish", "elvish", "powershell"] {
        let (code, out, err) = viscoroll(&["completions", shell]);
        assert_eq!(code, Some(0), "{shell}: {err}");
        for n in &names {
            assert!(out.contains(n.as_str()), "{shell} script lacks {n}");
        }
    }
    // A word every bash script must hold to be one: the `complete` builtin bound to our name.
    let (_, bash, _) = viscoroll(&["completions", "bash"]);
    assert!(bash.contains("complete -F") && bash.contains("viscoroll"));
    let (code, _, err) = viscoroll(&["completions", "tcsh"]);
    assert_eq!(code, Some(2), "{err}");
}

#[test]
fn man_pages_name_every_subcommand_and_the_exit_codes() {
    let names = subcommands();
    let (code, page, err) = viscoroll(&["man"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        page.starts_with(".ie") || page.contains(".TH viscoroll 1"),
        "{page}"
    );
    assert!(page.contains(".SH SUBCOMMANDS"));
    for n in &names {
        if n == "help" {
            continue;
        }
        // roff escapes '-' as '\-'.
        assert!(
            page.contains(&format!("viscoroll\\-{n}(1)")),
            "man page lacks {n}"
        );
        let (code, sub, err) = viscoroll(&["man", n]);
        assert_eq!(code, Some(0), "{n}: {err}");
        assert!(sub.contains(&format!(".TH viscoroll-{n} 1")), "{n}: {sub}");
    }
    assert!(page.contains("Exit codes: 0 success"));
    let (code, _, err) = viscoroll(&["man", "nope"]);
    assert_eq!(code, Some(1));
    assert!(err.contains("no such subcommand"), "{err}");
}

#[test]
fn every_help_lists_the_exit_codes() {
    let (code, top, _) = viscoroll(&["--help"]);
    assert_eq!(code, Some(0));
    assert!(top.contains("Exit codes: 0 success"), "{top}");
    for n in subcommands() {
        if n == "help" {
            continue;
        }
        let (code, out, err) = viscoroll(&[n.as_str(), "--help"]);
        assert_eq!(code, Some(0), "{n}: {err}");
        for part in [
            "0 success",
            "1 bad input",
            "2 usage error",
            "3 `run` finished",
        ] {
            assert!(out.contains(part), "{n} --help lacks {part:?}");
        }
    }
}

#[test]
fn cargo_metadata_is_filled_in() {
    let toml: toml::Table =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/Cargo.toml"))
            .unwrap()
            .parse()
            .unwrap();
    let p = toml["package"].as_table().unwrap();
    for key in ["description", "license", "readme", "keywords", "categories"] {
        assert!(p.contains_key(key), "Cargo.toml [package] lacks {key}");
    }
    let kw = p["keywords"].as_array().unwrap();
    // crates.io takes at most 5 keywords of at most 20 characters.
    assert!(kw.len() <= 5 && kw.iter().all(|k| k.as_str().unwrap().len() <= 20));
    assert!(std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).exists());
}
