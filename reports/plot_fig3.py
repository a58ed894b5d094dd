#!/usr/bin/python3
"""Analogue of paper Fig. 3: natural frequencies of the bladed disk against
their nodal diameter, one line per family (the m-th frequency of each
nodal diameter, a double pair counted once).

Usage: plot_fig3.py MODES_CSV OUT_PNG [N_FAMILIES]
MODES_CSV is the output of `rsi modes CASE --part bladed-disk --count N`.
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

modes_csv, out_png = sys.argv[1], sys.argv[2]
n_families = int(sys.argv[3]) if len(sys.argv) > 3 else 8

by_diameter = defaultdict(list)
with open(modes_csv) as f:
    for row in csv.DictReader(f):
        by_diameter[int(row["nodal_diameter"])].append(float(row["frequency_hz"]))
top = max(by_diameter)
families = defaultdict(dict)
for d, freqs in by_diameter.items():
    freqs.sort()
    # Diameters 1..N/2-1 are double: keep one frequency of each pair.
    single = freqs if d in (0, top) else freqs[::2]
    for m, f_hz in enumerate(single):
        families[m][d] = f_hz

fig, ax = plt.subplots(figsize=(7, 5))
for m in range(min(n_families, len(families))):
    ds = sorted(families[m])
    ax.plot(ds, [families[m][d] for d in ds], "o-", ms=3, label=f"family {m + 1}")
ax.set_yscale("log")
ax.set_xlabel("number of nodal diameters")
ax.set_ylabel("natural frequency [Hz]")
ax.set_xticks(range(0, top + 1))
ax.set_title("Bladed disk: frequency vs nodal diameter (cf. Batailly et al. 2007, Fig. 3)")
ax.grid(True, which="both", alpha=0.3)
ax.legend(fontsize=8, loc="lower right")
fig.tight_layout()
fig.savefig(out_png, dpi=120)
print(f"wrote {out_png}")
