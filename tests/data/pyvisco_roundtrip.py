"""pyvisco's side of tests/pyvisco_roundtrip.rs (issue 29 item 2), run with a Python that has pyvisco.

argv: RAW_CSV OURS_MASTER_CSV OURS_SHIFT_CSV OURS_PRONY_CSV REF_T OUT_DIR

1. Raw-data path: pyvisco's raw CSV with our shift factors -> master.get_curve (crashed before the
   shift CSV carried pyvisco's set temperatures). Writes raw_master.csv (f, E_stor, E_loss in MPa).
2. Master-curve path: our master curve and shift factors -> smooth, discretize, Prony fit; writes
   pyvisco's Prony-term CSV (prony_terms.csv, as its GUI writes it) and its own E', E'' of that
   series (gmaxw.csv).
3. Our Prony-term CSV read with pandas as pyvisco's files are and evaluated by pyvisco's
   calc_GMaxw: ours_gmaxw.csv.
"""

import os
import sys

from pyvisco import load, master, out, prony

raw_csv, m_csv, s_csv, p_csv, ref_t, out_dir = sys.argv[1:7]
ref_t = float(ref_t)

# 1. raw-data path
df_raw, arr_ref_t, units = load.user_raw(load.file(raw_csv), "freq", "E")
df_aT = load.user_shift(load.file(s_csv))
df_m = master.get_curve(df_raw, df_aT, ref_t)
df_m[["f", "E_stor", "E_loss"]].to_csv(os.path.join(out_dir, "raw_master.csv"), index=False)

# 2. master-curve path
df_master, units = load.user_master(load.file(m_csv), "freq", ref_t, "E")
df_master = master.smooth(df_master, 1)
df_dis = prony.discretize(df_master)
fit, df_gmaxw = prony.fit(df_dis, df_master, opt=False)
with open(os.path.join(out_dir, "prony_terms.csv"), "w") as f:
    f.write(out.to_csv(fit["df_terms"], units, index_label="i"))
df_gmaxw[["f", "E_stor", "E_loss"]].to_csv(os.path.join(out_dir, "gmaxw.csv"), index=False)

# 3. our Prony terms, evaluated by pyvisco
import pandas as pd

ours = pd.read_csv(p_csv, header=[0, 1])
ours.columns = ours.columns.get_level_values(0)
e0 = float(ours["E_0"].iloc[0])
g = prony.calc_GMaxw(e0, ours, 1e-10, 1e10, 20, "E")
g[["f", "E_stor", "E_loss"]].to_csv(os.path.join(out_dir, "ours_gmaxw.csv"), index=False)
print("ok")
