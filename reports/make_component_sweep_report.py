#!/usr/bin/python3
"""Report of a component case's rotation-speed sweep (`rsi sweep CASE --out
DIR` on a blade rubbing on its rigid casing): the interaction map, a
Campbell diagram of the response and sweep_report.md.

Usage: make_component_sweep_report.py DIR
Reads DIR/sweep.csv (a row per speed and run), DIR/campbell.csv when the
sweep had rotation effects (the blade's frequencies at each speed, drawn as
curves), DIR/interaction_lines.csv
(per run, the blade's lowest natural frequencies f_k and, for engine orders
EO = 1..10, the speed 2 pi f_k / EO) and DIR/sweep_summary.json; writes
DIR/sweep_map.png, DIR/sweep_campbell.png and DIR/sweep_report.md, each whole
(a temporary file, then a rename). Every number in the text is read from
those files. Missing or malformed input: `make_component_sweep_report.py:
error: ...` on stderr, exit status 1.

Lines drawn. The blade turns at Omega inside a casing at rest; seen from the
blade, a casing of n lobes passes n times a revolution, so it forces at
n Omega / 2 pi and its harmonics. The oval casing has two lobes (its gap has
period pi in the tip's angle): its orders are EO = 2, 4, 6, 8, 10 (solid
lines, column casing_harmonic = 1). The odd orders (dotted) are drawn for
reading the map: the casing does not force them, but contact, being
one-sided, makes every harmonic of the response. A resonance is where
EO Omega / 2 pi = f_k: Omega = 2 pi f_k / EO.
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

SWEEP_COLUMNS = ["speed_rad_s", "run", "method", "modes", "status", "diverged", "rows", "max_tip_radial",
                 "max_contact_force", "contact_fraction", "energy_ratio", "balance_residual",
                 "f1_hz", "a1", "f2_hz", "a2", "f3_hz", "a3"]
# A case with an abradable liner adds these (docs/outputs.md).
WEAR_COLUMNS = ["max_wear_depth", "wear_lobes", "plastic_work"]
LINE_COLUMNS = ["run", "mode", "blade_hz", "engine_order", "casing_harmonic", "speed_rad_s"]
NAME = "make_component_sweep_report.py"


def die(message):
    report_files.die(NAME, message)


def read_csv(path, columns, optional=()):
    return report_files.read_csv(NAME, path, columns, optional)


def main():
    if len(sys.argv) != 2:
        die("usage: make_component_sweep_report.py DIR")
    out = sys.argv[1]
    rows = read_csv(os.path.join(out, "sweep.csv"), SWEEP_COLUMNS, WEAR_COLUMNS)
    lines = read_csv(os.path.join(out, "interaction_lines.csv"), LINE_COLUMNS)
    summary_path = os.path.join(out, "sweep_summary.json")
    try:
        summary = json.load(open(summary_path))
    except (OSError, ValueError) as e:
        die(f"{summary_path}: {e}")
    if not rows:
        die("sweep.csv has no rows")
    # With rotation effects: the rotating blade's frequencies at each speed
    # (campbell.csv), and interaction_lines.csv holds the crossings.
    campbell_path = os.path.join(out, "campbell.csv")
    campbell = {}
    if os.path.exists(campbell_path):
        for r in read_csv(campbell_path, ["speed_rad_s", "mode", "frequency_hz"]):
            campbell.setdefault(int(r["mode"]), []).append(
                (abs(number(r["speed_rad_s"])), number(r["frequency_hz"])))

    def natural_at(speed):
        """The blade's natural frequencies at `speed` [(mode, Hz)]: campbell.csv's
        nearest grid speed with rotation effects, else the lines' (at rest)."""
        if campbell:
            return [(k, min(pts, key=lambda p: abs(p[0] - speed))[1]) for k, pts in sorted(campbell.items())]
        return sorted({(int(l["mode"]), number(l["blade_hz"])) for l in lines if l["run"] == first_run})
    units = summary.get("units", "model units")
    runs = []
    for r in rows:
        if r["run"] not in runs:
            runs.append(r["run"])
    first_run = runs[0]
    speeds = sorted({abs(number(r["speed_rad_s"])) for r in rows})
    lo, hi = speeds[0], speeds[-1]

    def series(run, key):
        pts = [(abs(number(r["speed_rad_s"])), number(r[key])) for r in rows
               if r["run"] == run and r["status"] != "failed"]
        return [p[0] for p in pts], [p[1] for p in pts]

    # Crossings in the swept range: Omega = 2 pi f_k / EO.
    crossings = [(abs(number(l["speed_rad_s"])), int(l["engine_order"]), int(l["mode"]),
                  number(l["blade_hz"]), l["casing_harmonic"] == "1", l["run"])
                 for l in lines if lo <= abs(number(l["speed_rad_s"])) <= hi]
    shown = [c for c in crossings if c[5] == first_run]

    # The map: tip displacement, contact fraction, contact force against speed.
    # "N, mm, t, s": force, length, mass, time.
    parts = [p.strip() for p in units.split(",")]
    force_unit, length_unit = (parts[0], parts[1]) if len(parts) >= 2 else ("model", "model")
    panels = [("max_tip_radial", f"max |radial tip displacement| [{length_unit}]"),
              ("contact_fraction", "contact fraction (rows with a closed contact)"),
              ("max_contact_force", f"max normal contact force [{force_unit}]")]
    liner = "max_wear_depth" in rows[0]
    def worn_through(run=None):
        """|speeds| of the runs stopped worn through (of `run` only if given), in row order."""
        return [abs(number(r["speed_rad_s"])) for r in rows
                if r["status"] == "worn_through" and run in (None, r["run"])]

    worn_speeds = sorted(set(worn_through()))
    # The bands' width: the smallest speed step.
    step = min((b - a for a, b in zip(speeds, speeds[1:])), default=1.0)
    if liner:
        panels.append(("max_wear_depth", f"deepest wear of the liner [{length_unit}]"))
    fig, axes = plt.subplots(len(panels), 1, figsize=(10, 3 * len(panels)), sharex=True)
    for ax, (key, label) in zip(axes, panels):
        for run in runs:
            x, y = series(run, key)
            ax.plot(x, y, ".-", ms=3, lw=0.8, label=run)
        # A worn-through run stopped early (often before the transient: no
        # indicators): a grey band over its speed on every panel.
        for i, s in enumerate(worn_speeds):
            ax.axvspan(s - step / 2, s + step / 2, color="0.8", lw=0,
                       label="liner worn through (run stopped)" if i == 0 and ax is axes[0] else None)
        for s, eo, k, f, casing, _ in shown:
            ax.axvline(s, color="C3" if casing else "0.6", ls="-" if casing else ":", lw=0.8)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    top = axes[0]
    ymax = top.get_ylim()[1]
    for s, eo, k, f, casing, _ in shown:
        top.text(s, ymax, f"EO{eo}/f{k}", rotation=90, va="top", ha="right", fontsize=6,
                 color="C3" if casing else "0.4")
    axes[0].legend(fontsize=8, loc="upper right")
    axes[-1].set_xlabel("rotation speed |Omega| [rad/s]")
    fig.suptitle("Interaction map: red solid, the oval casing's orders EO = 2, 4, .. meeting f_k; "
                 "grey dotted, odd orders", fontsize=9)
    save_figure(fig, os.path.join(out, "sweep_map.png"))

    # Campbell diagram: the response's dominant frequencies, the blade's f_k,
    # and the engine-order lines f = EO Omega / 2 pi.
    fig, ax = plt.subplots(figsize=(10, 6))
    fmax = 0.0
    for i in (1, 2, 3):
        x, f = series(first_run, f"f{i}_hz")
        _, a = series(first_run, f"a{i}")
        amax = max([v for v in a if not math.isnan(v)] or [1.0])
        ax.scatter(x, f, s=[4 + 40 * (v / amax if not math.isnan(v) else 0) for v in a],
                   color=f"C{i - 1}", alpha=0.7, label=f"peak {i} of the response")
        fmax = max([fmax] + [v for v in f if not math.isnan(v)])
    if campbell:
        blade = [(k, pts[-1][1]) for k, pts in sorted(campbell.items())]
        for k, pts in sorted(campbell.items()):
            ax.plot([p[0] for p in pts], [p[1] for p in pts], color="k", lw=0.8, ls="--")
            ax.text(hi, pts[-1][1], f" f{k}(Omega)", va="center", fontsize=7)
    else:
        blade = natural_at(hi)
        for k, f in blade:
            ax.axhline(f, color="k", lw=0.6, ls="--")
            ax.text(hi, f, f" f{k} {f:.0f} Hz", va="center", fontsize=7)
    fmax = max(fmax, max([f for _, f in blade] or [0.0])) * 1.05
    for eo in range(1, 11):
        casing = summary.get("gap", "").startswith("oval") and eo % 2 == 0
        ax.plot([lo, hi], [eo * lo / (2 * math.pi), eo * hi / (2 * math.pi)],
                color="C3" if casing else "0.6", ls="-" if casing else ":", lw=0.8)
        y = eo * hi / (2 * math.pi)
        if y < fmax:
            ax.text(hi, y, f"EO{eo}", fontsize=7, color="C3" if casing else "0.4")
    ax.set_xlim(lo, hi * 1.08)
    ax.set_ylim(0, fmax)
    ax.set_xlabel("rotation speed |Omega| [rad/s]")
    ax.set_ylabel("frequency [Hz]")
    ax.set_title(f"Campbell diagram of {summary.get('response', 'the response')} ({first_run})", fontsize=9)
    ax.legend(fontsize=8, loc="upper left")
    ax.grid(alpha=0.3)
    save_figure(fig, os.path.join(out, "sweep_campbell.png"))

    # The text.
    md = ["# Rotation-speed sweep of a component: interaction map", "",
          f"Generated by reports/{NAME} from `sweep.csv`, `interaction_lines.csv` and "
          "`sweep_summary.json` beside it.", "",
          "## What was run", "",
          f"- Component {summary.get('component', '?')}, units {units}; {len(speeds)} speeds, "
          f"{lo:g}-{hi:g} rad/s; runs: {', '.join(runs)}.",
          f"- Each run {summary.get('revolutions', '?')} revolutions at "
          f"{summary.get('steps_per_revolution', '?')} samples a revolution; indicators over the "
          f"rows after {summary.get('transient_revolutions', '?')} revolutions.",
          f"- Casing gap: {summary.get('gap', '?')}; tip sliding {summary.get('tip_sliding', '?')}; "
          f"mu = {summary.get('friction_coefficient', '?')}; modal damping ratio "
          f"{summary.get('modal_ratio', '?')}. Spectrum: {summary.get('window', '?')}.",
          f"- Ranks {summary.get('ranks', '?')}, jobs {summary.get('jobs', '?')}; wall time of the "
          f"whole sweep {summary.get('wall_s', math.nan):.1f} s.", ""]
    # A liner's runs may also stop worn through (a cell's wear reached its thickness).
    statuses = ["completed", "diverged", "failed"] + (["worn_through"] if liner else [])
    md += ["| run | natural frequencies, tip free [Hz] | basis s | wall s per speed (median) | " +
           " | ".join(st.replace("_", " ") for st in statuses) + " |",
           "|---|---|---|---|" + "---|" * len(statuses)]
    for run_summary in summary.get("runs", []):
        name = run_summary.get("name", "?")
        count = {s: sum(1 for r in rows if r["run"] == name and r["status"] == s) for s in statuses}
        freqs = ", ".join(f"{f:.1f}" for f in run_summary.get("natural_frequencies_hz", []))
        md.append(f"| {name} | {freqs} | {run_summary.get('basis_s', math.nan):.3g} | "
                  f"{run_summary.get('wall_s_per_speed_median', math.nan):.3g} | " +
                  " | ".join(str(count[st]) for st in statuses) + " |")
    md += ["", "## Interaction map", "", "![interaction map](sweep_map.png)", "",
           "Vertical lines: the speeds 2 pi f_k / EO in the range (red solid: the oval casing's "
           "orders EO = 2, 4, ...; grey dotted: odd orders).", ""]
    for run in runs:
        x, y = series(run, "max_tip_radial")
        if not y:
            continue
        i = max(range(len(y)), key=lambda j: (y[j] if not math.isnan(y[j]) else -1))
        # Which line: the response's dominant frequency there, as an engine
        # order of that speed, and the natural frequency nearest to it.
        _, f1 = series(run, "f1_hz")
        note = ""
        if not math.isnan(f1[i]):
            eo = f1[i] / (x[i] / (2 * math.pi))
            blade_run = natural_at(x[i])
            note = f"; its dominant frequency is {f1[i]:.1f} Hz = {eo:.2f} x Omega/2pi"
            if blade_run:
                k, fk = min(blade_run, key=lambda p: abs(p[1] - f1[i]))
                order = round(eo)
                at = [abs(number(l["speed_rad_s"])) for l in lines if l["run"] == run and
                      int(l["mode"]) == k and int(l["engine_order"]) == order]
                where = (f"{2 * math.pi * fk / order:.1f} rad/s" if not campbell else
                         ", ".join(f"{w:.1f}" for w in at) + " rad/s" if at else "no speed of the range")
                note += (f", nearest natural frequency f{k} = {fk:.1f} Hz"
                         f"{' (at that speed)' if campbell else ''}, whose EO {order} line crosses "
                         f"at {where}" if order >= 1 else "")
        md.append(f"- {run}: the largest radial tip displacement, {y[i]:.4g}, is at {x[i]:g} rad/s{note}.")
        if liner:
            xw, w = series(run, "max_wear_depth")
            j = max(range(len(w)), key=lambda m: (w[m] if not math.isnan(w[m]) else -1))
            lobes = [r["wear_lobes"] for r in rows if r["run"] == run and r["status"] != "failed"]
            md.append(f"- {run}: the deepest wear, {w[j]:.4g}, is at {xw[j]:g} rad/s "
                      f"({lobes[j]} lobes there); liner: {summary.get('liner', {})}.")
            worn = worn_through(run)
            if worn:
                md.append(f"- {run}: the liner wore through (a cell's wear reached its thickness; "
                          f"the run stopped there, its indicators up to that step, grey bands on "
                          f"the map) at {len(worn)} speeds: " + ", ".join(f"{w:g}" for w in worn) +
                          " rad/s.")
    md += ["", "## Campbell diagram", "", "![Campbell diagram](sweep_campbell.png)", ""]
    failures = summary.get("failures", [])
    if failures:
        md += ["## Failed runs", ""] + [f"- {f}" for f in failures] + [""]
    write_whole(os.path.join(out, "sweep_report.md"), "\n".join(md) + "\n")
    print(f"wrote {out}/sweep_report.md")


if __name__ == "__main__":
    main()
