#!/usr/bin/python3
"""Report of a rotation-speed sweep of a bladed disk against its flexible
casing (`rsi sweep CASE --out DIR` on a case with rubbing.casing, issue 27
item 6): the indicators against speed beside the interaction lines, the
nodal-diameter map and sweep_report.md.

Usage: make_system_sweep_report.py DIR
Reads DIR/sweep.csv (a row per speed and run), DIR/interaction_lines.csv
(family, nodal_diameter k, casing_lobes n, blade_hz, casing_mode, casing_hz,
speed_rad_s: the speeds Omega_int = 2 pi (f_b + f_c) / n at which a disk
family's wave of k nodal diameters and a casing mode's forward wave of n
lobes meet at the tips, Legrand et al. 2009; k = n up to N/2, above it the
alias of n that N tips see, sweep/interaction_lines.hpp), DIR/nodal_diameters.csv and
DIR/sweep_summary.json; writes DIR/sweep_map.png, DIR/nodal_diameter_map.png
and DIR/sweep_report.md, each whole (a temporary file, then a rename). Every
number in the text is read from those files. Missing or malformed input:
`make_system_sweep_report.py: error: ...` on stderr, exit status 1.
"""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.dont_write_bytecode = True  # no __pycache__ beside the scripts
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import report_files  # noqa: E402
from report_files import number, save_figure, write_whole  # noqa: E402
from nodal_diameter_figure import draw_nodal_diameter_map  # noqa: E402

SWEEP_COLUMNS = ["speed_rad_s", "run", "method", "modes", "status", "diverged", "rows",
                 "max_abs_response", "max_contact_force", "contact_fraction", "energy_ratio",
                 "balance_residual", "f1_hz", "a1", "f2_hz", "a2", "f3_hz", "a3"]
LINE_COLUMNS = ["family", "nodal_diameter", "casing_lobes", "blade_hz", "casing_mode", "casing_hz",
                "speed_rad_s"]
MAP_COLUMNS = ["part", "index", "frequency_hz", "nodal_diameter"]
NAME = "make_system_sweep_report.py"


def die(message):
    report_files.die(NAME, message)


def read_csv(path, columns, optional=()):
    return report_files.read_csv(NAME, path, columns, optional)


def main():
    if len(sys.argv) != 2:
        die("usage: make_system_sweep_report.py DIR")
    out = sys.argv[1]
    rows = read_csv(os.path.join(out, "sweep.csv"), SWEEP_COLUMNS)
    # A rotor that is not a bladed disk (one blade in the ring) has no map.
    has_map = os.path.exists(os.path.join(out, "nodal_diameters.csv"))
    lines = read_csv(os.path.join(out, "interaction_lines.csv"), LINE_COLUMNS) if has_map else []
    nd_rows = read_csv(os.path.join(out, "nodal_diameters.csv"), MAP_COLUMNS) if has_map else []
    summary_path = os.path.join(out, "sweep_summary.json")
    try:
        summary = json.load(open(summary_path))
    except (OSError, ValueError) as e:
        die(f"{summary_path}: {e}")
    if not rows:
        die("sweep.csv has no rows")
    units = summary.get("units", "model units")
    parts = [p.strip() for p in units.split(",")]
    force_unit, length_unit = (parts[0], parts[1]) if len(parts) >= 2 else ("model", "model")
    runs = []
    for r in rows:
        if r["run"] not in runs:
            runs.append(r["run"])
    speeds = sorted({abs(number(r["speed_rad_s"])) for r in rows})
    lo, hi = speeds[0], speeds[-1]

    def series(run, key):
        pts = [(abs(number(r["speed_rad_s"])), number(r[key])) for r in rows
               if r["run"] == run and r["status"] != "failed"]
        return [p[0] for p in pts], [p[1] for p in pts]

    # The interaction speeds in the swept range, one per (family, k, n): the
    # casing's pairs of lobes give two lines a few rad/s apart.
    shown = {}
    for l in lines:
        w = number(l["speed_rad_s"])
        key = (int(l["family"]), int(l["nodal_diameter"]), int(l["casing_lobes"]))
        if lo <= w <= hi and (key not in shown or w < shown[key]):
            shown[key] = w

    def line_name(key):
        family, k, n = key
        return f"family {family}, k = {k}" + (f" (n = {n} lobes)" if n != k else "")

    if has_map:
        draw_nodal_diameter_map(nd_rows, os.path.join(out, "nodal_diameter_map.png"))

    response = summary.get("response", "the response dof")
    # Growth spans decades (a diverged run's energy ratio reaches 1e6):
    # logarithmic axes but for the contact fraction.
    panels = [("max_abs_response", f"max |{response}| [{length_unit}]", True),
              ("energy_ratio", "E(last) / E(first after the transient)", True),
              ("contact_fraction", "contact fraction (rows with a closed contact)", False),
              ("max_contact_force", f"max normal contact force [{force_unit}]", True)]
    fig, axes = plt.subplots(len(panels), 1, figsize=(10, 2.6 * len(panels)), sharex=True)
    for ax, (key, label, log) in zip(axes, panels):
        for run in runs:
            x, y = series(run, key)
            ax.plot(x, y, ".-", ms=3, lw=0.8, label=run)
        for (family, k, n), w in shown.items():
            ax.axvline(w, color=f"C{2 + family}", ls="-" if n == k else ":", lw=0.8)
        ax.set_ylabel(label, fontsize=8)
        if log:
            ax.set_yscale("log")
        ax.grid(alpha=0.3)
    ymax = axes[0].get_ylim()[1]
    for key, w in shown.items():
        axes[0].text(w, ymax, line_name(key), rotation=90, va="top", ha="right", fontsize=6)
    axes[0].legend(fontsize=8, loc="upper right")
    axes[-1].set_xlabel("rotation speed |Omega| [rad/s]")
    fig.suptitle("Sweep against the interaction lines Omega_int = 2 pi (f_b + f_c) / n (red: "
                 "disk family 1, purple: family 2; dotted: n > N/2 lobes, aliased to k)", fontsize=9)
    save_figure(fig, os.path.join(out, "sweep_map.png"))

    md = ["# Rotation-speed sweep of a bladed disk against its flexible casing", "",
          f"Generated by reports/{NAME} from `sweep.csv`, `interaction_lines.csv`, "
          "`nodal_diameters.csv` and `sweep_summary.json` beside it.", "",
          "## What was run", "",
          f"- System {summary.get('component', '?')}, units {units}; {len(speeds)} speeds, "
          f"{lo:g}-{hi:g} rad/s; runs: {', '.join(runs)}; the casing in "
          f"{summary.get('casing_modes', '?')} modes plus a static correction in the reduced runs.",
          f"- Each run {summary.get('revolutions', '?')} revolutions at "
          f"{summary.get('steps_per_revolution', '?')} samples a revolution, from rest, the casing "
          "loaded as the case says; indicators over the rows after "
          f"{summary.get('transient_revolutions', '?')} revolutions.",
          f"- Contact: {summary.get('contact_nodes', '?')} tips, mu = "
          f"{summary.get('friction_coefficient', '?')}; modal damping ratio "
          f"{summary.get('modal_ratio', '?')}. Spectrum: {summary.get('window', '?')}.",
          f"- Ranks {summary.get('ranks', '?')}, jobs {summary.get('jobs', '?')}; wall time of the "
          f"whole sweep {summary.get('wall_s', math.nan):.1f} s.", "",
          "| run | coordinates | basis s | wall s per speed (median) | completed | diverged | failed |",
          "|---|---|---|---|---|---|---|"]
    for run_summary in summary.get("runs", []):
        name = run_summary.get("name", "?")
        count = {s: sum(1 for r in rows if r["run"] == name and r["status"] == s)
                 for s in ("completed", "diverged", "failed")}
        md.append(f"| {name} | {run_summary.get('coordinates', '?')} | "
                  f"{run_summary.get('basis_s', math.nan):.3g} | "
                  f"{run_summary.get('wall_s_per_speed_median', math.nan):.3g} | "
                  f"{count['completed']} | {count['diverged']} | {count['failed']} |")
    md += ["", "## Against the interaction lines", "", "![sweep map](sweep_map.png)", ""]
    if shown:
        md += ["| family | disk diameters k | casing lobes n | Omega_int [rad/s] |",
               "|---|---|---|---|"]
        md += [f"| {family} | {k} | {n} | {w:.1f} |"
               for (family, k, n), w in sorted(shown.items(), key=lambda i: i[1])]
        md.append("")
    elif has_map:
        md += ["No interaction line falls in the swept range.", ""]
    for run in runs:
        for key, what in (("max_abs_response", f"largest |{response}|"),
                          ("energy_ratio", "largest energy ratio")):
            x, y = series(run, key)
            finite = [i for i in range(len(y)) if not math.isnan(y[i])]
            if not finite:
                continue
            i = max(finite, key=lambda j: y[j])
            near = ""
            if shown:
                key, w = min(shown.items(), key=lambda item: abs(item[1] - x[i]))
                near = (f"; the nearest interaction line is {line_name(key)} at "
                        f"{w:.1f} rad/s ({100 * (x[i] - w) / w:+.1f} %)")
            md.append(f"- {run}: the {what}, {y[i]:.4g}, is at {x[i]:g} rad/s{near}.")
    md += ["", "## Nodal-diameter map", ""]
    md += (["![nodal-diameter map](nodal_diameter_map.png)", ""] if has_map else
           ["None: the rotor is not a bladed disk (no nodal diameters, no interaction "
            "lines).", ""])
    failures = summary.get("failures", [])
    if failures:
        md += ["## Failed runs", ""] + [f"- {f}" for f in failures] + [""]
    write_whole(os.path.join(out, "sweep_report.md"), "\n".join(md) + "\n")
    print(f"wrote {out}/sweep_report.md")


if __name__ == "__main__":
    main()
