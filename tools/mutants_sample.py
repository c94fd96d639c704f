#!/usr/bin/env python3
"""Sampled mutation testing (issue 19, item 6; docs/DEVLOG.md "Mutation testing"). Not part of CI.

cargo-mutants generates the mutants (`cargo mutants --list --json`); this script draws a seeded
random sample from the files given, then applies each mutant in place, builds the library and the
test binary, runs the given test filter, restores the file and appends one line per mutant to a TSV:
group, outcome (caught + the first failing tests | missed | unviable | timeout), seconds, name.

Why not `cargo mutants --re`: cargo-mutants 27.1 lists its "delete field … from struct" mutants
whatever `--re`/`--exclude-re` say, so a named sample cannot be selected with it.

usage (from the repository root, on a clean tree):
  tools/mutants_sample.py [--timeout S] [--lib-only] [--names FILE | --exclude FILE] GROUP N SEED OUT.tsv 'GLOB[,GLOB…]' [-- TEST FILTER ARGS…]
--timeout S: seconds allowed for the test run of one mutant (default 600; take ~3× the unmutated run).
--names FILE: run exactly the mutants named in FILE (one name a line, or the 4th column of a TSV this
script wrote, e.g. its `missed` lines, to rerun survivors after new tests), not a random sample.
--lib-only: build and run only the library's unit tests (`cargo test --lib`): one crate build per
mutant instead of three (library for tests, library, test binary), for modules whose own unit tests
are the ones that exercise them; the score is then that of the unit tests alone (a lower bound).
--exclude FILE: leave the mutants named in FILE (same forms) out of the frame before drawing, to
enlarge an earlier sample with a new seed without drawing a mutant twice.
e.g.
  nice -n 10 tools/mutants_sample.py contact 18 19 mutants.tsv 'src/contact/**,!src/contact/maps/**' \
      -- contact physical_units auto_vs_richardson golden_outputs results spectra_exact
A glob starting with ! excludes. Mutants of Display/Debug impls and of functions returning message
text (`-> String`) are left out of the sampling frame (formatting, not physics).
"""
import fnmatch
import json
import random
import re
import subprocess
import sys
import time

EXCLUDE = re.compile(r"impl .*fmt::(Display|Debug)|-> String with")


def in_group(path, globs):
    inc = [g for g in globs if not g.startswith("!")]
    exc = [g[1:] for g in globs if g.startswith("!")]
    return any(fnmatch.fnmatch(path, g) for g in inc) and not any(
        fnmatch.fnmatch(path, g) for g in exc
    )


def apply(m):
    """Replace the mutant's span (1-based line/column, end exclusive) by its replacement."""
    src = open(m["file"]).read()
    lines = src.split("\n")

    def off(pos):
        return sum(len(l) + 1 for l in lines[: pos["line"] - 1]) + len(
            lines[pos["line"] - 1][: pos["column"] - 1]
        )

    s, e = off(m["span"]["start"]), off(m["span"]["end"])
    open(m["file"], "w").write(src[:s] + m["replacement"] + src[e:])
    return src


def main():
    argv = sys.argv[1:]
    filt = argv[argv.index("--") + 1 :] if "--" in argv else []
    argv = argv[: argv.index("--")] if "--" in argv else argv
    timeout, names, exclude, lib_only = 600, None, set(), False
    while argv and argv[0].startswith("--"):
        if argv[0] == "--lib-only":
            lib_only, argv = True, argv[1:]
            continue
        opt, val, argv = argv[0], argv[1], argv[2:]
        if opt == "--timeout":
            timeout = int(val)
        elif opt == "--names":
            names = [l.rstrip("\n").split("\t")[-1] for l in open(val) if l.strip()]
        elif opt == "--exclude":
            exclude = {l.rstrip("\n").split("\t")[-1] for l in open(val) if l.strip()}
        else:
            sys.exit(f"unknown option {opt}")
    group, n, seed, out, globs = argv[:5]
    globs = globs.split(",")
    if subprocess.run(["git", "diff", "--quiet", "--", "src"]).returncode != 0:
        sys.exit("src/ has uncommitted changes: mutants are applied in place, start clean")
    listing = subprocess.run(
        ["cargo", "mutants", "--list", "--json"], capture_output=True, check=True
    ).stdout
    frame = [
        m
        for m in json.loads(listing)
        if in_group(m["file"], globs)
        and not EXCLUDE.search(m["name"])
        and m["name"] not in exclude
    ]
    if names is not None:
        by_name = {m["name"]: m for m in frame}
        missing = [x for x in names if x not in by_name]
        if missing:
            sys.exit(f"not in the frame (source moved?): {missing}")
        sample = [by_name[x] for x in names]
    else:
        sample = random.Random(int(seed)).sample(frame, min(int(n), len(frame)))
    print(f"{group}: {len(sample)} of {len(frame)} mutants", file=sys.stderr)
    test = ["nice", "-n", "10", "cargo", "test", "-q", "--lib"] + ([] if lib_only else ["--test", "tests"])
    with open(out, "a") as tsv:
        for m in sample:
            orig, t0 = apply(m), time.time()
            try:
                b = subprocess.run(test + ["--no-run"], capture_output=True)
                if b.returncode != 0:
                    res = "unviable"
                else:
                    try:
                        r = subprocess.run(test + ["--"] + filt, capture_output=True, timeout=timeout)
                        if r.returncode == 0:
                            res = "missed"
                        else:
                            fails = [
                                l.strip()
                                for l in r.stdout.decode(errors="replace").split("\n")
                                if l.startswith("    ") and "::" in l
                            ]
                            res = "caught " + ",".join(fails[:4])
                    except subprocess.TimeoutExpired:
                        res = "timeout"
            finally:
                open(m["file"], "w").write(orig)
            tsv.write(f"{group}\t{res}\t{time.time() - t0:.0f}s\t{m['name']}\n")
            tsv.flush()


if __name__ == "__main__":
    main()
