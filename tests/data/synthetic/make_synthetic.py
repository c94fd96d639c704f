#!/usr/bin/env python3
"""Writes the synthetic exports in this folder (run from the repository root:
`python3 tests/data/synthetic/make_synthetic.py`). No real RheoCompass, Proteus or TRIOS plain-text
sample with a licence we can ship was available, so these files follow the layouts the vendors
document (see data/SOURCES.md), filled with the first three isotherms (-50, -42.5, -35 °C) of the real
EPLEXOR data data/pyvisco-ems-ca/freq_user_raw.csv, converted exactly:
  RheoCompass, TRIOS text: shear, G = E / 3 (nu = 0.5), omega = 2 pi f in rad/s, moduli in Pa;
  Proteus: tensile, E in MPa, f in Hz.
Values are written with 12 significant digits."""
import math, os

here = os.path.dirname(os.path.abspath(__file__))
rows = []
with open(os.path.join(here, "../../../data/pyvisco-ems-ca/freq_user_raw.csv"), encoding="utf-8-sig") as fh:
    lines = fh.read().splitlines()
for l in lines[2:]:
    f, e1, e2, t, s = l.split(",")
    if int(s) < 3:
        rows.append((float(f), float(e1), float(e2), float(t), int(s)))

g = lambda v: "%.12g" % v
comma = lambda s: s.replace(".", ",")
sets = sorted(set(r[4] for r in rows))

def rheocompass(labels, name):
    out = [f"{labels['project']}:\tviscoroll synthetic export (see data/SOURCES.md)",
           f"{labels['test']}:\tEMS-CA frequency sweeps",
           f"{labels['system']}:\tPP25-SN41234"]
    for s in sets:
        pts = [r for r in rows if r[4] == s]
        tn = round(sum(p[3] for p in pts) / len(pts) * 2) / 2
        out.append(f"{labels['result']}:\tFS {comma(g(tn))} °C")
        out.append(f"{labels['points']}:\t1\t{len(pts)}")
        out.append(f"{labels['data']}:\t" + "\t".join(labels["cols"]))
        out.append("\t\t[rad/s]\t[Pa]\t[Pa]\t[°C]\t[s]")
        for i, p in enumerate(pts):
            w = 2 * math.pi * p[0]
            vals = [g(w), g(p[1] * 1e6 / 3), g(p[2] * 1e6 / 3), g(p[3]), g(30.0 * (i + 1))]
            out.append("\t" + str(i + 1) + "\t" + "\t".join(comma(v) for v in vals))
        out.append("")
    text = "\r\n".join(out) + "\r\n"
    with open(os.path.join(here, name), "wb") as fh:
        fh.write(b"\xff\xfe" + text.encode("utf-16-le"))

rheocompass({"project": "Project", "test": "Test", "system": "Measuring System", "result": "Result", "points": "Interval and data points",
             "data": "Interval data", "cols": ["Point No.", "Angular Frequency", "Storage Modulus", "Loss Modulus", "Temperature", "Time"]},
            "rheocompass_en.csv")
rheocompass({"project": "Projekt", "test": "Test", "system": "Messsystem", "result": "Ergebnis", "points": "Intervall und Messpunkte",
             "data": "Intervalldaten", "cols": ["Messpunkt", "Kreisfrequenz", "Speichermodul", "Verlustmodul", "Temperatur", "Zeit"]},
            "rheocompass_de.csv")
rheocompass({"project": "Projet", "test": "Essai", "system": "Système de mesure", "result": "Résultat", "points": "Intervalle et points de mesure",
             "data": "Données d'intervalle", "cols": ["Point n°", "Fréquence angulaire", "Module de stockage", "Module de perte", "Température", "Temps"]},
            "rheocompass_fr.csv")

# Netzsch Proteus ASCII export of a DMA 242 run (tensile).
out = ["#EXPORTTYPE:DATA ALL", "#FILE:EMS-CA_synthetic.dm2", "#FORMAT:NETZSCH5", "#FTYPE:ANSI",
       "#IDENTITY:viscoroll synthetic", "#DATE/TIME:2019-04-29 08:45", "#INSTRUMENT:NETZSCH DMA 242E Artemis",
       "#MODE:Tension", "#SAMPLE:EMS-CA (values from freq_user_raw.csv)", "#DECIMAL:COMMA", "#SEPARATOR:SEMICOLON",
       "##Temp./°C;Time/min;Freq./Hz;E'/MPa;E''/MPa;tan d"]
for i, p in enumerate(rows):
    out.append(";".join(comma(v) for v in [g(p[3]), g(0.5 * i), g(p[0]), g(p[1]), g(p[2]), g(p[2] / p[1])]))
with open(os.path.join(here, "proteus_ascii.txt"), "wb") as fh:
    fh.write(("\r\n".join(out) + "\r\n").encode("cp1252"))

# TRIOS plain text export of an ARES-G2 run (shear), one [step] per isotherm.
out = ["Filename\tEMS-CA synthetic.tri", "Instrument type\tAresG2", "Instrument serial number\t4010-xxxx",
       "Trios version\t5.1.1.46572", "Run date\t4/29/2019"]
for s in sets:
    pts = [r for r in rows if r[4] == s]
    tn = round(sum(p[3] for p in pts) / len(pts) * 2) / 2
    out += ["", "[step]", f"Frequency sweep ({tn:.1f} °C)",
            "Angular frequency\tStorage modulus\tLoss modulus\tTemperature\tOscillation torque",
            "rad/s\tPa\tPa\t°C\tµN.m"]
    for p in pts:
        out.append("\t".join([g(2 * math.pi * p[0]), g(p[1] * 1e6 / 3), g(p[2] * 1e6 / 3), g(p[3]), "100"]))
with open(os.path.join(here, "trios_text.txt"), "w", encoding="utf-8", newline="\n") as fh:
    fh.write("\n".join(out) + "\n")
