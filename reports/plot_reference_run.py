#!/usr/bin/python3
"""Figures of one reference run (analogues of paper Figs. 9-11).

Usage: plot_reference_run.py RUN_DIR OUT_DIR
RUN_DIR holds history.csv, summary.json and casing_first_contact.csv of
`rsi simulate CASE --method full --out RUN_DIR`. Writes
OUT_DIR/reference_gap_blade1.png (blade-1 gap, 0-20 ms and 0-5 ms) and
OUT_DIR/casing_first_contact.png (casing deformation at the first contact).
"""
import csv
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

run_dir, out_dir = sys.argv[1], sys.argv[2]
with open(f"{run_dir}/history.csv") as f:
    rows = list(csv.DictReader(f))
with open(f"{run_dir}/summary.json") as f:
    summary = json.load(f)
t_ms = [1e3 * float(r["t"]) for r in rows]
gap_mm = [1e3 * float(r["gap_1"]) for r in rows]
lam = [float(r["lambda_1"]) for r in rows]

fig, axes = plt.subplots(2, 1, figsize=(8, 6.5))
for ax, t_max in zip(axes, (20.0, 5.0)):
    keep = [i for i, t in enumerate(t_ms) if t <= t_max]
    ax.plot([t_ms[i] for i in keep], [gap_mm[i] for i in keep], "k-", lw=1, label="gap of blade tip 1")
    for a, b in summary["contact_intervals_blade_1"]:
        if 1e3 * a <= t_max:
            ax.axvspan(1e3 * a, 1e3 * b, color="tab:red", alpha=0.25, lw=0)
    ax.axhline(0.0, color="tab:red", lw=0.8)
    ax.set_xlim(0, t_max)
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("gap [mm]")
    ax.grid(alpha=0.3)
axes[0].set_title("Full reference run: blade-1 tip / casing gap (shaded: contact), cf. paper Figs. 10-11")
axes[0].legend(loc="upper right", fontsize=8)
fig.tight_layout()
fig.savefig(f"{out_dir}/reference_gap_blade1.png", dpi=120)

with open(f"{run_dir}/casing_first_contact.csv") as f:
    casing = list(csv.DictReader(f))
theta = [float(r["theta"]) for r in casing]
u = [float(r["u"]) for r in casing]
radius = 0.501
scale = 0.1 / max(abs(x) for x in u)  # radial displacement drawn at 10 cm for the largest
# Hermite-free drawing: straight segments between nodes, closed.
fine_theta = theta + [theta[0] + 2 * math.pi]
fine_u = u + [u[0]]
fig, ax = plt.subplots(figsize=(6, 6))
ax.plot([radius * math.cos(a) for a in fine_theta], [radius * math.sin(a) for a in fine_theta], "0.6", lw=1,
        label="undeformed casing")
ax.plot([(radius + scale * d) * math.cos(a) for a, d in zip(fine_theta, fine_u)],
        [(radius + scale * d) * math.sin(a) for a, d in zip(fine_theta, fine_u)], "k-o", ms=2, lw=1.2,
        label=f"deformed, radial displacement x {scale:.0f}")
ax.plot([-radius], [0.0], "rs", label="clamped node")
step = summary["first_contact_step"]
ax.set_title(f"Casing at the first contact (step {step}, t = {1e3 * step * summary['dt']:.3f} ms)\n"
             f"max |u| = {1e3 * max(abs(x) for x in u):.3f} mm; cf. paper Fig. 9")
ax.set_aspect("equal")
ax.legend(loc="lower right", fontsize=8)
ax.axis("off")
fig.tight_layout()
fig.savefig(f"{out_dir}/casing_first_contact.png", dpi=120)
print(f"wrote {out_dir}/reference_gap_blade1.png, {out_dir}/casing_first_contact.png")
