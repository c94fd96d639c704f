"""pyvisco's side of tests/pyvisco_time_roundtrip.rs (issue 29 item 2): its time-domain master-curve
path, run with a Python that has pyvisco.

argv: OURS_TIME_MASTER_CSV OURS_SHIFT_CSV REF_T OUT_DIR

Our `t, E_relax` export read by load.user_master(..., 'time', ...) with our shift factors
(load.user_shift), smoothed, discretized and fitted in time by prony.fit (its L-BFGS-B fit of
E_relax); writes its Prony-term CSV as its GUI does (prony_terms.csv) and its own E(t) of that
series at the master curve's times (time_fit.csv: t, E_relax in the file's unit).
"""

import os
import sys

import numpy as np
import pandas as pd
from pyvisco import load, master, out, prony

m_csv, s_csv, ref_t, out_dir = sys.argv[1:5]
df_master, units = load.user_master(load.file(m_csv), "time", float(ref_t), "E")
df_aT = load.user_shift(load.file(s_csv))
df_master = master.smooth(df_master, 1)
df_dis = prony.discretize(df_master)
fit, _ = prony.fit(df_dis, df_master, opt=False)
with open(os.path.join(out_dir, "prony_terms.csv"), "w") as f:
    f.write(out.to_csv(fit["df_terms"], units, index_label="i"))
terms = fit["df_terms"]
t = df_master["t"].values
e_relax = fit["E_0"] * prony.E_relax_norm(t, terms["alpha_i"].values, terms["tau_i"].values)
pd.DataFrame({"t": t, "E_relax": e_relax}).to_csv(
    os.path.join(out_dir, "time_fit.csv"), index=False
)
print("ok", len(df_aT), "shift factors,", len(terms), "terms")
