#!/usr/bin/env bash
# Issue 11, modal convergence campaign without contact, from the CLI: `rsi
# modal-campaign` on the gmsh blade (data/cases/blade3d.json) writes its
# tables and report; the tables satisfy Rayleigh-Ritz (CB, CCM: every reduced
# frequency at or above the full one, and not rising as modes are added,
# within the per-frequency round-off tolerance the command writes) and
# MacNeal's identity (its finite frequencies are the kept free-interface
# ones, within the same tolerance). Skipped (exit 77) without gmsh or ccx.
# Usage: modal_campaign.sh RSI SOURCE_DIR CCX_CACHE
set -u
rsi=$1
src=$2
cache=$3
. "$(dirname "$0")/skip_without_gmsh_ccx.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$rsi" modal-campaign "$src/data/cases/blade3d.json" --ccx-cache "$cache" --out "$work/mc" || exit 1
/usr/bin/python3 - "$work/mc" <<'PY'
import csv, os, sys
out = sys.argv[1]
failures = 0
def check(ok, what):
    global failures
    print(("ok   " if ok else "FAIL ") + what)
    failures += not ok
for f in ["modal_convergence.csv", "modal_errors.csv", "modal_summary.json", "modal_report.md",
          "modal_convergence.png", "modal_errors.png"]:
    check(os.path.getsize(f"{out}/{f}") > 0, f"{f} written")
rows = list(csv.DictReader(open(f"{out}/modal_errors.csv")))
check(len(rows) > 0, f"{len(rows)} compared frequencies")
for m in ["cb", "ccm"]:
    es = [r for r in rows if r["method"] == m]
    worst = min(float(r["rel_error"]) + float(r["tolerance"]) for r in es)
    check(worst >= 0, f"{m}: every reduced frequency >= the full one - tolerance (Rayleigh-Ritz; "
                      f"smallest margin {worst:.2e})")
    by = {}
    for r in es:
        by.setdefault(int(r["modes"]), {})[int(r["index"])] = r
    counts = sorted(by)
    rises = [(a, b, i) for a, b in zip(counts, counts[1:]) for i in by[b] if i in by[a]
             and float(by[b][i]["rel_error"]) - float(by[a][i]["rel_error"])
             > float(by[a][i]["tolerance"]) + float(by[b][i]["tolerance"])]
    check(not rises, f"{m}: no frequency rises as modes are added {counts} (nested bases)")
es = [r for r in rows if r["method"] == "macneal"]
worst = max(abs(float(r["rel_error"])) / float(r["tolerance"]) for r in es)
check(worst <= 1, f"macneal: finite frequencies = kept free-interface ones (largest |error| / "
                  f"tolerance {worst:.2e})")
print(f"{failures} failed")
sys.exit(failures > 0)
PY
