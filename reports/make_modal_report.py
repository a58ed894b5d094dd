#!/usr/bin/python3
"""The modal convergence report of `rsi modal-campaign` (issue 11).

Reads DIR/modal_convergence.csv, modal_errors.csv and modal_summary.json and
writes DIR/modal_report.md with DIR/modal_convergence.png (largest relative
frequency error against the mode count, per method) and
DIR/modal_errors.png (relative error of each of the lowest frequencies).

Usage: make_modal_report.py DIR
"""
import csv
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

NAMES = {"cb": "Craig-Bampton", "ccm": "Craig-Chang-Martinez", "macneal": "MacNeal"}


def main(out):
    summary = json.load(open(f"{out}/modal_summary.json"))
    rows = list(csv.DictReader(open(f"{out}/modal_convergence.csv")))
    errors = list(csv.DictReader(open(f"{out}/modal_errors.csv")))
    methods = list(dict.fromkeys(r["method"] for r in rows))
    count = summary["frequencies"]

    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for m in methods:
        rs = [r for r in rows if r["method"] == m]
        # A relative error of exactly 0 (or below round-off) is drawn at 1e-16.
        ax.semilogy([int(r["modes"]) for r in rs],
                    [max(abs(float(r["max_rel_error"])), 1e-16) for r in rs], "o-",
                    label=NAMES.get(m, m))
    ax.set_xlabel("modes kept (fixed-interface for CB, free for CCM and MacNeal)")
    ax.set_ylabel(f"largest relative error, lowest {count} frequencies")
    ax.set_title(f"{summary['component']}: {summary['full_dofs']} dofs, "
                 f"{summary['boundary_dofs']} boundary dofs")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(f"{out}/modal_convergence.png", dpi=120)

    fig, axes = plt.subplots(1, len(methods), figsize=(4.2 * len(methods), 3.8), squeeze=False)
    for ax, m in zip(axes[0], methods):
        for n in dict.fromkeys(int(e["modes"]) for e in errors if e["method"] == m):
            es = [e for e in errors if e["method"] == m and int(e["modes"]) == n]
            ax.semilogy([int(e["index"]) for e in es],
                        [max(abs(float(e["rel_error"])), 1e-16) for e in es], ".-",
                        label=f"{n} modes")
        ax.set_title(NAMES.get(m, m))
        ax.set_xlabel("mode index")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    axes[0][0].set_ylabel("|f_reduced - f_full| / f_full")
    fig.tight_layout()
    fig.savefig(f"{out}/modal_errors.png", dpi=120)

    lines = [f"# Modal convergence of the reductions: {summary['component']}", "",
             f"Case `{summary['case']}`: {summary['full_dofs']} dofs, "
             f"{summary['boundary_dofs']} boundary dofs kept physical, units "
             f"{summary['units']}. No contact: the reduced frequencies (boundary free) against "
             f"the full model's lowest {count} ({summary['full_modes_seconds']:.2f} s for them; "
             f"peak memory {summary['peak_memory_bytes'] / 2**20:.0f} MB for the whole command).",
             "",
             "| method | modes | reduced dofs | compared | largest rel. error | smallest rel. error "
             "| critical Δt | build [s] |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {NAMES.get(r['method'], r['method'])} | {r['modes']} | {r['reduced_dofs']} "
                     f"| {r['compared']} | {float(r['max_rel_error']):.3e} "
                     f"| {float(r['min_rel_error']):.3e} | {float(r['critical_dt']):.4e} "
                     f"| {float(r['build_s']):.3f} |")
    lines += ["", "![largest error against modes](modal_convergence.png)", "",
              "![error per mode](modal_errors.png)", ""]
    # What the rows show, from the numbers above. A reduced frequency may fall
    # below the full one, or a larger basis do worse, only by the solvers'
    # round-off: the per-frequency tolerance of modal_errors.csv (the dense
    # reduced solve's n_r eps lambda_max / lambda_i and the full mode's residual).
    notes = []
    for m in methods:
        rs = [r for r in rows if r["method"] == m]
        worst = [float(r["max_rel_error"]) for r in rs]
        es = [e for e in errors if e["method"] == m]
        below = [(float(e["rel_error"]), float(e["tolerance"])) for e in es]
        violations = [e for e in es if float(e["rel_error"]) < -float(e["tolerance"])]
        by_count = {}
        for e in es:
            by_count.setdefault(int(e["modes"]), {})[int(e["index"])] = e
        counts = sorted(by_count)
        rises = []
        for a, b in zip(counts, counts[1:]):
            for i, eb in by_count[b].items():
                ea = by_count[a].get(i)
                if ea is not None and (float(eb["rel_error"]) - float(ea["rel_error"])
                                       > float(ea["tolerance"]) + float(eb["tolerance"])):
                    rises.append((a, b, i))
        smallest = min(x for x, _ in below)
        if m in ("cb", "ccm"):
            notes.append(
                f"- {NAMES[m]}: the reduced frequencies "
                f"{'bound the full ones from above' if not violations else 'do NOT bound the full ones'}"
                f" within the solvers' round-off (Rayleigh-Ritz; smallest relative error "
                f"{smallest:.2e}, {len(violations)} of {len(es)} below their tolerance); each "
                f"frequency {'decreases' if not rises else 'does NOT always decrease'} as modes are "
                f"added ({len(rises)} rises beyond round-off); largest error {worst[0]:.2e} with "
                f"{counts[0]} modes, {worst[-1]:.2e} with {counts[-1]}.")
        else:
            notes.append(f"- MacNeal: with the boundary massless and free, the finite reduced "
                         f"frequencies are the kept free-interface frequencies themselves "
                         f"(largest |error| {max(abs(x) for x, _ in below):.2e}, "
                         f"{len([x for x, t in below if abs(x) > t])} of {len(below)} beyond "
                         f"their tolerance); only min(ψ, {count}) are compared, and the critical "
                         f"step is 2/ω_ψ.")
    lines += ["## What the rows show", ""] + notes + [""]
    open(f"{out}/modal_report.md", "w").write("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1])
