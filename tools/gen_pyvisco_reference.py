"""pyvisco's own fits of EMS-CA, for the E'/E'' trade test (tests/prony_ems_ca.rs, issue 29 item 6).

Run with pyvisco 2.1.3 installed (`python -m venv v && v/bin/pip install pyvisco==2.1.3`), from the
repository root: `v/bin/python tools/gen_pyvisco_reference.py`. It writes into data/pyvisco-ems-ca/:

- pyvisco_prony_terms_freq_user_master.csv: pyvisco's Prony fit of the shipped master curve
  freq_user_master.csv (T_ref -5 C) as its GUI does it: one relaxation time per decade over the rounded
  window (`prony.discretize(..., "round", 0)`, 26 terms), `prony.fit(..., opt=False)`;
- pyvisco_prony_terms_freq_user_master_opt.csv: the same with `opt=True` (L-BFGS-B on the alphas and
  the times, its least-squares objective on E/E_0, which weights E' far above E'');
- pyvisco_master_freq_user_raw.csv and its __shift_factors.csv: pyvisco's own master curve built from
  the raw data freq_user_raw.csv (`master.get_aT`, `master.get_curve`, T_ref -5 C);
- pyvisco_prony_terms_freq_user_raw_opt.csv: its `opt=True` fit of that curve (32 terms).

The files are pyvisco's own output (`out.to_csv`, its layout); nothing here evaluates them.
"""

from pyvisco import load, master, out, prony

D = "data/pyvisco-ems-ca/"


def fit(df_master, opt):
    df_dis = prony.discretize(df_master, "round", 0)
    p, _ = prony.fit(df_dis, df_master, opt=opt)
    return p["df_terms"]


df_m, units = load.user_master(load.file(D + "freq_user_master.csv"), "freq", -5, "E")
df_m = master.smooth(df_m, 1)
out.to_csv(fit(df_m, False), units, index_label="i",
           filepath=D + "pyvisco_prony_terms_freq_user_master.csv")
out.to_csv(fit(df_m, True), units, index_label="i",
           filepath=D + "pyvisco_prony_terms_freq_user_master_opt.csv")

df_raw, _, units_r = load.user_raw(load.file(D + "freq_user_raw.csv"), "freq", "E")
df_aT, _ = master.get_aT(df_raw, -5)
df_r = master.smooth(master.get_curve(df_raw, df_aT, -5), 1)
out.to_csv(df_r[["f", "E_stor", "E_loss"]], units_r, filepath=D + "pyvisco_master_freq_user_raw.csv")
out.to_csv(df_aT, units_r, filepath=D + "pyvisco_master_freq_user_raw__shift_factors.csv")
out.to_csv(fit(df_r, True), units_r, index_label="i",
           filepath=D + "pyvisco_prony_terms_freq_user_raw_opt.csv")
