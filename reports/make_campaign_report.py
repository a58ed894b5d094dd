#!/usr/bin/python3
"""Method-comparison report of one campaign (SPEC §5): figures and report.md
from the outputs of `rsi campaign CASE --out DIR`.

Usage: make_campaign_report.py DIR
Writes DIR/report.md and DIR/*.png.
"""
import csv
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = sys.argv[1]
rows = list(csv.DictReader(open(f"{out}/convergence.csv")))
for r in rows:
    r["modes"] = int(r["modes"])
    for k in ("e2", "e_inf", "wall_s", "speedup"):
        r[k] = float(r[k])


def history(name):
    data = list(csv.DictReader(open(f"{out}/runs/{name}/history.csv")))
    return ([1e3 * float(d["t"]) for d in data], [1e3 * float(d["gap_1"]) for d in data],
            [float(d["energy"]) for d in data], [float(d["external_work"]) + float(d["contact_work"]) for d in data])


summaries = {f"{r['method']}-{r['modes']}": json.load(open(f"{out}/runs/{r['method']}-{r['modes']}/summary.json"))
             for r in rows}
t_ref, g_ref, e_ref, w_ref = history("full-0")

# Figs. 10-13: blade-1 gap, reduced vs reference, 0-20 ms and 0-5 ms.
for method, title in (("cb", "Craig-Bampton (eta fixed-interface modes)"),
                      ("ccm", "Craig-Chang-Martinez (psi free modes)")):
    counts = sorted(r["modes"] for r in rows if r["method"] == method)
    fig, axes = plt.subplots(2, 1, figsize=(8, 7))
    for ax, t_max in zip(axes, (20.0, 5.0)):
        keep = [i for i, t in enumerate(t_ref) if t <= t_max]
        ax.plot([t_ref[i] for i in keep], [g_ref[i] for i in keep], "k-", lw=2, label="reference (full FE)")
        for m in counts:
            t, g, _, _ = history(f"{method}-{m}")
            ax.plot([t[i] for i in keep], [g[i] for i in keep], lw=1, label=f"{method.upper()} {m}")
        ax.axhline(0.0, color="tab:red", lw=0.8)
        ax.set_xlim(0, t_max)
        ax.set_xlabel("time [ms]")
        ax.set_ylabel("gap of blade tip 1 [mm]")
        ax.grid(alpha=0.3)
    axes[0].set_title(f"{title}: blade-1 gap against the reference")
    axes[0].legend(fontsize=7, ncol=4, loc="upper right")
    fig.tight_layout()
    fig.savefig(f"{out}/gap_{method}.png", dpi=110)
    plt.close(fig)

# Error norms against the number of modes.
fig, ax = plt.subplots(figsize=(7, 4.5))
for method, marker in (("cb", "o"), ("ccm", "s")):
    sel = sorted((r for r in rows if r["method"] == method), key=lambda r: r["modes"])
    ax.semilogy([r["modes"] for r in sel], [r["e2"] for r in sel], marker + "-", label=f"{method.upper()} e2")
    ax.semilogy([r["modes"] for r in sel], [r["e_inf"] for r in sel], marker + "--", label=f"{method.upper()} e_inf")
ax.set_xlabel("number of modes (eta for CB, psi for CCM), plus 44 boundary coordinates")
ax.set_ylabel("error of the blade-1 gap history")
ax.grid(alpha=0.3, which="both")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(f"{out}/error_vs_modes.png", dpi=110)
plt.close(fig)

# Fig. 14: relative computation time.
fig, ax = plt.subplots(figsize=(8, 4))
names = [f"{r['method']}-{r['modes']}" for r in rows]
ax.bar(range(len(rows)), [100.0 * r["wall_s"] / rows[0]["wall_s"] for r in rows], color="0.4")
ax.set_xticks(range(len(rows)))
ax.set_xticklabels(names, rotation=60, fontsize=8)
ax.set_ylabel("wall time, % of the reference")
ax.set_title("Relative computation time (cf. paper Fig. 14), measured in one campaign")
ax.grid(alpha=0.3, axis="y")
fig.tight_layout()
fig.savefig(f"{out}/relative_time.png", dpi=110)
plt.close(fig)

# Energy balance traces.
fig, ax = plt.subplots(figsize=(8, 4))
for name in ("full-0", "cb-44", "ccm-44"):
    if name in summaries:
        t, _, e, w = history(name)
        ax.plot(t, e, lw=1.2, label=f"{name}: energy E")
        ax.plot(t, [summaries[name]["initial_energy"] + x for x in w], "--", lw=0.8, label=f"{name}: E0 + W_ext + W_contact")
ax.set_xlabel("time [ms]")
ax.set_ylabel("[J]")
ax.grid(alpha=0.3)
ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(f"{out}/energy.png", dpi=110)
plt.close(fig)

ref = summaries["full-0"]
lines = ["# Method comparison: reduced models against the full reference", "",
         f"Reference (full FE): {ref['dofs']} dofs, {ref['steps']} steps, wall {ref['wall_seconds']:.3f} s "
         f"(all runs of this table measured in one campaign, two at a time on the two cores).", "",
         "| method | modes | e2 | e_inf | wall s | speedup | critical dt [s] | max penetration [m] | energy balance error [J] |",
         "|---|---|---|---|---|---|---|---|---|"]
for r, name in zip(rows, names):
    s = summaries[name]
    lines.append(f"| {r['method']} | {r['modes']} | {r['e2']:.4f} | {r['e_inf']:.4f} | {r['wall_s']:.3f} | "
                 f"{r['speedup']:.2f} | {s['critical_dt']:.3e} | {s['max_penetration']:.1e} | "
                 f"{s['energy_balance_error']:.1e} |")
lines += ["", "![CB gaps](gap_cb.png)", "", "![CCM gaps](gap_ccm.png)", "", "![errors](error_vs_modes.png)", "",
          "![relative time](relative_time.png)", "", "![energy](energy.png)", ""]
open(f"{out}/report.md", "w").write("\n".join(lines))
print(f"wrote {out}/report.md and its figures")
