"""Fixtures of the Python package's tests: the repository, the CLI binary to compare with, a
scratch folder, and the main job run once by the CLI and once from Python on the shipped data.

The CLI is ``target/debug/viscoroll`` (built by ``cargo build`` or ``cargo test``), or the binary
named by ``VISCOROLL_CLI``. It is the same library as the Python module (both are built from this
repository's src/), so every comparison expects the same numbers: equality of the library's JSON,
which ``serde_json`` writes and reads back bit for bit (``float_roundtrip``).
"""

import json
import os
import pathlib
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
DATA = REPO / "data"
EMS_RAW = DATA / "pyvisco-ems-ca" / "freq_Eplexor_raw.xls"


@pytest.fixture(scope="session")
def cli_path():
    p = pathlib.Path(os.environ.get("VISCOROLL_CLI", REPO / "target" / "debug" / "viscoroll"))
    if not p.exists():
        pytest.fail(f"{p} not found: run `cargo build` first (or set VISCOROLL_CLI)")
    return p


@pytest.fixture(scope="session")
def cli(cli_path):
    """Run the CLI with ``--json``; return its JSON object (and its exit code must be ``code``)."""

    def call(*args, code=0):
        r = subprocess.run(
            [str(cli_path), *map(str, args), "--json"],
            capture_output=True,
            text=True,
            cwd=REPO,
        )
        assert r.returncode == code, r.stderr
        return json.loads(r.stdout)

    return call


@pytest.fixture(scope="session")
def scratch(tmp_path_factory):
    return tmp_path_factory.mktemp("viscoroll")


@pytest.fixture(scope="session")
def ems_fit_cli(cli, scratch):
    """EMS-CA ingested and fitted by the CLI: (measurement JSON path, fit file path)."""
    m = scratch / "ems.json"
    f = scratch / "ems-ca.json"
    cli("ingest", EMS_RAW, "-o", m)
    cli("fit", m, "-o", f)
    return m, f


@pytest.fixture(scope="session")
def ems_fit_py():
    """EMS-CA ingested and fitted from Python (warnings are checked elsewhere)."""
    import warnings

    import viscoroll as vr

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vr.ViscorollWarning)
        m = vr.ingest(EMS_RAW)
        return m, vr.fit(m, name="ems-ca")


@pytest.fixture(scope="session")
def runs(cli, scratch):
    """The main job on the shipped data: (CLI's output folder, Python's Run)."""
    import warnings

    import viscoroll as vr

    out_cli = scratch / "run-cli"
    cli("run", DATA, "--out", out_cli)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vr.ViscorollWarning)
        r = vr.run(DATA, scratch / "run-py")
    return out_cli, r
