#!/usr/bin/python3
"""Recomputes one row of a component sweep's sweep.csv from the history.csv
and summary.json of `rsi simulate` of the same run, and compares.

Usage: sweep_row_from_history.py SWEEP_CSV SPEED RUN HISTORY SUMMARY
                                 STEPS_PER_REV OUTPUT_EVERY TRANSIENT_REVS
                                 RESPONSE GAP
SPEED as sweep.csv writes it, RESPONSE the history's column of the
response dof (u_11_2), GAP: the constant g0 of a rigid casing (its tips'
radial displacement u_r = g0 - g recomputed), "oval" (u_r not recomputed:
its g0 needs the nodes' angles) or "flexible" (the flexible casing's
max_abs_response, the largest |u| of RESPONSE). Exit 1 if any indicator
differs: rows, the displacement, the largest lambda_n, the contact
fraction, the energy ratio and the balance residual to the last bit (the
same doubles through the same operations), the three spectral peaks to
1e-9 (sweep/response_spectrum: Hann (periodic), mean removed, padded 8x,
A = 2|X|/sum(w), local maxima largest first; numpy's FFT against GSL's,
round-off of order n log n eps ~ 1e-12 relative; frequencies on the same
padded bin, k / (8 n dt)).
"""
import csv
import json
import math
import sys

import numpy as np

(sweep_csv, speed_text, run, history, summary_path, steps, every, transient_revs, response,
 gap) = sys.argv[1:11]
row = [r for r in csv.DictReader(open(sweep_csv))
       if r["speed_rad_s"] == speed_text and r["run"] == run][0]
hist = list(csv.DictReader(open(history)))
summary = json.load(open(summary_path))
speed = abs(float(speed_text))
period = 2.0 * math.pi / speed
interval = period / int(steps) * int(every)
transient = float(transient_revs) * period
kept = [h for h in hist if float(h["t"]) >= transient - 1e-6 * interval]
nc = sum(1 for k in hist[0] if k.startswith("gap_"))
gaps = [[float(h[f"gap_{c}"]) for c in range(1, nc + 1)] for h in kept]
lams = [[float(h[f"lambda_{c}"]) for c in range(1, nc + 1)] for h in kept]
mine = {
    "rows": len(kept),
    "max_contact_force": max(max(r) for r in lams),
    "contact_fraction": sum(1 for r in lams if max(r) > 0.0) / len(kept),
    "energy_ratio": float(kept[-1]["energy"]) / float(kept[0]["energy"]),
    "balance_residual": summary["energy_balance_error"] / summary["energy_scale"],
}
if gap == "flexible":
    mine["max_abs_response"] = max(abs(float(h[response])) for h in kept)
elif gap != "oval":
    # u_r = g0 - g (g = g0 + e_n . u, e_n inward); exact in floating point as rsi's.
    mine["max_tip_radial"] = max(abs(float(gap) - g) for r in gaps for g in r)
bad = 0
for key, value in mine.items():
    theirs = float(row[key])
    print(f"{key}: sweep.csv {theirs!r}, from history.csv {value!r}")
    if theirs != value:
        bad += 1
x = np.array([float(h[response]) for h in kept])
m = len(x)
w = 0.5 * (1.0 - np.cos(2.0 * np.pi * np.arange(m) / m))
a = 2.0 * np.abs(np.fft.rfft(w * (x - x.mean()), 8 * m)) / w.sum()
peaks = [k for k in range(1, len(a) - 1) if a[k] > a[k - 1] and a[k] >= a[k + 1]]
peaks.sort(key=lambda k: (-a[k], k))
for i, k in enumerate(peaks[:3], 1):
    f, amp = k / (8 * m * interval), a[k]
    tf, ta = float(row[f"f{i}_hz"]), float(row[f"a{i}"])
    err = abs(ta - amp) / amp
    print(f"peak {i}: sweep.csv {tf} Hz {ta}, numpy {f} Hz {amp} (relative {err:.1e})")
    if abs(tf - f) > 1e-9 * f or err > 1e-9:
        bad += 1
sys.exit(1 if bad else 0)
