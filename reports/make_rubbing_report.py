#!/usr/bin/python3
"""Report of a component case's rubbing campaign (issue 12 item 6): figures
and report.md from the outputs of `rsi campaign CASE --out DIR` on a
component case, which runs this script at its end.

Usage: make_rubbing_report.py DIR
Reads DIR/convergence.csv, DIR/rubbing.json and
DIR/runs/<name>/{history.csv,summary.json}; writes DIR/report.md and
DIR/*.png. Every number in the text is read from those files.

Errors: against the full-order run when the campaign has one (over its
window, the norms of convergence.csv); otherwise against the reduced run
with the most coordinates (CCM first, then CB, among equals) over the whole
length, and the table says so (a converged reduced run is not the full
model).
Spectrum: |FFT| of the response over the last 5 revolutions (or the last
half of a shorter run), mean removed, Hann window, against the first kept
free-interface mode and the multiples of 2 Omega (the oval gap's
fundamental).
"""
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.dont_write_bytecode = True  # no __pycache__ beside the scripts
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from nodal_diameter_figure import draw_nodal_diameter_map  # noqa: E402

out = sys.argv[1]
setup = json.load(open(f"{out}/rubbing.json"))
rows = list(csv.DictReader(open(f"{out}/convergence.csv")))
for r in rows:
    r["modes"] = int(r["modes"])
    r["name"] = "full" if r["method"] == "full" else f"{r['method']}-{r['modes']}"
    for k, v in list(r.items()):
        if k not in ("method", "name"):
            try:
                r[k] = float(v)
            except ValueError:
                pass
# A run refused before its first step (a reduction refused: too many modes)
# left no history and no summary; rsi's message named why. Listed, not drawn.
refused = [r["name"] for r in rows if not os.path.exists(f"{out}/runs/{r['name']}/summary.json")]
rows = [r for r in rows if r["name"] not in refused]
for r in rows:
    r["summary"] = json.load(open(f"{out}/runs/{r['name']}/summary.json"))

omega = abs(setup["rotation_speed"])  # the sign is the direction; the period and 2 Omega need |Omega|
period = 2 * math.pi / omega
response = setup["response"]
nc = len(setup["contact_nodes"])


def history(name):
    data = np.genfromtxt(f"{out}/runs/{name}/history.csv", delimiter=",", names=True)
    return data


histories = {r["name"]: history(r["name"]) for r in rows}
full = next((r for r in rows if r["method"] == "full"), None)
reduced = [r for r in rows if r["method"] != "full"]
ref_name = None
if full is None and reduced:
    # The most coordinates; among equals CCM, then CB: on the Rotor 37 window
    # against the full model (reports/rubbing-rotor37/window) CCM-100 came
    # closest (e2 1.3e-4), CB-100 next (3.5e-4), MacNeal-100 last (1.0e-3).
    ref_name = max(reduced, key=lambda r: (r["coordinates"], r["method"] == "ccm",
                                           r["method"] == "cb"))["name"]


def norms(name, ref):
    a, b = histories[name], histories[ref]
    n = min(len(a), len(b))
    x, xr = a[response][:n], b[response][:n]
    lam = np.column_stack([a[f"lambda_{k}"][:n] for k in range(1, nc + 1)])
    lref = np.column_stack([b[f"lambda_{k}"][:n] for k in range(1, nc + 1)])
    return (np.linalg.norm(x - xr) / np.linalg.norm(xr), np.max(np.abs(x - xr)) / np.max(np.abs(xr)),
            np.linalg.norm(lam - lref) / np.linalg.norm(lref),
            np.max(np.abs(lam - lref)) / np.max(np.abs(lref)))


for r in rows:
    if full is not None:
        r["e"] = (r["e2_response"], r["einf_response"], r["e2_lambda"], r["einf_lambda"])
    elif ref_name:
        r["e"] = norms(r["name"], ref_name)
    else:
        r["e"] = (math.nan,) * 4
against = (f"the full-order run over its {setup['full_revolutions']:g} revolutions"
           if full is not None else f"{ref_name} (the largest reduced model), over "
           f"{setup['revolutions']:g} revolutions: a converged reduced run, not the full model")

methods = sorted({r["method"] for r in reduced})
colors = {"full": "k", "macneal": "C0", "cb": "C1", "ccm": "C2", "guyan": "C3"}


def best(method):
    runs = [r for r in reduced if r["method"] == method]
    return max(runs, key=lambda r: r["modes"]) if runs else None


shown = ([full] if full else []) + [best(m) for m in methods]
# Response, whole length.
fig, ax = plt.subplots(figsize=(9, 3.5))
for r in shown:
    h = histories[r["name"]]
    ax.plot(h["t"] / period, h[response], color=colors.get(r["method"], None), lw=0.7,
            label=r["name"])
ax.set_xlabel("revolutions")
ax.set_ylabel(f"{response} [{setup['units'].split(',')[1].strip()}]")
ax.legend(fontsize=8)
ax.set_title("Response, whole run")
fig.tight_layout()
fig.savefig(f"{out}/response.png", dpi=120)
plt.close(fig)
# Response, last 5 revolutions.
fig, ax = plt.subplots(figsize=(9, 3.5))
for r in shown:
    h = histories[r["name"]]
    rev = h["t"] / period
    keep = rev >= rev[-1] - 5
    ax.plot(rev[keep], h[response][keep], color=colors.get(r["method"], None), lw=0.8,
            label=r["name"])
ax.set_xlabel("revolutions")
ax.set_ylabel(response)
ax.legend(fontsize=8)
ax.set_title("Response, last 5 revolutions")
fig.tight_layout()
fig.savefig(f"{out}/response_last.png", dpi=120)
plt.close(fig)
# Spectrum.
first_modes = [r["first_mode_hz"] for r in reduced if r.get("first_mode_hz", 0) > 0]
first_mode = min(first_modes) if first_modes else None
fig, ax = plt.subplots(figsize=(9, 3.5))
peaks = {}
for r in shown:
    h = histories[r["name"]]
    rev = h["t"] / period
    span = min(5.0, rev[-1] / 2)
    keep = rev >= rev[-1] - span
    x = h[response][keep] - np.mean(h[response][keep])
    dt = h["t"][1] - h["t"][0]
    spec = np.abs(np.fft.rfft(x * np.hanning(len(x))))
    f = np.fft.rfftfreq(len(x), dt)
    ax.semilogy(f, spec + 1e-300, color=colors.get(r["method"], None), lw=0.8, label=r["name"])
    peaks[r["name"]] = (f[1 + np.argmax(spec[1:])], span, f[1] - f[0])
for k in range(1, 5):
    ax.axvline(k * 2 * omega / (2 * math.pi), color="gray", ls=":", lw=0.8)
if first_mode:
    ax.axvline(first_mode, color="r", ls="--", lw=0.8, label=f"first mode {first_mode:.1f} Hz")
ax.set_xlim(0, 6 * 2 * omega / (2 * math.pi))
ax.set_xlabel("frequency [Hz] (dotted: multiples of 2 Omega)")
ax.set_ylabel("|FFT|")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(f"{out}/spectrum.png", dpi=120)
plt.close(fig)
# Contact forces and energy.
fig, axes = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
for r in shown:
    h = histories[r["name"]]
    total = sum(h[f"lambda_{k}"] for k in range(1, nc + 1))
    axes[0].plot(h["t"] / period, total, color=colors.get(r["method"], None), lw=0.7,
                 label=r["name"])
    axes[1].plot(h["t"] / period, h["contact_work"], color=colors.get(r["method"], None), lw=0.8,
                 label=f"{r['name']} W_contact")
    if np.any(h["damping_work"] > 0):
        axes[1].plot(h["t"] / period, h["damping_work"], color=colors.get(r["method"], None),
                     lw=0.8, ls="--", label=f"{r['name']} W_damp")
axes[0].set_ylabel("sum of lambda_n [N]")
axes[1].set_ylabel("work [N mm]" if "mm" in setup["units"] else "work")
axes[1].set_xlabel("revolutions")
axes[0].legend(fontsize=8)
axes[1].legend(fontsize=7)
fig.tight_layout()
fig.savefig(f"{out}/contact_energy.png", dpi=120)
plt.close(fig)
# Error against cost.
fig, ax = plt.subplots(figsize=(6, 4))
for m in methods:
    rs = sorted([r for r in reduced if r["method"] == m and r["name"] != ref_name],
                key=lambda r: r["modes"])
    ax.loglog([r["integration_s"] for r in rs], [r["e"][0] for r in rs], "o-",
              color=colors.get(m), label=m)
    for r in rs:
        ax.annotate(str(r["modes"]), (r["integration_s"], r["e"][0]), fontsize=7)
ax.set_xlabel("integration wall time [s]")
ax.set_ylabel("e2 of the response")
ax.legend()
ax.set_title("accuracy against cost")
fig.tight_layout()
fig.savefig(f"{out}/error_vs_cost.png", dpi=120)
plt.close(fig)

flexible = setup.get("gap") == "flexible"
if flexible:
    # The flexible casing (issue 27): every tip's gap against the reference,
    # the tip the full run loads most (the analogue of the paper's blade-1
    # gap, Figs. 10-11), the least gap over all tips, and the gaps' e2
    # against cost.
    gap_keys = [f"gap_{k}" for k in range(1, nc + 1)]
    ref_h = histories[full["name"] if full else ref_name]
    loaded = 1 + int(np.argmax([np.max(ref_h[f"lambda_{k}"]) for k in range(1, nc + 1)]))
    fig, axes = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    for r in shown:
        h = histories[r["name"]]
        axes[0].plot(h["t"] * 1e3, h[f"gap_{loaded}"], color=colors.get(r["method"], None),
                     lw=0.8, label=r["name"])
        axes[1].plot(h["t"] * 1e3, np.min(np.column_stack([h[k] for k in gap_keys]), axis=1),
                     color=colors.get(r["method"], None), lw=0.8, label=r["name"])
    axes[0].set_ylabel(f"gap of tip {loaded} [mm]")
    axes[1].set_ylabel("least gap, all tips [mm]")
    axes[1].set_xlabel("t [ms]")
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(f"{out}/gap_histories.png", dpi=120)
    plt.close(fig)
    fig, ax = plt.subplots(figsize=(6, 4))
    for m in methods:
        rs = sorted([r for r in reduced if r["method"] == m], key=lambda r: r["modes"])
        ax.loglog([r["integration_s"] for r in rs], [r["e2_gap"] for r in rs], "o-",
                  color=colors.get(m), label=m)
        for r in rs:
            ax.annotate(str(r["modes"]), (r["integration_s"], r["e2_gap"]), fontsize=7)
    if full is not None:
        ax.axvline(full["integration_s"], color="k", ls=":", lw=0.8, label="full run")
    ax.set_xlabel("integration wall time [s]")
    ax.set_ylabel("e2 of the gaps (all tips)")
    ax.legend()
    ax.set_title("accuracy against cost (gaps)")
    fig.tight_layout()
    fig.savefig(f"{out}/gap_error_vs_cost.png", dpi=120)
    plt.close(fig)
    # The nodal-diameter map (the paper's Fig. 3 in 3D) and the interaction
    # lines, when the campaign wrote them (a bladed-disk rotor).
    nd_rows = (list(csv.DictReader(open(f"{out}/nodal_diameters.csv")))
               if os.path.exists(f"{out}/nodal_diameters.csv") else [])
    interaction = (list(csv.DictReader(open(f"{out}/interaction_lines.csv")))
                   if os.path.exists(f"{out}/interaction_lines.csv") else [])
    if nd_rows:
        draw_nodal_diameter_map(nd_rows, f"{out}/nodal_diameter_map.png")
    casing_text = (f"Flexible casing: the gmsh ring of inner radius {setup['casing_inner_radius']:g} "
                   f"mm, {setup['casing_thickness']:g} mm thick, {setup['casing_width']:g} mm wide "
                   f"({setup['casing_dofs']:,} dofs), in its {setup['casing_modes']} lowest modes "
                   "plus a static correction in the reduced runs")
    if "casing_pressure" in setup:
        casing_text += (f", loaded by p0 cos({setup['casing_nodal_diameters']} theta), p0 = "
                        f"{setup['casing_pressure']:g} N/mm^2 over "
                        f"{setup['casing_load_duration']:g} s")
    casing_text += "; "
else:
    casing_text = f"Oval casing g_m = {setup['gap_value']:g}, w = {setup['gap_width']:g}; "

lines = [f"# Rubbing campaign: {setup['component']} ({setup['dofs']:,} dofs, {setup['mass']} mass)",
         "",
         f"Generated by `reports/make_rubbing_report.py` from `rsi campaign {setup['case']}`. "
         f"{casing_text}"
         f"mu = {setup['friction_coefficient']:g}; Omega = {setup['rotation_speed']:g} rad/s "
         f"(T = {period * 1e3:.4f} ms, 2 Omega = {2 * omega / (2 * math.pi):.1f} Hz), "
         f"tip sliding {setup.get('tip_sliding', 'with_rotation').replace('_', ' ')}; "
         f"{nc} contact nodes; modal damping ratio {setup['modal_ratio']:g} on reduced runs, "
         f"Rayleigh alpha {setup['rayleigh_alpha']:g}, beta {setup['rayleigh_beta']:g} on the full "
         f"run; {setup['steps_per_revolution']} samples a revolution; response {response}.",
         "",
         "Every run integrates at its own stable step: dt = T/(k N), k the smallest integer with "
         "dt <= 0.9 x its limit (the full model: 2/omega_max of (K, M); CB, CCM: of (K^, M^); "
         "MacNeal: its interior with the whole boundary held), sampled every k steps, so all rows "
         "fall at the same instants.",
         "",
         f"## Methods against cost (errors against {against})",
         "",
         "| run | coordinates | dt [s] | limit [s] | steps | basis [s] | integration [s] | us/step "
         "| e2 resp. | einf resp. | e2 lambda_n | einf lambda_n | transitions | stick | slip |",
         "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
for r in rows:
    e = r["e"]
    lines.append(
        f"| {r['name']} | {int(r['coordinates'])} | {r['dt']:.3e} | {r['step_limit']:.3e} "
        f"| {int(r['steps'])} | {r['basis_s']:.2f} | {r['integration_s']:.3f} "
        f"| {r['us_per_step']:.1f} | {e[0]:.3e} | {e[1]:.3e} | {e[2]:.3e} | {e[3]:.3e} "
        f"| {int(r['stick_slip_transitions'])} | {r['stick_fraction']:.4f} "
        f"| {r['slip_fraction']:.4f} |")
lines += ["",
          "stick, slip: fractions of (step, contact node) pairs in stick and in slip.",
          ""]
if refused:
    lines += [f"Refused before a step (no history; rsi's message says why): {', '.join(refused)}.", ""]
# MacNeal against the mass-carrying methods at equal accuracy.
lines += ["## MacNeal against CB and CCM at equal accuracy", ""]
mac = [r for r in reduced if r["method"] == "macneal" and r["name"] != ref_name]
for m in ("cb", "ccm"):
    for r in sorted([r for r in reduced if r["method"] == m and r["name"] != ref_name],
                    key=lambda r: r["modes"]):
        cheaper = [q for q in mac if q["e"][0] <= r["e"][0]]
        if not cheaper:
            lines.append(f"- {r['name']} (e2 {r['e'][0]:.2e}): no MacNeal run of the campaign "
                         "is as accurate.")
            continue
        q = min(cheaper, key=lambda q: q["integration_s"])
        lines.append(f"- {r['name']} (e2 {r['e'][0]:.2e}, {r['integration_s']:.3f} s): "
                     f"{q['name']} reaches e2 {q['e'][0]:.2e} in {q['integration_s']:.3f} s, "
                     f"{r['integration_s'] / q['integration_s']:.0f}x faster.")
if flexible:
    lines += ["", f"## Gaps (every tip, against {against})", "",
              "The response dof is one tip's displacement; against the flexible casing the "
              "gaps of every tip are the measure (the issue's e2 of the blade-tip gaps).", "",
              "| run | casing | e2 gaps | einf gaps | W_ext |", "|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['name']} | {r['casing_basis']} | {r['e2_gap']:.3e} "
                     f"| {r['einf_gap']:.3e} | {r['external_work']:.4e} |")
    lines += ["", "![gaps](gap_histories.png)", "", "![gaps against cost](gap_error_vs_cost.png)"]
    if nd_rows:
        lines += ["", "## Nodal diameters and interaction lines", "",
                  "The bladed disk's lowest modes with their nodal diameters (from its sectors' "
                  "images) and the casing's with their lobes (the harmonic of its radial "
                  "displacement): nodal_diameters.csv. A disk family of n nodal diameters at "
                  "f_b (rotating frame) and a casing mode of n lobes at f_c meet when the "
                  "disk's backward wave and the casing's forward wave travel together, at "
                  "Omega_int = 2 pi (f_b + f_c) / n (Legrand et al. 2009; "
                  "interaction_lines.csv).", "", "![nodal-diameter map](nodal_diameter_map.png)",
                  ""]
        if interaction:
            lowest = min(interaction, key=lambda r: float(r["speed_rad_s"]))
            lines += ["| family | disk diameters k | casing lobes n | f_b [Hz] | casing mode "
                      "| f_c [Hz] | Omega_int [rad/s] | Omega_int / Omega |",
                      "|---|---|---|---|---|---|---|---|"]
            for r in interaction:
                w = float(r["speed_rad_s"])
                lines.append(f"| {r['family']} | {r['nodal_diameter']} | {r['casing_lobes']} | "
                             f"{float(r['blade_hz']):.2f} | {r['casing_mode']} | "
                             f"{float(r['casing_hz']):.2f} | {w:.1f} | {w / omega:.2f} |")
            lines += ["", "A casing mode of n lobes meets the N tips as the disk's k = |n - m N| "
                      "<= N/2 diameters (k = n up to N/2; above, its alias: "
                      "sweep/interaction_lines.hpp); Omega_int = 2 pi (f_b(k) + f_c) / n.", "",
                      f"The lowest interaction speed is {float(lowest['speed_rad_s']):.1f} "
                      f"rad/s (family {lowest['family']}, k = {lowest['nodal_diameter']}, n = "
                      f"{lowest['casing_lobes']} lobes), "
                      f"{float(lowest['speed_rad_s']) / omega:.2f} times this case's "
                      f"{omega:g} rad/s."]
        else:
            lines += ["No disk family and casing mode share a nodal diameter in 1 .. N/2 among "
                      "the modes computed."]
lines += ["", "![accuracy against cost](error_vs_cost.png)", "",
          "## Response", "", "![response](response.png)", "",
          "![last 5 revolutions](response_last.png)", "",
          "## Spectrum", ""]
for name, (f, span, df) in peaks.items():
    lines.append(f"- {name}: highest peak at {f:.1f} Hz (last {span:g} revolutions, resolution "
                 f"{df:.1f} Hz)")
if first_mode:
    lines.append(f"- first kept free-interface mode: {first_mode:.2f} Hz; 2 Omega "
                 f"{2 * omega / (2 * math.pi):.1f} Hz")
lines += ["", "![spectrum](spectrum.png)", "",
          "## Contact forces and works", "", "![contact and energy](contact_energy.png)", "",
          "## Certificates", "",
          "| run | max penetration | max cone violation | max stick/slip residual | energy balance "
          "error / scale | status |",
          "|---|---|---|---|---|---|"]
for r in rows:
    s = r["summary"]
    scale = s["energy_scale"] if s["energy_scale"] > 0 else 1.0
    lines.append(f"| {r['name']} | {s['max_penetration']:.2e} | {s['max_cone_violation']:.2e} "
                 f"| {s['max_stick_slip_residual']:.2e} | {s['energy_balance_error'] / scale:.2e} "
                 f"| {s['status']} |")
open(f"{out}/report.md", "w").write("\n".join(lines) + "\n")
print(f"wrote {out}/report.md")
