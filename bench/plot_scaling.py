#!/usr/bin/python3
"""Scaling figure and table of `bench_step_scaling` (SPEC §6).

Usage: plot_scaling.py SCALING_JSON OUT_PNG
SCALING_JSON: build/bench/bench_step_scaling --benchmark_repetitions=3
  --benchmark_report_aggregates_only=true --benchmark_out=FILE
  --benchmark_out_format=json
Prints the Markdown table of bench/RESULTS.md and the model size at which
each reduced model is 10x faster (linear interpolation in the dofs along the
blade refinement).
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

data = json.load(open(sys.argv[1]))
rows = {}
for b in data["benchmarks"]:
    if b.get("aggregate_name") != "median":
        continue
    parts = b["run_name"].split("/")
    kind = parts[0] if parts[0] == "full_step" else parts[1]
    elements, blades = int(parts[-2]), int(parts[-1])
    rows[(kind, elements, blades)] = b
sizes = sorted({(e, n) for _, e, n in rows}, key=lambda s: (s[1], s[0]))
kinds = [("full_step", "full"), ("cb44", "CB-44"), ("ccm44", "CCM-44")]

print("| blade elements | blades | full dofs | full µs/step | reduced dofs | CB-44 µs/step | CCM-44 µs/step "
      "| full / CB-44 | full / CCM-44 |")
print("|---|---|---|---|---|---|---|---|---|")
for e, n in sizes:
    full, cb, ccm = (rows[(k, e, n)] for k, _ in kinds)
    print(f"| {e} | {n} | {full['dofs']:.0f} | {full['real_time']:.1f} | {cb['reduced_dofs']:.0f} | "
          f"{cb['real_time']:.1f} | {ccm['real_time']:.1f} | {full['real_time'] / cb['real_time']:.1f} | "
          f"{full['real_time'] / ccm['real_time']:.1f} |")

refined = [(e, 22) for e, n in sizes if n == 22]
for k, label in kinds[1:]:
    ratios = [(rows[("full_step", e, n)]["dofs"], rows[("full_step", e, n)]["real_time"] / rows[(k, e, n)]["real_time"])
              for e, n in refined]
    for (d0, r0), (d1, r1) in zip(ratios, ratios[1:]):
        if r0 < 10 <= r1:
            print(f"{label}: 10x at about {d0 + (10 - r0) / (r1 - r0) * (d1 - d0):.0f} full dofs")

fig, ax = plt.subplots(figsize=(7, 4.5))
for k, label in kinds:
    for n, marker in ((22, "o-"), (44, "s"), (88, "^")):
        pts = sorted((rows[("full_step", e, nn)]["dofs"], rows[(k, e, nn)]["real_time"])
                     for e, nn in sizes if nn == n)
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker,
                label=f"{label}, {n} blades" + (" (9-72 el./blade)" if n == 22 else ""),
                color={"full_step": "k", "cb44": "tab:blue", "ccm44": "tab:orange"}[k])
ax.set_xlabel("dofs of the full model (bladed disk + casing)")
ax.set_ylabel("µs per contact-free step (median of 3)")
ax.set_yscale("log")
ax.grid(alpha=0.3, which="both")
ax.legend(fontsize=7)
ax.set_title("Cost per step against model size (bench_step_scaling)")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)
print(f"wrote {sys.argv[2]}")
