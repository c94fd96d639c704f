# %% [markdown]
# # viscoroll from Python
#
# The README's main example in a notebook: the shipped DMA data of three compounds -> fits ->
# friction in the shipped scenes -> ranking; then one compound stage by stage. Cells are marked
# `# %%` (VS Code, PyCharm, Jupytext). Install the package first: `pip install ./python` from the
# repository (it builds the Rust library with maturin), plus pandas.
#
# Run as a script from anywhere: `python examples/python_notebook.py`.

# %%
import pathlib
import tempfile
import warnings

import pandas as pd

import viscoroll as vr

try:  # as a script: the repository is this file's parent's parent
    REPO = pathlib.Path(__file__).resolve().parents[1]
except NameError:  # in a notebook opened from examples/
    REPO = pathlib.Path.cwd().parent
DATA = REPO / "data"
OUT = pathlib.Path(tempfile.mkdtemp(prefix="vr-demo-"))
pd.set_option("display.width", 120)

# %% [markdown]
# ## The main job: `viscoroll run data --out OUT`
#
# Every compound is fitted and rolled in every scene; fits/ and reports/ (datasheets, CSV, plots)
# are written into `OUT` as by the CLI. Data checks and flags come as `ViscorollWarning`s; here
# they are collected and counted.

# %%
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always", vr.ViscorollWarning)
    run = vr.run(DATA, OUT)
print(run, f"({len(caught)} warnings; reports in {OUT / 'reports' / 'index.html'})")

# %% [markdown]
# The friction table: F/N per compound, scene and temperature, with its 90 % band.

# %%
friction = run.friction
table = friction.pivot_table(index=["scene", "T"], columns="compound", values="friction")
print(table.map(lambda v: f"{v:.3e}").to_string())

# %%
ranking = run.ranking[["scene", "rank", "compound", "mean_friction", "mean_friction_p05",
                       "mean_friction_p95", "verdict"]]
print(ranking.to_string(index=False))

# %% [markdown]
# ## One compound stage by stage (EMS-CA, an EPLEXOR export)

# %%
warnings.simplefilter("ignore", vr.ViscorollWarning)  # shown above; the stages raise the same
m = vr.ingest(DATA / "pyvisco-ems-ca" / "freq_Eplexor_raw.xls")
print(m)
print(m.data.head())  # f_set, E_stor, E_loss (MPa), T, ... as pyvisco names them

# %%
mc = vr.master(m)
print(mc)
print(mc.shifts[["T", "log_aT", "overlap_rms_log10"]].head())

# %%
fit = vr.fit(m, name="ems-ca")
print(fit)
print(fit.prony.head())  # tau_i, alpha_i, E_0, E_i: pyvisco's Prony-term table

# %%
creep = vr.convert(fit)
print(creep, "max |E*J* - 1| =", creep.checks["max_abs_product_error"])

# %%
# The conveyor idler of the README on a half-space (roll R = 66.5 mm, 10 kN/m, 4 m/s)
rows = vr.roll(fit, [-20, 0, 20, 40], radius_mm=66.5, load_n_per_m=10_000, speed_m_s=4)
print(rows[["T", "friction", "friction_p05", "friction_p95", "contact_length_mm"]].to_string(index=False))

# %%
# Friction maps of a shipped scene: the listed speeds at the scene's load (and loads at its speed)
scene = next(s for s in vr.shipped_scenes() if s["name"] == "conveyor-idler")
maps = vr.maps(fit, scene)
speeds = maps[maps["sweep"] == "speed"]
print(speeds.pivot_table(index="speed_m_s", columns="T", values="friction"))
