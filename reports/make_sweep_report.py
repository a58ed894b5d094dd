#!/usr/bin/python3
"""Report of a rotation-speed sweep (`rsi sweep CASE --out DIR`): the
interaction map, a Campbell diagram of the response and sweep_report.md.

Usage: make_sweep_report.py DIR
Reads DIR/sweep.csv (a row per speed and run), DIR/interaction_lines.csv and
DIR/sweep_summary.json (every key optional); writes DIR/sweep_map.png,
DIR/sweep_campbell.png and DIR/sweep_report.md, each whole (a temporary file,
then a rename). Every number in the text is read from those files. Missing or
malformed input: `make_sweep_report.py: error: ...` on stderr, exit status 1.

Interaction (Legrand et al. 2009, after Schmiechen): the backward wave of a
blade family at n nodal diameters, seen in the fixed frame, travels with the
casing's forward n-lobe wave when Omega = (omega_b + omega_c) / n. The tip
history is in the rotating frame, where the casing mode appears at
|f_c - n Omega / 2 pi| and f_c + n Omega / 2 pi; the first meets the blade
frequency f_b exactly at that speed (the circles of the Campbell diagram).
"""
import csv
import json
import math
import numbers
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402
from scipy.signal import find_peaks  # noqa: E402

SWEEP_COLUMNS = ["speed_rad_s", "run", "method", "modes", "status", "diverged", "rows", "max_tip_radial_m",
                 "max_tip_tangential_m", "max_contact_force_n", "contact_fraction", "energy_ratio",
                 "f1_hz", "a1_m", "f2_hz", "a2_m", "f3_hz", "a3_m"]
LINE_COLUMNS = ["family", "nodal_diameter", "blade_hz", "casing_mode", "casing_hz", "speed_rad_s"]
STATUSES = ("completed", "diverged", "failed")
# (column, axis label, log axis): the panels of the interaction map, top to bottom.
INDICATORS = (("max_tip_radial_m", "max tip radial [m]", False),
              ("max_tip_tangential_m", "max tip tangential [m]", False),
              ("max_contact_force_n", "max contact force [N]", False),
              ("contact_fraction", "contact fraction", False),
              ("energy_ratio", "E(end) / E(transient)", True))
PEAK_COLUMNS = ("f1_hz", "a1_m", "f2_hz", "a2_m", "f3_hz", "a3_m")
# A reduced run disagrees with the full one at a speed when the statuses differ
# or max_tip_radial_m differs by more than this fraction of the full value.
DISAGREE_WHY = ("10 % is the loosest error the campaign's mode-count guidance accepts for a reduced model "
                "(e2 <= 0.1 on the blade-1 gap history), so a larger miss of the peak tip displacement is more "
                "than the error a reduced model is accepted with")
DISAGREE_REL = 0.1
# A response peak must stand out of its neighbours by this fraction of the run's
# largest max_tip_radial_m (of its largest value, not of its range, which would
# turn the wiggles of a flat sweep without resonance into peaks).
PEAK_WHY = ("a secondary resonance a tenth the size of the main one stays, the wiggles of a few per cent that "
            "a finite, trimmed history leaves between neighbouring speeds go")
PEAK_PROMINENCE = 0.1
MARKERS = "osD^vP*h"
FAMILY_STYLES = ("--", ":", "-.", (0, (5, 1, 1, 1)))


class InputError(Exception):
    """Missing or malformed input: reported on one line, exit status 1."""


# ---- Reading the three files.

def read_csv(path, columns):
    """Rows of `path` as dicts; the header must be exactly `columns`."""
    try:
        with open(path, newline="") as f:
            table = [r for r in csv.reader(f) if r]
    except OSError as e:
        raise InputError(f"{path}: {e.strerror}")
    if not table:
        raise InputError(f"{path}: empty file, expected the header {','.join(columns)}")
    if table[0] != columns:
        wrong = next((f"column {k + 1} is {a!r}, expected {b!r}" for k, (a, b) in enumerate(zip(table[0], columns))
                      if a != b), f"{len(table[0])} columns, expected {len(columns)}")
        raise InputError(f"{path}: header: {wrong}")
    for i, r in enumerate(table[1:]):
        if len(r) != len(columns):
            raise InputError(f"{path}:{i + 2}: {len(r)} fields, expected {len(columns)}")
    return [(f"{path}:{i + 2}", dict(zip(columns, r))) for i, r in enumerate(table[1:])]


def number(row, key, where, kind=float, empty=None):
    """row[key] as `kind`; an empty field gives `empty` when allowed (not None)."""
    text = row[key].strip()
    if text == "" and empty is not None:
        return empty
    try:
        x = kind(text)
    except ValueError:
        raise InputError(f"{where}: {key} = {text!r} is not {'an integer' if kind is int else 'a number'}")
    if empty is None and not math.isfinite(x):
        raise InputError(f"{where}: {key} = {text!r} is not finite")
    return x


def read_sweep(out):
    """The runs of sweep.csv in their order of first appearance (the case's),
    each with numpy arrays sorted by speed."""
    path = f"{out}/sweep.csv"
    runs, keys = {}, [k for k, _, _ in INDICATORS] + list(PEAK_COLUMNS)
    for where, r in read_csv(path, SWEEP_COLUMNS):
        for ok, what in ((r["status"] in STATUSES, f"status {r['status']!r}, expected one of {', '.join(STATUSES)}"),
                         (r["diverged"] in ("0", "1"), f"diverged {r['diverged']!r}, expected 0 or 1"),
                         (r["run"] != "", "run is empty")):
            if not ok:
                raise InputError(f"{where}: {what}")
        run = runs.setdefault(r["run"], {"name": r["run"], "method": r["method"], "modes": r["modes"], "rows": []})
        rec = {"speed": number(r, "speed_rad_s", where), "status": r["status"]}
        for key in keys:  # a failed run has no indicators, whatever the row says
            rec[key] = math.nan if r["status"] == "failed" else number(r, key, where, empty=math.nan)
        run["rows"].append(rec)
    if not runs:
        raise InputError(f"{path}: no rows")
    for run in runs.values():  # columns sorted by speed, one row a speed
        rows = sorted(run.pop("rows"), key=lambda rec: rec["speed"])
        twice = [a["speed"] for a, b in zip(rows, rows[1:]) if a["speed"] == b["speed"]]
        if twice:
            raise InputError(f"{path}: run {run['name']} has several rows at speed {twice[0]!r}")
        for key in ["speed", "status"] + keys:
            run[key] = np.array([rec[key] for rec in rows])
    return list(runs.values())


def read_lines(out):
    path = f"{out}/interaction_lines.csv"
    lines = []
    for where, r in read_csv(path, LINE_COLUMNS):
        line = {k: number(r, k, where, int if k in ("family", "nodal_diameter", "casing_mode") else float)
                for k in LINE_COLUMNS}
        if line["nodal_diameter"] < 1 or line["family"] < 1:
            raise InputError(f"{where}: family {line['family']} and nodal_diameter {line['nodal_diameter']}, "
                             "expected >= 1")
        lines.append(line)
    return lines


def read_summary(out):
    path = f"{out}/sweep_summary.json"
    try:
        with open(path) as f:
            summary = json.load(f)
    except OSError as e:
        raise InputError(f"{path}: {e.strerror}")
    except ValueError as e:
        raise InputError(f"{path}: not JSON: {e}")
    if not isinstance(summary, dict):
        raise InputError(f"{path}: expected a JSON object")
    return summary


# ---- What the report computes.

def disagreements(ref, run):
    """[(speed, full row index, run row index, reason)] where `run` disagrees with
    the full run `ref`: the statuses differ, or, both completed, max_tip_radial_m
    differs by more than DISAGREE_REL of the full value (a diverged run's maximum
    is that of a blow-up cut short, not a response level, so it is not compared)."""
    at = {s: i for i, s in enumerate(ref["speed"])}
    found = []
    for j, s in enumerate(run["speed"]):
        i = at.get(s)
        if i is None:
            continue
        a, b = ref["max_tip_radial_m"][i], run["max_tip_radial_m"][j]
        if ref["status"][i] != run["status"][j]:
            found.append((s, i, j, f"status {ref['status'][i]} against {run['status'][j]}"))
        elif ref["status"][i] == "completed" and np.isfinite(a + b) and abs(b - a) > DISAGREE_REL * abs(a):
            found.append((s, i, j, f"max tip radial {100 * (b - a) / a:+.0f} %" if a else "max tip radial: full is 0"))
    return found


def response_peaks(run):
    """([(row index, prominence)] of the local maxima of max_tip_radial_m over the
    run's completed speeds, why there are none). Diverged values are left out:
    a blow-up cut short would set the scale and hide the resonances."""
    keep = np.flatnonzero((run["status"] == "completed") & np.isfinite(run["max_tip_radial_m"]))
    y = run["max_tip_radial_m"][keep]
    if len(y) < 3:
        return [], f"no peak: {len(y)} completed speed{'s' * (len(y) != 1)}, a local maximum needs 3"
    peaks, props = find_peaks(y, prominence=PEAK_PROMINENCE * np.max(np.abs(y)))
    return [(keep[p], prom) for p, prom in zip(peaks, props["prominences"])], "no peak prominent enough"


def nearest_line(lines, lo, hi):
    """The predicted line nearest to the speeds lo..hi (None without lines)."""
    return min(lines, key=lambda ln: max(lo - ln["speed_rad_s"], ln["speed_rad_s"] - hi), default=None)


def g(x, digits=4):
    """x to `digits` significant digits, exponent form below 1e-3 (metres of
    tip displacement); '-' when not available."""
    if not isinstance(x, numbers.Real) or math.isnan(x):
        return "-"
    return f"{x:.{digits - 1}e}" if 0 < abs(x) < 1e-3 else f"{x:.{digits}g}"


def count(run, status):
    return int(np.sum(run["status"] == status))


# ---- Figures.

def save(fig, out, name):
    """Writes a figure whole: a temporary file, then a rename."""
    fig.savefig(f"{out}/.{name}.tmp.png", dpi=110)
    os.replace(f"{out}/.{name}.tmp.png", f"{out}/{name}")
    plt.close(fig)


def style(i, run):
    """The full run black and filled; reduced runs in colour, hollow markers."""
    full = run["method"] == "full"
    colour = "black" if full else f"C{i % 10}"
    return dict(color=colour, marker=MARKERS[i % len(MARKERS)], ms=5 if full else 6, lw=1.2 if full else 1.0,
                mfc=colour if full else "none")


def x_limits(speeds):
    lo, hi = min(speeds), max(speeds)
    pad = 0.03 * (hi - lo) if hi > lo else 0.05 * max(abs(hi), 1.0)
    return lo - pad, hi + pad


def half_step(speeds):
    """Half the smallest speed step: the width of a disagreement's shading."""
    steps = np.diff(np.unique(speeds))
    return 0.5 * steps.min() if len(steps) else 0.02 * max(abs(speeds[0]), 1.0)


def draw_lines(ax, lines_in, labels):
    """Vertical lines at the predicted speeds, one style a family; n and family
    labelled once per (family, n) (a clamp splits a ring pair into two close lines)."""
    done = set()
    for ln in lines_in:
        ax.axvline(ln["speed_rad_s"], color="0.45", lw=0.8,
                   ls=FAMILY_STYLES[(ln["family"] - 1) % len(FAMILY_STYLES)], zorder=0)
        key = (ln["family"], ln["nodal_diameter"])
        if labels and key not in done:
            done.add(key)
            ax.text(ln["speed_rad_s"], 1.01, f"n{key[1]} F{key[0]}", transform=ax.get_xaxis_transform(),
                    rotation=90, fontsize=7, ha="center", va="bottom", color="0.3")


def draw_run(ax, i, run, key):
    st = style(i, run)
    y = run[key]
    ax.plot(run["speed"], y, label=run["name"], **st)
    strip = ax.get_xaxis_transform()  # x in data, y in axes fractions
    div = run["status"] == "diverged"
    shown = div & np.isfinite(y)
    ax.plot(run["speed"][shown], y[shown], "x", color="red", ms=10, mew=2, zorder=5)
    ax.plot(run["speed"][div & ~shown], np.full(np.sum(div & ~shown), 0.95), "x", color="red", ms=10, mew=2,
            transform=strip)
    failed = run["status"] == "failed"
    ax.plot(run["speed"][failed], np.full(np.sum(failed), 0.035 + 0.05 * (i % 2)), st["marker"], color="red",
            mec="k", ms=7, transform=strip, zorder=5)


def reserve_strip(ax):
    """Widens the y axis downwards by a tenth, so that the failed markers at the
    bottom sit below the data instead of among it."""
    lo, hi = ax.get_ylim()
    ax.set_ylim(lo / (hi / lo) ** 0.12 if ax.get_yscale() == "log" else lo - 0.12 * (hi - lo), hi)


def plot_map(out, runs, lines_in, disagree, xlim):
    fig, axes = plt.subplots(len(INDICATORS), 1, figsize=(11, 13.5), sharex=True)
    width = half_step(np.concatenate([r["speed"] for r in runs]))
    for p, (ax, (key, label, log)) in enumerate(zip(axes, INDICATORS)):
        draw_lines(ax, lines_in, labels=p == 0)
        for i, run in enumerate(runs):
            draw_run(ax, i, run, key)
            for s, *_ in disagree.get(run["name"], []):
                ax.axvspan(s - width, s + width, color=style(i, run)["color"], alpha=0.15, lw=0, zorder=0)
        values = np.concatenate([r[key] for r in runs])
        values = values[np.isfinite(values)]
        if log and np.any(values > 0):
            ax.set_yscale("log")
        if not len(values):
            ax.text(0.5, 0.5, "no run has a value", transform=ax.transAxes, ha="center", color="0.4")
            ax.set_yticks([])
        reserve_strip(ax)
        if not log and len(values):
            ax.ticklabel_format(axis="y", style="sci", scilimits=(-3, 4))
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[-1].set_xlim(*xlim)
    axes[-1].set_xlabel("rotation speed Omega [rad/s]")
    handles = [Line2D([], [], **style(i, r), label=r["name"]) for i, r in enumerate(runs)]
    handles += [Line2D([], [], ls="", marker="x", color="red", ms=8, mew=2, label="diverged"),
                Line2D([], [], ls="", marker="o", color="red", mec="k", label="failed (at the bottom, run's marker)")]
    handles += [Patch(color=style(i, r)["color"], alpha=0.15, label=f"{r['name']} disagrees with the full run")
                for i, r in enumerate(runs) if r["name"] in disagree]
    families = sorted({ln["family"] for ln in lines_in})
    handles += [Line2D([], [], color="0.45", lw=0.8, ls=FAMILY_STYLES[(f - 1) % len(FAMILY_STYLES)],
                       label=f"predicted interaction, family {f}") for f in families]
    fig.legend(handles=handles, loc="upper center", ncol=4, fontsize=8, frameon=False)
    fig.subplots_adjust(left=0.09, right=0.98, top=0.92, bottom=0.05, hspace=0.08)
    save(fig, out, "sweep_map.png")


def casing_lines(ax, lines, omega, f_max):
    """Each casing mode seen from the rotating frame, |f_c - n Omega/2pi| solid and
    f_c + n Omega/2pi dashed, one colour per n; legend handles for the n shown."""
    shown = {}
    for _, n, hz in sorted({(ln["casing_mode"], ln["nodal_diameter"], ln["casing_hz"]) for ln in lines}):
        colour = plt.cm.viridis(((n - 1) % 10) / 9)
        for y, ls in ((np.abs(hz - n * omega / (2 * np.pi)), "-"), (hz + n * omega / (2 * np.pi), "--")):
            ax.plot(omega, y, ls=ls, color=colour, lw=0.8, alpha=0.8, zorder=1)
            if np.any(y <= f_max):
                shown[n] = colour
    handles = [Line2D([], [], color=c, lw=0.8, label=f"casing n = {n}") for n, c in sorted(shown.items())]
    if shown:
        handles += [Line2D([], [], color="0.4", lw=0.8, ls="-", label="|f_c - n Omega/2pi|"),
                    Line2D([], [], color="0.4", lw=0.8, ls="--", label="f_c + n Omega/2pi")]
    return handles


def plot_campbell(out, runs, lines, lines_in, xlim):
    f1 = np.concatenate([r["f1_hz"] for r in runs])
    f_max = max(200.0, 1.2 * np.nanmax(f1)) if np.any(np.isfinite(f1)) else 200.0
    fig, ax = plt.subplots(figsize=(12, 7))
    omega = np.linspace(xlim[0], xlim[1], 300)
    for hz in np.unique(np.round([ln["blade_hz"] for ln in lines], 1)):
        if hz <= f_max:
            ax.axhline(hz, color="0.2", lw=1.2, zorder=1)
    handles = [Line2D([], [], **style(i, r), ls="", label=r["name"]) for i, r in enumerate(runs)]
    handles += [Line2D([], [], color="0.2", lw=1.2, label="blade families")] if lines else []
    handles += [Line2D([], [], ls="", marker="o", mfc="none", mec="red", ms=9,
                       label="predicted interaction")] if lines_in else []
    handles += casing_lines(ax, lines, omega, f_max)
    ax.plot([ln["speed_rad_s"] for ln in lines_in], [ln["blade_hz"] for ln in lines_in], "o", mfc="none",
            mec="red", ms=9, zorder=2)
    amps = np.concatenate([r[a] for r in runs for a in ("a1_m", "a2_m", "a3_m")])
    has_amps = np.any(np.isfinite(amps) & (amps > 0))
    a_max = np.nanmax(amps) if has_amps else 1.0
    for i, run in enumerate(runs):
        st = style(i, run)
        for f, a in (("f1_hz", "a1_m"), ("f2_hz", "a2_m"), ("f3_hz", "a3_m")):
            size = 6 + 150 * np.nan_to_num(run[a] / a_max)
            ax.scatter(run["speed"], run[f], s=size, marker=st["marker"], edgecolors=st["color"],
                       facecolors=st["mfc"], lw=1, alpha=0.8, zorder=3)
    ax.set_xlim(*xlim)
    ax.set_ylim(0, f_max)
    ax.set_xlabel("rotation speed Omega [rad/s]")
    ax.set_ylabel("frequency in the rotating frame [Hz]")
    sizes = f"(marker area ~ amplitude, largest {g(a_max, 3)} m)" if has_amps else "(none: no run has a spectrum)"
    ax.set_title(f"Peaks f1-f3 of blade 1's radial tip spectrum {sizes} over the model's lines, rotating frame",
                 fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(handles=handles, fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    save(fig, out, "sweep_campbell.png")


# ---- Text.

def run_info(summary, name):
    """The run's entry of sweep_summary.json, {} when it has none."""
    runs = summary.get("runs") if isinstance(summary.get("runs"), list) else []
    return next((r for r in runs if isinstance(r, dict) and r.get("name") == name), {})


def span(lo, hi):
    return f"{g(lo)}-{g(hi)}" if g(lo) != g(hi) else g(lo)


def setup_lines(summary, runs, speeds, ref):
    lo, hi = min(speeds), max(speeds)
    steps = np.diff(speeds)
    grid = (f"{len(speeds)} speed{'s' * (len(speeds) != 1)}, {span(lo, hi)} rad/s "
            f"({span(lo * 30 / math.pi, hi * 30 / math.pi)} rpm)"
            + (f", uniform step {g(steps[0])} rad/s" if len(steps) and np.ptp(steps) <= 1e-9 * hi else ""))
    L = ["## What was run", "",
         f"- Speeds: {grid}.",
         f"- Runs: {', '.join(r['name'] for r in runs)}.",
         f"- Each run lasts {g(summary.get('duration_s'))} s; indicators over t >= {g(summary.get('transient_s'))} s "
         f"(the transient). Spectrum: {summary.get('window', 'window not given')}.",
         f"- Ranks: {summary.get('ranks', '-')}, jobs: {summary.get('jobs', '-')}; "
         f"wall time of the whole sweep {g(summary.get('wall_s'))} s.", "",
         "| run | method | modes | basis s | wall s (all speeds) | wall s per speed (median) | per speed vs full | "
         "completed | diverged | failed |", "|---|---|---|---|---|---|---|---|---|---|"]
    ref_cost = run_info(summary, ref["name"]).get("wall_s_per_speed_median") if ref else None
    for r in runs:
        s = run_info(summary, r["name"])
        cost = s.get("wall_s_per_speed_median")
        ok = all(isinstance(x, numbers.Real) and x > 0 for x in (cost, ref_cost))
        ratio = f"{cost / ref_cost:.3g}x" if ok else "-"
        L.append(f"| {r['name']} | {s.get('method', r['method'])} | {s.get('modes', r['modes'])} | "
                 f"{g(s.get('basis_s'), 3)} | {g(s.get('wall_s_total'), 3)} | {g(cost, 3)} | {ratio} | "
                 f"{count(r, 'completed')} | {count(r, 'diverged')} | {count(r, 'failed')} |")
    return L + [""]


def lines_section(lines, lines_in, lo, hi):
    L = ["## Predicted interaction speeds", ""]
    if not lines:
        return L + ["`interaction_lines.csv` has no line: no interaction is predicted for this case.", ""]
    if not lines_in:
        near = nearest_line(lines, lo, hi)
        return L + [f"None of the {len(lines)} predicted interaction speeds falls within the swept range "
                    f"{span(lo, hi)} rad/s (the nearest: family {near['family']}, n = {near['nodal_diameter']}, "
                    f"{g(near['speed_rad_s'])} rad/s).", ""]
    L += [f"{len(lines_in)} of the {len(lines)} predicted speeds Omega = 2 pi (f_b + f_c) / n fall within the "
          "swept range (vertical lines of the map, labelled n and family F):", "",
          "| family | n | f_b [Hz] | casing mode | f_c [Hz] | Omega [rad/s] |", "|---|---|---|---|---|---|"]
    for ln in lines_in:
        L.append(f"| {ln['family']} | {ln['nodal_diameter']} | {g(ln['blade_hz'])} | {ln['casing_mode']} | "
                 f"{g(ln['casing_hz'])} | {g(ln['speed_rad_s'])} |")
    return L + [""]


def peaks_section(runs, lines):
    L = ["## Response peaks", "",
         "Local maxima of max tip radial against Omega, per run, over its completed speeds "
         f"(`scipy.signal.find_peaks`, prominence at least {PEAK_PROMINENCE:g} of the run's largest value: "
         f"{PEAK_WHY}). Diverged speeds are left out: a blow-up cut short would set the scale. "
         "A maximum at either end of the sweep is not a local maximum and is not listed. Distance: peak speed "
         "minus the nearest predicted interaction speed (over all lines, in range or not).", "",
         "| run | Omega [rad/s] | max tip radial [m] | prominence [m] | nearest interaction (family, n, casing mode) "
         "| its Omega [rad/s] | distance [rad/s] |", "|---|---|---|---|---|---|---|"]
    for run in runs:
        peaks, why = response_peaks(run)
        if not peaks:
            L.append(f"| {run['name']} | {why} | | | | | |")
        for i, prom in peaks:
            s = run["speed"][i]
            ln = nearest_line(lines, s, s)
            near = (f"{ln['family']}, {ln['nodal_diameter']}, {ln['casing_mode']} | {g(ln['speed_rad_s'])} | "
                    f"{s - ln['speed_rad_s']:+.3g}") if ln else "- | - | -"
            L.append(f"| {run['name']} | {g(s)} | {g(run['max_tip_radial_m'][i], 3)} | {g(prom, 3)} | {near} |")
    return L + [""]


def disagree_section(ref, runs, disagree):
    L = ["## Reduced runs against the full run", ""]
    if ref is None:
        return L + ["The sweep has no full run (method `full`): the reduced runs are not compared.", ""]
    reduced = [r for r in runs if r is not ref]
    if not reduced:
        return L + ["The sweep has the full run only: nothing to compare.", ""]
    L += [f"A reduced run disagrees with the full run at a speed when the statuses differ, or, both completed, "
          f"when max tip radial differs by more than {DISAGREE_REL:g} of the full value ({DISAGREE_WHY}). A "
          "diverged run's maximum is that of a blow-up cut short, so two diverged runs are not compared by "
          "value. Shaded on the map.", ""]
    for r in reduced:
        found = disagree.get(r["name"], [])
        common = int(np.sum(np.isin(r["speed"], ref["speed"])))
        done = ref["speed"][ref["status"] == "completed"]
        both = int(np.sum(np.isin(r["speed"][r["status"] == "completed"], done)))
        L.append(f"- {r['name']}: {common} speed{'s' * (common != 1)} in common with the full run, "
                 f"both completed at {both}; disagrees at {len(found)}.")
    rows = [(s, r, i, j, why) for r in reduced for s, i, j, why in disagree.get(r["name"], [])]
    if not rows:
        return L + [""]
    L += ["", "| Omega [rad/s] | run | full status | run status | full max tip radial [m] | run max tip radial [m] "
          "| reason |", "|---|---|---|---|---|---|---|"]
    for s, r, i, j, why in sorted(rows, key=lambda x: (x[0], runs.index(x[1]))):
        L.append(f"| {g(s)} | {r['name']} | {ref['status'][i]} | {r['status'][j]} | "
                 f"{g(ref['max_tip_radial_m'][i], 3)} | {g(r['max_tip_radial_m'][j], 3)} | {why} |")
    return L + [""]


def speed_list(speeds, total, shown=12):
    """' at a, b, ... rad/s', at most `shown` of them."""
    if len(speeds) == 0:
        return ""
    if len(speeds) == total and total > 1:
        return " (every speed)"
    more = f" and {len(speeds) - shown} more" if len(speeds) > shown else ""
    return f" at {', '.join(g(s) for s in speeds[:shown])}{more} rad/s"


def status_section(runs):
    L = ["## Diverged and failed speeds", "",
         "Diverged: the run's blow-up monitor stopped it, and its indicators are over the rows up to the stop. "
         "Failed: the run raised an exception and has no indicators.", ""]
    for r in runs:
        parts = [f"{count(r, st)} {st}" + speed_list(r["speed"][r["status"] == st], len(r["speed"]))
                 for st in ("diverged", "failed")]
        L.append(f"- {r['name']}: " + "; ".join(parts) + ".")
    return L + [""]


def write_report(out, summary, runs, ref, lines, lines_in, disagree, speeds):
    L = ["# Rotation-speed sweep: interaction map", "",
         "Generated by reports/make_sweep_report.py from `sweep.csv`, `interaction_lines.csv` and "
         "`sweep_summary.json` beside it. The bladed disk rotating inside its casing is run at each speed, the "
         "full model beside the reduced ones, and each run is summarised by indicators over the rows after the "
         "transient.", ""]
    L += setup_lines(summary, runs, speeds, ref)
    L += ["## Interaction map", "", "![interaction map](sweep_map.png)", "",
          "Indicators against the rotation speed, one curve per run (full: black, filled; reduced: coloured, "
          "hollow). Red x: diverged; red marker at the bottom: failed. Dashed or dotted vertical lines: predicted "
          "interaction speeds within the range. Shading: a reduced run disagrees with the full run there.", ""]
    L += lines_section(lines, lines_in, min(speeds), max(speeds))
    L += peaks_section(runs, lines)
    L += disagree_section(ref, runs, disagree)
    L += status_section(runs)
    L += ["## Campbell diagram of the response", "", "![Campbell diagram](sweep_campbell.png)", "",
          "The three largest peaks of each speed's spectrum (blade 1's radial tip displacement, rotating frame), "
          "marker area proportional to the amplitude, over the model's lines in the rotating frame: the blade "
          "families (horizontal) and each casing mode at |f_c - n Omega/2pi| and f_c + n Omega/2pi. A response "
          "that follows a casing line rather than a blade family is the casing seen from the blades. The red circles "
          "sit where |f_c - n Omega/2pi| crosses f_b: the predicted interaction speeds of the map.", ""]
    with open(f"{out}/.sweep_report.md.tmp", "w") as f:
        f.write("\n".join(L))
    os.replace(f"{out}/.sweep_report.md.tmp", f"{out}/sweep_report.md")


def main(argv):
    if len(argv) != 2:
        raise InputError("usage: make_sweep_report.py DIR")
    out = argv[1]
    if not os.path.isdir(out):
        raise InputError(f"{out}: not a directory")
    runs, lines, summary = read_sweep(out), read_lines(out), read_summary(out)
    ref = next((r for r in runs if r["method"] == "full"), None)
    speeds = np.unique(np.concatenate([r["speed"] for r in runs]))
    lines_in = sorted((ln for ln in lines if speeds[0] <= ln["speed_rad_s"] <= speeds[-1]),
                      key=lambda ln: (ln["speed_rad_s"], ln["family"]))
    disagree = {r["name"]: disagreements(ref, r) for r in runs if ref is not None and r is not ref}
    disagree = {k: v for k, v in disagree.items() if v}
    xlim = x_limits(speeds)
    plot_map(out, runs, lines_in, disagree, xlim)
    plot_campbell(out, runs, lines, lines_in, xlim)
    write_report(out, summary, runs, ref, lines, lines_in, disagree, speeds)
    print(f"wrote {out}/sweep_report.md, sweep_map.png and sweep_campbell.png")


if __name__ == "__main__":
    try:
        main(sys.argv)
    except (InputError, OSError) as e:  # OSError here: DIR not writable, disk full
        print(f"make_sweep_report.py: error: {e}", file=sys.stderr)
        sys.exit(1)
