"""The stage functions and result objects of the ``viscoroll`` package (see its docstring).

Everything numeric is done by ``viscoroll._core`` (Rust); this module only converts: DataFrames and
numpy arrays into the library's inputs (a DataFrame of raw data is handed over as pyvisco's CSV
layout and read by the library's own reader, so it is checked like any export), and the library's
JSON results into DataFrames. Moduli are in MPa in the DataFrames (pyvisco's unit), in Pa in the
``.json`` dicts (the library's SI units).
"""

from __future__ import annotations

import io
import json
import os
import warnings
from typing import Iterable, Optional, Sequence, Union

import numpy as np
import pandas as pd

from . import _core

PathLike = Union[str, "os.PathLike[str]"]


class ViscorollWarning(UserWarning):
    """A warning of the viscoroll library (data checks, extrapolation, fit and solver notes)."""


def _warn(messages: Iterable[str], prefix: str = "") -> None:
    for m in messages:
        warnings.warn(prefix + m, ViscorollWarning, stacklevel=3)


def _opts(**kw) -> str:
    """Options for ``_core`` as JSON: the keyword arguments given (None = the CLI's default)."""
    return json.dumps({k: v for k, v in kw.items() if v is not None})


def _letter(kind: str) -> str:
    return "G" if kind == "shear" else "E"


def _is_paths(x) -> bool:
    if isinstance(x, (str, os.PathLike)):
        return True
    return isinstance(x, (list, tuple)) and len(x) > 0 and all(
        isinstance(p, (str, os.PathLike)) for p in x
    )


def _frame(data) -> pd.DataFrame:
    """A DataFrame from a DataFrame or a mapping of column name -> numpy array / sequence."""
    if isinstance(data, pd.DataFrame):
        return data
    if isinstance(data, dict):
        return pd.DataFrame({k: np.asarray(v, dtype=float) for k, v in data.items()})
    raise TypeError(f"expected a DataFrame or a dict of arrays, got {type(data).__name__}")


def _pyvisco_csv(df: pd.DataFrame, columns: Sequence[tuple], name: str) -> bytes:
    """``df`` in pyvisco's CSV layout: a row of names, a row of units, then the data.

    ``columns`` lists (output name, unit, accepted input names); moduli are taken as MPa."""
    out = {}
    names, units = [], []
    for out_name, unit, accepted in columns:
        src = next((c for c in accepted if c in df.columns), None)
        if src is None:
            if unit == "-":  # optional (the set number)
                continue
            raise KeyError(f"{name}: no column {' or '.join(accepted)}")
        out[out_name] = np.asarray(df[src], dtype=float)
        names.append(out_name)
        units.append(unit)
    body = pd.DataFrame(out).to_csv(index=False, header=False, float_format="%.17g")
    return (",".join(names) + "\n" + ",".join(units) + "\n" + body).encode()


def _modulus_columns(df: pd.DataFrame):
    """(letter, storage names, loss names) of a DataFrame with E_... or G_... columns."""
    shear = "G_stor" in df.columns and "E_stor" not in df.columns
    L = "G" if shear else "E"
    return L, [f"{L}_stor"], [f"{L}_loss"]


# ----------------------------------------------------------------------------------------------
# ingest


class Measurement:
    """The DMA data of one compound, as the library reads it (``viscoroll ingest``).

    ``data``: one row per point: ``f_set`` (Hz), ``E_stor``, ``E_loss`` (MPa; ``G_...`` for shear),
    ``T`` (°C: the point's own temperature where the file has one, else its isotherm's mean),
    ``T_mean`` (the isotherm's mean), ``T_set`` (its nominal temperature), ``Set`` (isotherm
    number, from 0), ``flags`` (the data checks' flags, ``;``-joined), ``line`` (line in the file).
    ``json``: the library's Measurement (SI units)."""

    def __init__(self, json_text: str):
        self._text = json_text
        self.json = json.loads(json_text)

    @property
    def kind(self) -> str:
        return self.json["kind"]

    @property
    def warnings(self) -> list:
        return list(self.json["warnings"])

    @property
    def summary(self) -> dict:
        return self.json["summary"]

    @property
    def data(self) -> pd.DataFrame:
        L = _letter(self.kind)
        rows = []
        for s, iso in enumerate(self.json["isotherms"]):
            for p in iso["points"]:
                t = p.get("temp_c")
                rows.append(
                    (
                        p["freq_hz"],
                        p["storage_pa"] / 1e6,
                        p["loss_pa"] / 1e6,
                        iso["temp_mean_c"] if t is None else t,
                        iso["temp_mean_c"],
                        iso["temp_nominal_c"],
                        s,
                        ";".join(p.get("flags", [])),
                        p.get("line"),
                    )
                )
        cols = ["f_set", f"{L}_stor", f"{L}_loss", "T", "T_mean", "T_set", "Set", "flags", "line"]
        return pd.DataFrame(rows, columns=cols)

    def __repr__(self) -> str:
        s = self.summary
        return (
            f"<viscoroll.Measurement {self.kind}: {s.get('isotherms')} isotherms, "
            f"{s.get('points')} points, {len(self.warnings)} warnings>"
        )


def ingest(
    data,
    *,
    format: Optional[str] = None,
    modulus_unit: Optional[str] = None,
    freq_unit: Optional[str] = None,
    temp_unit: Optional[str] = None,
    mode: Optional[str] = None,
    columns: Optional[str] = None,
    poisson: Optional[float] = None,
) -> Measurement:
    """Read DMA data: ``viscoroll ingest``.

    ``data``: a path or a list of paths of exports (EPLEXOR, TRIOS, RheoCompass, Proteus, RepTate,
    generic text), or a DataFrame (or dict of numpy arrays) of raw points in pyvisco's names:
    ``f_set`` (or ``f``, Hz), ``E_stor``, ``E_loss`` (MPa; ``G_...`` for shear), ``T`` (°C) and
    optionally ``Set`` (isotherm number). Keyword options are ``ingest``'s flags. The data checks'
    warnings are issued as :class:`ViscorollWarning`; errors raise :class:`IngestError`."""
    opts = _opts(
        format=format,
        modulus_unit=modulus_unit,
        freq_unit=freq_unit,
        temp_unit=temp_unit,
        mode=mode,
        columns=columns,
        poisson=poisson,
    )
    if _is_paths(data):
        paths = [data] if isinstance(data, (str, os.PathLike)) else list(data)
        text = _core.ingest_files([os.fspath(p) for p in paths], opts)
    else:
        df = _frame(data)
        L, stor, loss = _modulus_columns(df)
        csv = _pyvisco_csv(
            df,
            [
                ("f", "Hz", ["f_set", "f"]),
                (f"{L}_stor", "MPa", stor),
                (f"{L}_loss", "MPa", loss),
                ("T", "C", ["T"]),
                ("Set", "-", ["Set"]),
            ],
            "ingest",
        )
        text = _core.ingest_bytes([("dataframe.csv", csv)], opts)
    m = Measurement(text)
    _warn(m.warnings)
    return m


# ----------------------------------------------------------------------------------------------
# master


class MasterCurve:
    """A master curve by time-temperature superposition (``viscoroll master``).

    ``data``: ``f`` (reduced frequency at ``t_ref``, Hz), ``E_stor``, ``E_loss`` (MPa), ``T``
    (the point's isotherm, °C), ``Set``. ``shifts``: per isotherm ``T``, ``T_set``, ``log_aT``,
    ``log_aT_std``, ``log_bT``, the overlap figures and flags. ``wlf``, ``arrhenius``: the fitted
    laws (dicts) or None; ``shift_law``: the law used; ``json``: the library's MasterCurve."""

    def __init__(self, json_text: str):
        self.json = json.loads(json_text)

    t_ref = property(lambda self: self.json["t_ref_c"])
    kind = property(lambda self: self.json["kind"])
    wlf = property(lambda self: self.json.get("wlf"))
    arrhenius = property(lambda self: self.json.get("arrhenius"))
    shift_law = property(lambda self: self.json["shift_law"])
    warnings = property(lambda self: list(self.json["warnings"]))
    flags = property(lambda self: list(self.json["quality"].get("flags", [])))

    @property
    def data(self) -> pd.DataFrame:
        L = _letter(self.kind)
        p = self.json["points"]
        return pd.DataFrame(
            {
                "f": [q["reduced_freq_hz"] for q in p],
                f"{L}_stor": [q["storage_pa"] / 1e6 for q in p],
                f"{L}_loss": [q["loss_pa"] / 1e6 for q in p],
                "T": [q["temp_c"] for q in p],
                "Set": [q["isotherm"] for q in p],
            }
        )

    @property
    def shifts(self) -> pd.DataFrame:
        s = self.json["isotherms"]
        return pd.DataFrame(
            {
                "T": [i["temp_c"] for i in s],
                "T_set": [i["temp_nominal_c"] for i in s],
                "log_aT": [i["log10_a_t"] for i in s],
                "log_aT_std": [i["log10_a_t_std"] for i in s],
                "log_bT": [i["log10_b_t"] for i in s],
                "overlap_rms_log10": [i.get("overlap_rms_log10") for i in s],
                "loss_overlap_rms_log10": [i.get("loss_overlap_rms_log10") for i in s],
                "shift_determined": [i.get("shift_determined") for i in s],
                "flags": [";".join(i.get("flags", [])) for i in s],
            }
        )

    def __repr__(self) -> str:
        return (
            f"<viscoroll.MasterCurve {len(self.json['isotherms'])} isotherms, "
            f"{len(self.json['points'])} points, T_ref = {self.t_ref} °C>"
        )


def _shift_csv(shifts) -> bytes:
    df = _frame(shifts)
    return _pyvisco_csv(df, [("T", "C", ["T"]), ("log_aT", "-", ["log_aT"])], "shifts")


def _master_csv(data) -> bytes:
    df = _frame(data)
    L, stor, loss = _modulus_columns(df)
    return _pyvisco_csv(
        df,
        [("f", "Hz", ["f", "f_set"]), (f"{L}_stor", "MPa", stor), (f"{L}_loss", "MPa", loss)],
        "master curve",
    )


def _measurement(data, stage_opts: Optional[dict] = None) -> Measurement:
    if isinstance(data, Measurement):
        return data
    return ingest(data, **(stage_opts or {}))


def master(
    data,
    shifts=None,
    *,
    tref: Optional[float] = None,
    shift: Optional[str] = None,
    vertical: Optional[str] = None,
    criterion: Optional[str] = None,
    law: Optional[str] = None,
    fit_range: Optional[str] = None,
    nominal: bool = False,
) -> MasterCurve:
    """The master curve: ``viscoroll master``.

    ``data``: a :class:`Measurement` (or what :func:`ingest` takes); or, with ``shifts``, a master
    curve already shifted in pyvisco's layout (``f``, ``E_stor``, ``E_loss`` in MPa) and its shift
    factors (``T``, ``log_aT``; the row with log_aT = 0 is the reference, else give ``tref``), read
    as ``master --master-curve --shift-factors`` reads them. Keyword options are ``master``'s flags
    (``law="wlf"``, ``criterion="storage"``, ``fit_range="-30:60"``...)."""
    if shifts is not None:
        mj, mcj = _core.master_pyvisco(
            "master.csv", _master_csv(data), "shift_factors.csv", _shift_csv(shifts), tref
        )
        mc = MasterCurve(mcj)
    else:
        m = _measurement(data)
        opts = _opts(
            tref=tref,
            shift=shift,
            vertical=vertical,
            criterion=criterion,
            law=law,
            fit_range=fit_range,
            nominal=nominal or None,
        )
        mc = MasterCurve(_core.master(m._text, opts))
    _warn(mc.warnings, "master curve: ")
    _warn(mc.flags, "master curve: ")
    return mc


# ----------------------------------------------------------------------------------------------
# fit


def _terms_frame(relaxation: dict) -> pd.DataFrame:
    """A relaxation spectrum as pyvisco's Prony-term table (``tau_i``, ``alpha_i``, ``E_0``,
    ``E_i``; ``G_...`` for shear; MPa), written by the library (crate::prony::pyvisco_csv)."""
    text = _core.pyvisco_terms_write(json.dumps(relaxation))
    return pd.read_csv(io.StringIO(text), skiprows=[1], index_col=0, skipinitialspace=True)


class Fit:
    """A compound's fit (``viscoroll fit``; the library's CompoundFit, the file ``fits/NAME.json``):
    master curve, Prony series, exact creep spectrum, shift law, quality figures and the bootstrap
    ensemble of the uncertainty bands. Pass it on to :func:`convert`, :func:`roll`, :func:`maps`.

    ``prony``: pyvisco's Prony-term table (``tau_i`` s, ``alpha_i``, ``E_0``, ``E_i`` MPa);
    ``E_inf``, ``E_0`` (MPa); ``master``: ``f``, ``E_stor``, ``E_loss`` (MPa); ``shifts``: ``T``,
    ``log_aT``; ``creep``: ``tau_i`` (s), ``J_i`` (1/MPa) with ``J_0`` the glassy compliance;
    ``quality``: the quality figures against their bounds; ``rms``: RMS log10 error of E' and E''."""

    def __init__(self, json_text: str, bands_note: Optional[str] = None):
        self._text = json_text
        self.json = json.loads(json_text)
        self.bands_note = bands_note

    compound = property(lambda self: self.json["compound"])
    kind = property(lambda self: self.json["relaxation"]["kind"])
    t_ref = property(lambda self: self.json["shift_law"]["t_ref_c"])
    shift_law = property(lambda self: self.json["shift_law"])
    E_inf = property(lambda self: self.json["relaxation"]["modulus_inf_pa"] / 1e6)

    @property
    def E_0(self) -> float:
        r = self.json["relaxation"]
        return (r["modulus_inf_pa"] + sum(t["modulus_pa"] for t in r["terms"])) / 1e6

    @property
    def rms(self) -> dict:
        i = self.json["prony_info"]
        return {"storage": i["rms_log10_storage"], "loss": i["rms_log10_loss"]}

    @property
    def warnings(self) -> list:
        tts = self.json.get("tts") or {}
        w = [f"master curve: {f}" for f in tts.get("flags", []) + tts.get("warnings", [])]
        return w + list(self.json["measurement"].get("warnings", []))

    @property
    def prony(self) -> pd.DataFrame:
        return _terms_frame(self.json["relaxation"])

    @property
    def master(self) -> pd.DataFrame:
        L = _letter(self.kind)
        p = self.json["master_curve"]
        return pd.DataFrame(
            {
                "f": [q["reduced_freq_hz"] for q in p],
                f"{L}_stor": [q["storage_pa"] / 1e6 for q in p],
                f"{L}_loss": [q["loss_pa"] / 1e6 for q in p],
            }
        )

    @property
    def shifts(self) -> pd.DataFrame:
        s = (self.json.get("tts") or {}).get("shifts", [])
        return pd.DataFrame({"T": [t for t, _ in s], "log_aT": [a for _, a in s]})

    @property
    def creep(self) -> pd.DataFrame:
        c = self.json.get("creep")
        return Creep.from_spectrum(c).data if c else pd.DataFrame(columns=["tau_i", "J_i"])

    @property
    def quality(self) -> pd.DataFrame:
        return pd.DataFrame(self.json["quality"])

    def save(self, path: PathLike, force: bool = False) -> None:
        """Write the fit file (atomically, with its content hash), readable by ``viscoroll roll``,
        ``rank`` and ``export``."""
        _core.fit_write(self._text, os.fspath(path), force)

    @classmethod
    def load(cls, path: PathLike) -> "Fit":
        """Read a fit file written by ``viscoroll fit`` or ``run`` (checked as the CLI checks it)."""
        return cls(_core.fit_read(os.fspath(path)))

    def __repr__(self) -> str:
        r = self.rms
        return (
            f"<viscoroll.Fit {self.compound!r}: {len(self.json['relaxation']['terms'])} terms, "
            f"T_ref = {self.t_ref} °C, RMS log10 E' {r['storage']:.4f}, E'' {r['loss']:.4f}>"
        )


def fit(
    data,
    shifts=None,
    *,
    name: str = "compound",
    tref: Optional[float] = None,
    bands: bool = True,
    poisson: float = 0.5,
    shift: Optional[str] = None,
    vertical: Optional[str] = None,
    criterion: Optional[str] = None,
    law: Optional[str] = None,
    fit_range: Optional[str] = None,
    nominal: bool = False,
    max_terms: Optional[int] = None,
    target_rms: Optional[str] = None,
    reduce: bool = False,
) -> Fit:
    """Master curve + Prony fit + creep spectrum: ``viscoroll fit`` (a new fit, not written to a
    file: :meth:`Fit.save` writes it).

    ``data``: a :class:`Measurement` (or what :func:`ingest` takes); or, with ``shifts``, pyvisco's
    master curve and shift factors as in :func:`master`. ``bands=False`` is ``--no-bands``. The
    other keyword options are ``fit``'s flags."""
    opts = _opts(
        name=name,
        tref=tref,
        no_bands=(not bands) or None,
        shift=shift,
        vertical=vertical,
        criterion=criterion,
        law=law,
        fit_range=fit_range,
        nominal=nominal or None,
        max_terms=max_terms,
        target_rms=target_rms,
        reduce=reduce or None,
    )
    if shifts is not None:
        text, why = _core.fit_pyvisco(
            "master.csv", _master_csv(data), "shift_factors.csv", _shift_csv(shifts), poisson, opts
        )
    else:
        text, why = _core.fit(_measurement(data)._text, opts)
    f = Fit(text, why)
    _warn(f.warnings, f"{f.compound}: ")
    if why:
        _warn([why], f"{f.compound}: ")
    info = f.json["prony_info"]
    if info.get("term_target_met") is False:
        _warn(["the term target is not met; kept %d terms" % len(f.json["relaxation"]["terms"])])
    return f


# ----------------------------------------------------------------------------------------------
# convert


class Creep:
    """A creep (retardation) spectrum: ``data`` with ``tau_i`` (s) and ``J_i`` (1/MPa), ``J_0``
    the glassy compliance (1/MPa); ``checks``: the conversion's checks (``viscoroll convert
    --json``); ``json``: the library's CreepSpectrum (SI units). Pass it on to :func:`roll`."""

    def __init__(self, spectrum: dict, checks: Optional[dict] = None, info=None):
        self.json = spectrum
        self.checks = checks or {}
        self.info = info

    @classmethod
    def from_spectrum(cls, spectrum: dict) -> "Creep":
        return cls(spectrum)

    J_0 = property(lambda self: self.json["compliance_glassy_per_pa"] * 1e6)

    @property
    def data(self) -> pd.DataFrame:
        t = self.json["terms"]
        return pd.DataFrame(
            {"tau_i": [x["tau_s"] for x in t], "J_i": [x["compliance_per_pa"] * 1e6 for x in t]}
        )

    def __repr__(self) -> str:
        return f"<viscoroll.Creep {len(self.json['terms'])} retardation terms, J_0 = {self.J_0:.4e} 1/MPa>"


def _relaxation(source, poisson: float) -> dict:
    if isinstance(source, Fit):
        return source.json["relaxation"]
    if isinstance(source, dict) and "modulus_inf_pa" in source:
        return source
    if isinstance(source, pd.DataFrame):
        # pyvisco's Prony-term table, read by the library's reader of pyvisco's CSV
        df = source
        shear = any(c.startswith("G_") for c in df.columns)
        L = "G" if shear else "E"
        cols = [("tau_i", "s", ["tau_i"]), ("alpha_i", "-", ["alpha_i"])]
        cols += [(f"{L}_0", "MPa", [f"{L}_0"]), (f"{L}_i", "MPa", [f"{L}_i"])]
        present = [c for c in cols if c[2][0] in df.columns]
        text = _pyvisco_csv(df, present, "Prony terms")
        return json.loads(_core.pyvisco_terms_read("prony_terms.csv", text, poisson))
    raise TypeError("convert takes a Fit, a relaxation spectrum dict or pyvisco's Prony-term DataFrame")


def convert(
    source,
    method: str = "exact",
    variant: str = "collocation-1",
    *,
    poisson: float = 0.5,
) -> Creep:
    """Relaxation -> creep spectrum: ``viscoroll convert`` (``method="exact"`` or
    ``"park-schapery"`` with ``variant``). ``source``: a :class:`Fit`, pyvisco's Prony-term
    DataFrame (``tau_i``, ``alpha_i``, ``E_0`` and/or ``E_i`` in MPa) or a relaxation spectrum dict
    (the library's JSON). Errors raise :class:`ConvertError`."""
    out = json.loads(_core.convert(json.dumps(_relaxation(source, poisson)), method, variant))
    c = Creep(out["creep_spectrum"], out["checks"], out["info"])
    if out["checks"]["negative_terms"]:
        _warn([f"{out['checks']['negative_terms']} negative strengths (non-physical)"])
    return c


# ----------------------------------------------------------------------------------------------
# roll, maps


def roll(
    source,
    temp_c=None,
    *,
    radius_mm: float,
    load_n_per_m: float,
    speed_m_s: float,
    poisson: Optional[float] = None,
    scheme: str = "auto",
    n: int = 200,
    tol: float = 1e-6,
    bands: bool = True,
    cover_mm: Optional[float] = None,
    model: Optional[str] = None,
) -> pd.DataFrame:
    """One rolling scene: ``viscoroll roll``, at each temperature of ``temp_c`` (a number or an
    array; a :class:`Fit` needs it, a :class:`Creep` takes none). On a half-space by default; with
    ``cover_mm`` (a rubber cover of that thickness bonded to a rigid carcass) or ``model``
    (``auto``, ``half-space``, ``layer``, ``winkler``) as ``viscoroll roll --cover-mm H --model M``,
    with the columns ``model``, ``model_reason`` and ``cover_over_contact`` besides.

    One row per temperature: ``T``, ``log_aT``, ``extrapolated``, ``friction`` (F/N),
    ``friction_p05``/``p50``/``p95`` (the 90 % band, NaN without one, ``bands_note`` why),
    ``resistance_n_per_m``, ``contact_length_mm``, ``offset_mm``, ``max_pressure_mpa``,
    ``error_estimate``, ``warnings``. The pressure profiles are in ``.attrs["pressure"]`` (one
    DataFrame ``x_mm``, ``pressure_mpa`` per row). Errors raise :class:`RollError`."""
    if isinstance(source, Fit):
        text = source._text
    elif isinstance(source, Creep):
        text = json.dumps(source.json)
    else:
        raise TypeError("roll takes a Fit or a Creep")
    temps = None if temp_c is None else [float(t) for t in np.atleast_1d(temp_c)]
    opts = _opts(
        radius_mm=radius_mm,
        load_n_per_m=load_n_per_m,
        speed_m_s=speed_m_s,
        poisson=poisson,
        scheme=scheme,
        n=n,
        tol=tol,
        no_bands=(not bands) or None,
        cover_mm=cover_mm,
        model=model,
    )
    rows = json.loads(_core.roll(text, temps, opts))
    for r in rows:
        _warn(r["warnings"], "" if r["temp_c"] is None else f"{r['temp_c']} °C: ")
    df = pd.DataFrame(
        {
            "T": [r["temp_c"] for r in rows],
            "log_aT": [r["log10_a_t"] for r in rows],
            "extrapolated": [r["extrapolated"] for r in rows],
            "friction": [r["friction"] for r in rows],
            "friction_p05": [r["friction_p05"] for r in rows],
            "friction_p50": [r["friction_p50"] for r in rows],
            "friction_p95": [r["friction_p95"] for r in rows],
            "resistance_n_per_m": [r["resistance_n_per_m"] for r in rows],
            "contact_length_mm": [r["contact_length_mm"] for r in rows],
            "offset_mm": [r["offset_mm"] for r in rows],
            "max_pressure_mpa": [r["max_pressure_mpa"] for r in rows],
            "error_estimate": [r["error_estimate"] for r in rows],
            "bands_note": [r["bands_note"] for r in rows],
            "bands_notes": ["; ".join(r["bands_notes"]) for r in rows],
            "warnings": ["; ".join(r["warnings"]) for r in rows],
        }
    ).astype({"friction_p05": float, "friction_p50": float, "friction_p95": float})
    if rows and "model" in rows[0]:
        for k in ["model", "model_reason", "cover_over_contact"]:
            df[k] = [r[k] for r in rows]
    df.attrs["pressure"] = [
        pd.DataFrame({"x_mm": r["x_mm"], "pressure_mpa": r["pressure_mpa"]}) for r in rows
    ]
    return df


def shipped_scenes() -> list:
    """The shipped scenes (``data/scenes.toml``), each a dict with scenes.toml's keys."""
    return json.loads(_core.shipped_scenes())


def _scene(scene) -> dict:
    if isinstance(scene, str):
        found = [s for s in shipped_scenes() if s["name"] == scene]
        if not found:
            names = ", ".join(s["name"] for s in shipped_scenes())
            raise _core.MapsError(f"no shipped scene {scene!r} (shipped: {names})")
        return found[0]
    return dict(scene)


def maps(fit_: Fit, scene) -> pd.DataFrame:
    """Friction maps of a fit in one scene, as the main job makes them (``friction_map.csv`` and
    ``friction_map_2d.csv`` of ``viscoroll run``): ``scene`` is a shipped scene's name or a dict
    with scenes.toml's keys (``map_temps_c``, ``map_speeds_m_s``, ``map_loads_n_per_m`` among them).

    One row per map point: ``scene``, ``T``, ``speed_m_s``, ``load_n_per_m``, ``friction``,
    ``contact_length_mm`` and ``kind``: ``listed`` (the scene's speeds and loads: friction_map.csv),
    ``grid`` (the speed x load grid: friction_map_2d.csv) or ``curve`` (the dense curves the plots
    draw); ``sweep`` of a listed point: ``speed`` (at the scene's load) or ``load`` (at its speed).
    ``.attrs``: ``error_estimate``, ``tol``, ``solves``. Errors raise :class:`MapsError`."""
    spec = _scene(scene)
    m = json.loads(_core.maps(fit_._text, json.dumps(spec)))
    _warn(m.get("warnings", []), f"{fit_.compound}, {spec['name']}: ")
    frames = []
    for kind, key in [("listed", "points"), ("grid", "grid"), ("curve", "curves")]:
        pts = m.get(key, [])
        frames.append(
            pd.DataFrame(
                {
                    "scene": spec["name"],
                    "T": [p["temp_c"] for p in pts],
                    "speed_m_s": [p["speed_m_s"] for p in pts],
                    "load_n_per_m": [p["load_n_per_m"] for p in pts],
                    "friction": [p["friction"] for p in pts],
                    "contact_length_mm": [p["contact_length_mm"] for p in pts],
                    "kind": kind,
                }
            )
        )
    # the listed points come per map temperature as the speeds (at the scene's load), then the
    # loads (at its speed): crate::pipeline::scenes::map_jobs
    ns, nl = len(spec.get("map_speeds_m_s", [])), len(spec.get("map_loads_n_per_m", []))
    listed = frames[0]
    if len(listed) == len(spec.get("map_temps_c", [])) * (ns + nl):
        listed["sweep"] = (["speed"] * ns + ["load"] * nl) * len(spec["map_temps_c"])
    df = pd.concat(frames, ignore_index=True).astype({"friction": float, "contact_length_mm": float})
    df.attrs.update({k: m.get(k) for k in ("error_estimate", "tol", "solves")})
    return df


# ----------------------------------------------------------------------------------------------
# run


def _read_table(path: str) -> pd.DataFrame:
    """A CSV the CLI writes: one header row, no comment lines (its notes are in the sidecar
    ``NAME.meta.json``)."""
    return pd.read_csv(path, encoding="utf-8")


class Run:
    """The main job's results (``viscoroll run``): ``friction`` (one row per compound, scene and
    temperature: ``compound``, ``scene``, ``T``, ``log_aT``, ``friction``, ``friction_p05``/``p50``/
    ``p95``, ``resistance_n_per_m``, ``contact_length_mm``, ``extrapolated``, ``error``,
    ``undetermined``, ``model``, ``error_estimate``, ``note``), ``ranking`` (reports/ranking.csv),
    ``summary`` (the library's RunSummary), ``log`` (the run's log lines), ``out`` (the folder)."""

    def __init__(self, summary_json: str, log: list, out: str):
        self.summary = json.loads(summary_json)
        self.log = log
        self.out = out

    @property
    def friction(self) -> pd.DataFrame:
        rows = []
        for c in self.summary["compounds"]:
            for scene, points in c.get("friction", []):
                for p in points:
                    b = p.get("band") or {}
                    rows.append(
                        {
                            "compound": c["compound"],
                            "scene": scene,
                            "T": p["temp_c"],
                            "log_aT": p.get("log10_a_t"),
                            "friction": p["friction"],
                            "friction_p05": b.get("p05"),
                            "friction_p50": b.get("p50"),
                            "friction_p95": b.get("p95"),
                            "resistance_n_per_m": p["resistance_n_per_m"],
                            "contact_length_mm": p["contact_length_mm"],
                            "extrapolated": p["extrapolated"],
                            "error": p.get("error"),
                            "undetermined": p.get("undetermined"),
                            "model": p.get("model"),
                            "error_estimate": p.get("error_estimate"),
                            "note": "; ".join(p.get("warnings", [])),
                        }
                    )
        float_cols = ["friction", "friction_p05", "friction_p50", "friction_p95",
                      "resistance_n_per_m", "contact_length_mm", "error_estimate"]
        return pd.DataFrame(rows).astype({c: float for c in float_cols})

    @property
    def ranking(self) -> pd.DataFrame:
        return _read_table(self.summary["ranking_csv"])

    def __repr__(self) -> str:
        n = len(self.summary["compounds"])
        failed = sum(1 for c in self.summary["compounds"] if c.get("error"))
        return f"<viscoroll.Run {n} compounds ({failed} failed) into {self.out!r}>"


def run(
    dir: PathLike = "data",
    out: PathLike = ".",
    *,
    scenes: Optional[PathLike] = None,
    force: bool = False,
    tref: Optional[float] = None,
    allow_extrapolation: bool = False,
    tol: Optional[float] = None,
    bands: bool = True,
    shard: Optional[str] = None,
    xlsx: bool = True,
    **fit_options,
) -> Run:
    """The main job: ``viscoroll run DIR --out OUT`` (fits/ and reports/ written into ``out``).

    A compound that failed or is not trusted does not raise: each such compound is issued as a
    :class:`ViscorollWarning` (the run goes on, as the CLI's), with its reasons; the tables are in
    the returned :class:`Run`. A folder that cannot be run raises :class:`RunError`. The fit
    options (``criterion``, ``law``, ``max_terms``...) are ``run``'s flags; ``xlsx=False`` is
    ``--no-xlsx`` (no ``reports/viscoroll.xlsx``)."""
    opts = _opts(
        scenes=None if scenes is None else os.fspath(scenes),
        force=force or None,
        tref=tref,
        allow_extrapolation=allow_extrapolation or None,
        tol=tol,
        no_bands=(not bands) or None,
        shard=shard,
        no_xlsx=(not xlsx) or None,
        **fit_options,
    )
    text, log = _core.run(os.fspath(dir), os.fspath(out), opts)
    r = Run(text, log, os.fspath(out))
    for c in r.summary["compounds"]:
        if c.get("error"):
            _warn([f"{c['compound']}: failed: {c['error']}"])
        elif c.get("untrusted"):
            _warn([f"{c['compound']}: not trusted: " + "; ".join(c["untrusted"])])
        _warn(c.get("warnings", []), f"{c['compound']}: ")
    return r
