"""Each stage function against the CLI on the shipped data.

Tolerance: none. The Python module and the CLI run the same library calls on the same inputs, and
every value crosses as JSON written and read back bit for bit (serde_json's float_roundtrip;
Python's json module reads the shortest round-trip repr exactly), so any difference is a bug of
the adaptor (another call, another default, a lost option), not rounding. The one conversion the
Python side does itself is Pa -> MPa for the DataFrames, checked against the same division.
"""

import math
import warnings

import pandas as pd
import pytest

import viscoroll as vr
from conftest import DATA, EMS_RAW, REPO

PV_MASTER = DATA / "pyvisco-ems-ca" / "freq_user_master.csv"
PV_SHIFTS = DATA / "pyvisco-ems-ca" / "freq_user_master__shift_factors.csv"
PV_RAW = DATA / "pyvisco-ems-ca" / "freq_user_raw.csv"


def pyvisco_frame(path):
    """A pyvisco CSV (names, units, data) as pyvisco's loader gives it: the names, no unit row."""
    return pd.read_csv(path, skiprows=[1], skipinitialspace=True, encoding="utf-8-sig")


def quiet(f, *a, **k):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", vr.ViscorollWarning)
        return f(*a, **k)


# ------------------------------------------------------------------------------------ ingest


def test_ingest_file_is_the_cli_measurement(cli, ems_fit_cli):
    m_path, _ = ems_fit_cli
    import json

    expected = json.loads(m_path.read_text())
    got = quiet(vr.ingest, EMS_RAW).json
    assert got == expected


def test_ingest_dataframe_reads_the_points_of_pyvisco_raw_csv(cli, scratch):
    out = scratch / "raw.json"
    cli("ingest", PV_RAW, "-o", out)
    import json

    expected = json.loads(out.read_text())
    df = pyvisco_frame(PV_RAW).rename(columns={"f": "f_set"})  # pyvisco's raw-data names
    m = quiet(vr.ingest, df)
    got = m.json
    assert got["kind"] == expected["kind"] == "tensile"
    strip = lambda isos: [  # noqa: E731  (the points; file names and lines differ)
        (i["temp_nominal_c"], i["temp_mean_c"], [(p["freq_hz"], p["storage_pa"], p["loss_pa"], p["temp_c"]) for p in i["points"]])
        for i in isos
    ]
    assert strip(got["isotherms"]) == strip(expected["isotherms"])
    # the DataFrame back: pyvisco's names, MPa
    d = m.data
    assert list(d.columns[:4]) == ["f_set", "E_stor", "E_loss", "T"]
    assert d["E_stor"].tolist() == [p["storage_pa"] / 1e6 for i in expected["isotherms"] for p in i["points"]]
    assert len(d) == 210 and d["Set"].nunique() == 21


def test_ingest_numpy_arrays():
    df = pyvisco_frame(PV_RAW)
    arrays = {"f_set": df["f"].to_numpy(), "E_stor": df["E_stor"].to_numpy(),
              "E_loss": df["E_loss"].to_numpy(), "T": df["T"].to_numpy(), "Set": df["Set"].to_numpy()}
    a = quiet(vr.ingest, arrays)
    b = quiet(vr.ingest, df.rename(columns={"f": "f_set"}))
    assert a.json["isotherms"] == b.json["isotherms"]


def test_ingest_error_is_typed_with_the_cli_message(cli, scratch):
    missing = scratch / "no-such-export.txt"
    expected = cli("ingest", missing, code=1)["error"]
    with pytest.raises(vr.IngestError) as e:
        vr.ingest(str(missing))
    assert isinstance(e.value, vr.ViscorollError)
    assert str(e.value) == expected


def test_unknown_option_is_refused():
    with pytest.raises(vr.IngestError, match="modulus_unit `furlong`"):
        vr.ingest(EMS_RAW, modulus_unit="furlong")


# ------------------------------------------------------------------------------------ master


@pytest.mark.parametrize("flags,kw", [
    (["--tref", "25"], {"tref": 25.0}),
    (["--law", "wlf", "--criterion", "storage"], {"law": "wlf", "criterion": "storage"}),
])
def test_master_is_the_cli_master_curve(cli, ems_fit_cli, flags, kw):
    m_path, _ = ems_fit_cli
    expected = cli("master", m_path, *flags)
    expected.pop("schema_version", None)  # the CLI's JSON output carries its schema's version
    m = quiet(vr.ingest, EMS_RAW)
    with pytest.warns(vr.ViscorollWarning, match="master curve: "):
        mc = vr.master(m, **kw)
    assert mc.json == expected
    s = mc.shifts
    assert s["log_aT"].tolist() == [i["log10_a_t"] for i in expected["isotherms"]]
    assert mc.data["f"].tolist() == [p["reduced_freq_hz"] for p in expected["points"]]


def test_master_of_pyvisco_master_curve(cli):
    expected = cli("master", "--master-curve", PV_MASTER, "--shift-factors", PV_SHIFTS)
    mc = quiet(vr.master, pyvisco_frame(PV_MASTER), pyvisco_frame(PV_SHIFTS))
    for k in ("points", "shift_law", "wlf", "arrhenius", "t_ref_c"):
        assert mc.json[k] == expected[k], k


# ------------------------------------------------------------------------------------ fit

FIT_KEYS = ("shift_law", "master_curve", "relaxation", "prony_info", "creep", "tts", "quality",
            "settings", "bands")


def test_fit_is_the_cli_fit(ems_fit_cli, ems_fit_py):
    import json

    _, f_path = ems_fit_cli
    expected = json.loads(f_path.read_text())
    _, fit = ems_fit_py
    for k in FIT_KEYS:
        assert fit.json.get(k) == expected.get(k), k
    # the tables: pyvisco's Prony terms and the shifts
    p = fit.prony
    assert list(p.columns) == ["tau_i", "alpha_i", "E_0", "E_i"]
    # (pyvisco's order: slowest term first)
    assert sorted(p["tau_i"]) == sorted(t["tau_s"] for t in expected["relaxation"]["terms"])
    assert fit.shifts["log_aT"].tolist() == [a for _, a in expected["tts"]["shifts"]]
    assert fit.rms["storage"] == expected["prony_info"]["rms_log10_storage"]


def test_fit_options_reach_the_fit(cli, ems_fit_cli, scratch):
    import json

    m_path, _ = ems_fit_cli
    out = scratch / "ems-18.json"
    cli("fit", m_path, "-o", out, "--max-terms", "18", "--no-bands")
    expected = json.loads(out.read_text())
    fit = quiet(vr.fit, quiet(vr.ingest, EMS_RAW), name="ems-18", max_terms=18, bands=False)
    assert len(fit.json["relaxation"]["terms"]) == 18
    for k in FIT_KEYS:
        assert fit.json.get(k) == expected.get(k), k


def test_fit_of_pyvisco_master_curve(cli, scratch):
    import json

    out = scratch / "pv.json"
    cli("fit", "--master-curve", PV_MASTER, "--shift-factors", PV_SHIFTS, "-o", out)
    expected = json.loads(out.read_text())
    fit = quiet(vr.fit, pyvisco_frame(PV_MASTER), pyvisco_frame(PV_SHIFTS), name="pv")
    for k in FIT_KEYS:
        assert fit.json.get(k) == expected.get(k), k


def test_fit_save_is_read_by_the_cli(cli, ems_fit_py, scratch):
    _, fit = ems_fit_py
    path = scratch / "saved.json"
    fit.save(path)
    r = cli("roll", path, "--temp-c", 20, "--radius-mm", 66.5, "--load-n-per-m", 1e4, "--speed-m-s", 4, "--no-bands")
    row = vr.roll(fit, 20, radius_mm=66.5, load_n_per_m=1e4, speed_m_s=4, bands=False)
    assert row["friction"][0] == r["friction"]
    assert vr.Fit.load(path).json["relaxation"] == fit.json["relaxation"]
    with pytest.raises(vr.FitError, match="exists"):
        fit.save(path)


# ------------------------------------------------------------------------------------ convert


@pytest.mark.parametrize("flags", [[], ["--method", "park-schapery", "--park-schapery-variant", "least-squares"]])
def test_convert_is_the_cli_conversion(cli, ems_fit_cli, ems_fit_py, flags):
    _, f_path = ems_fit_cli
    expected = cli("convert", f_path, *flags)
    method = "park-schapery" if flags else "exact"
    c = vr.convert(ems_fit_py[1], method, "least-squares")
    assert c.json == expected["creep_spectrum"]
    assert c.checks == expected["checks"]
    assert c.data["J_i"].tolist() == [t["compliance_per_pa"] * 1e6 for t in expected["creep_spectrum"]["terms"]]


def test_convert_pyvisco_prony_terms(cli, ems_fit_cli, scratch):
    _, f_path = ems_fit_cli
    out = scratch / "ems-pv.csv"
    cli("export", f_path, "--to", "pyvisco", "-o", out)
    terms = scratch / "ems-pv__prony_terms.csv"
    expected = cli("convert", terms)
    df = pd.read_csv(terms, skiprows=[1], index_col=0, skipinitialspace=True)
    c = vr.convert(df)
    assert c.json == expected["creep_spectrum"]


# ------------------------------------------------------------------------------------ roll

ROLL = dict(radius_mm=66.5, load_n_per_m=10000.0, speed_m_s=4.0)
ROLL_FLAGS = ["--radius-mm", 66.5, "--load-n-per-m", 10000, "--speed-m-s", 4]
ROLL_COLUMNS = ["friction", "friction_p05", "friction_p50", "friction_p95", "contact_length_mm",
                "offset_mm", "resistance_n_per_m", "max_pressure_mpa", "error_estimate"]


def test_roll_is_the_cli_roll(cli, ems_fit_cli, ems_fit_py):
    _, f_path = ems_fit_cli
    temps = [-20.0, 20.0, 60.0]  # 60 °C lies above the measured temperatures: extrapolated
    rows = quiet(vr.roll, ems_fit_py[1], temps, **ROLL)
    for i, t in enumerate(temps):
        e = cli("roll", f_path, "--temp-c", t, *ROLL_FLAGS)
        for k in ROLL_COLUMNS:
            assert rows[k][i] == e[k], (t, k)
        assert rows["log_aT"][i] == e["log10_a_t"]
        assert bool(rows["extrapolated"][i]) == e["extrapolated"]
        assert rows["warnings"][i] == "; ".join(e["warnings"])
        assert rows.attrs["pressure"][i]["pressure_mpa"].tolist() == e["pressure_mpa"]


@pytest.mark.parametrize("model", [None, "layer", "winkler"])
def test_roll_on_a_cover_is_the_cli_roll(cli, ems_fit_cli, ems_fit_py, model):
    _, f_path = ems_fit_cli
    temps = [0.0, 40.0]
    extra = {} if model is None else {"model": model}
    rows = quiet(vr.roll, ems_fit_py[1], temps, cover_mm=5.0, **extra, **ROLL)
    for i, t in enumerate(temps):
        flags = [] if model is None else ["--model", model]
        e = cli("roll", f_path, "--temp-c", t, "--cover-mm", 5, *flags, *ROLL_FLAGS)
        for k in ROLL_COLUMNS:
            a, b = rows[k][i], e[k]
            # no band on the Winkler model: NaN here, null in the CLI's JSON
            assert a == b or (b is None and math.isnan(a)), (model, t, k)
        for k in ["model", "model_reason", "cover_over_contact"]:
            assert rows[k][i] == e[k], (model, t, k)
        assert rows["bands_note"][i] == e["bands_note"]
        assert rows["warnings"][i] == "; ".join(e["warnings"])
        assert rows.attrs["pressure"][i]["pressure_mpa"].tolist() == e["pressure_mpa"]
    if model == "layer":
        # the cover is solved, not the half-space
        half = quiet(vr.roll, ems_fit_py[1], temps, bands=False, **ROLL)
        assert (rows["model"] == "layer").all()
        assert all(a != b for a, b in zip(rows["friction"], half["friction"]))


def test_roll_refuses_a_bad_cover(ems_fit_py):
    with pytest.raises(vr.RollError, match="cover_mm must be finite and > 0"):
        vr.roll(ems_fit_py[1], 20.0, cover_mm=-1.0, **ROLL)
    with pytest.raises(vr.RollError, match="model `plate` is not known"):
        vr.roll(ems_fit_py[1], 20.0, cover_mm=5.0, model="plate", **ROLL)


def test_roll_warns_when_extrapolated(ems_fit_py):
    with pytest.warns(vr.ViscorollWarning, match="outside the measured temperatures"):
        vr.roll(ems_fit_py[1], 150.0, bands=False, **ROLL)


def test_roll_on_a_creep_spectrum(cli, ems_fit_py):
    creep = REPO / "data" / "spectra" / "example_creep.json"
    import json

    e = cli("roll", creep, *ROLL_FLAGS)
    c = vr.Creep(json.loads(creep.read_text()))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        row = vr.roll(c, **ROLL)
    # every warning of the solve is a ViscorollWarning, the same as the CLI's
    assert [str(w.message) for w in caught] == e["warnings"] and e["warnings"]
    assert all(w.category is vr.ViscorollWarning for w in caught)
    assert row["friction"][0] == e["friction"]
    assert math.isnan(row["friction_p05"][0]) and row["bands_note"][0] == e["bands_note"]


def test_roll_errors_are_typed(ems_fit_py):
    with pytest.raises(vr.RollError, match="radius_mm must be finite and > 0"):
        vr.roll(ems_fit_py[1], 20.0, radius_mm=-1.0, load_n_per_m=1e4, speed_m_s=4.0)
    with pytest.raises(vr.RollError, match="needs a temperature"):
        vr.roll(ems_fit_py[1], None, **ROLL)


# ------------------------------------------------------------------------------------ run, maps


def read_cli_csv(path):
    # pandas' defaults: the CLI's tables have one header row and no comment lines
    return pd.read_csv(path, encoding="utf-8")


def test_run_is_the_cli_run(runs):
    out_cli, r = runs
    f = r.friction
    for compound in ["ems-ca", "dmasuite-tensile", "trios-aresg2-lims"]:
        e = read_cli_csv(out_cli / "reports" / compound / "friction.csv")
        g = f[f["compound"] == compound].reset_index(drop=True)
        assert len(g) == len(e) > 0
        assert g["scene"].tolist() == e["scene"].tolist()
        assert g["T"].tolist() == e["temp_c"].tolist()
        for k in ["friction", "friction_p05", "friction_p50", "friction_p95"]:
            # the CSV writes the shortest round-trip repr: read back exactly
            assert g[k].fillna(-1).tolist() == e[k].fillna(-1).tolist(), (compound, k)
    pd.testing.assert_frame_equal(r.ranking, read_cli_csv(out_cli / "reports" / "ranking.csv"))


@pytest.mark.parametrize("scene", ["conveyor-idler", "tyre-like"])
def test_maps_are_the_run_maps(runs, scene):
    out_cli, _ = runs
    fit = vr.Fit.load(out_cli / "fits" / "ems-ca.json")
    m = quiet(vr.maps, fit, scene)
    e = read_cli_csv(out_cli / "reports" / "ems-ca" / "friction_map.csv")
    e = e[e["scene"] == scene].reset_index(drop=True)
    listed = m[m["kind"] == "listed"].reset_index(drop=True)
    assert len(listed) == len(e) > 0
    for a, b in [("T", "temp_c"), ("speed_m_s", "speed_m_s"), ("load_n_per_m", "load_n_per_m"),
                 ("friction", "friction")]:
        assert listed[a].tolist() == e[b].tolist(), a
    scn = next(s for s in vr.shipped_scenes() if s["name"] == scene)
    sp = listed[listed["sweep"] == "speed"]
    assert (sp["load_n_per_m"] == scn["load_n_per_m"]).all() and len(sp) == len(scn["map_speeds_m_s"]) * len(scn["map_temps_c"])
    ld = listed[listed["sweep"] == "load"]
    assert (ld["speed_m_s"] == scn["speed_m_s"]).all()
    e2 = read_cli_csv(out_cli / "reports" / "ems-ca" / "friction_map_2d.csv")
    e2 = e2[e2["scene"] == scene].reset_index(drop=True)
    grid = m[m["kind"] == "grid"].reset_index(drop=True)
    assert grid["friction"].tolist() == e2["friction"].tolist()


def test_maps_of_an_unknown_scene():
    with pytest.raises(vr.MapsError, match="no shipped scene"):
        vr.maps(None, "moon-buggy")


def test_run_of_an_empty_folder_raises(scratch):
    empty = scratch / "empty"
    empty.mkdir()
    with pytest.raises(vr.RunError):
        vr.run(empty, scratch / "empty-out")


def test_the_notebook_example_runs(tmp_path, monkeypatch):
    """examples/python_notebook.py, the README's main example from Python, runs to its end."""
    import runpy
    import tempfile

    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))  # its output folder goes here
    ns = runpy.run_path(str(REPO / "examples" / "python_notebook.py"), run_name="__main__")
    assert set(ns["friction"]["compound"]) == {"ems-ca", "dmasuite-tensile", "trios-aresg2-lims"}
    assert (ns["OUT"] / "reports" / "ranking.csv").exists()
    assert len(ns["speeds"]) == len(ns["scene"]["map_speeds_m_s"]) * len(ns["scene"]["map_temps_c"])
