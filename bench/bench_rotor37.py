#!/usr/bin/python3
"""Rotor 37 benchmark (issue 11): rsi's import, 50 modes and 50-mode
reductions of the NASA Rotor 37 blade (61,098 dofs), each timed by the CLI
itself with its peak memory, against CalculiX's own eigensolver for the same
50 modes, measured side by side in this one run.

Usage: bench_rotor37.py RSI SOURCE_DIR OUT_JSON [REPEATS]

Each rsi command runs REPEATS times (default 3; medians reported) in its own
process, after one run that fills the ccx cache (the matrices: timed as
"ccx matrices"). ccx's 50-mode run (about a minute) runs once.
"""
import glob
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time


def run(cmd, cwd=None):
    start = time.monotonic()
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    wall = time.monotonic() - start
    if p.returncode != 0:
        sys.exit(f"failed ({p.returncode}): {' '.join(cmd)}\n{p.stdout}\n{p.stderr}")
    return wall, p.stdout


def number(pattern, text):
    m = re.search(pattern, text)
    if not m:
        sys.exit(f"no '{pattern}' in:\n{text}")
    return float(m.group(1))


def main():
    rsi, src, out_json = sys.argv[1:4]
    repeats = int(sys.argv[4]) if len(sys.argv) > 4 else 3
    case = f"{src}/data/cases/rotor37.json"
    if not os.path.exists(f"{src}/../shared/external/rotor37/blade.inp"):
        print("skipped: ../shared/external/rotor37 is absent")
        return
    work = tempfile.mkdtemp(prefix="rsi-bench-rotor37-")
    cache = f"{work}/cache"
    result = {"repeats": repeats, "machine": os.uname().nodename, "nproc": os.cpu_count()}
    try:
        wall, _ = run([rsi, "export", case, "--ccx-cache", cache, "--out", f"{work}/export"])
        entry = glob.glob(f"{cache}/*-matrices")[0]
        log = open(f"{entry}/ccx.log").read()
        # ccx's own run of the matrices, timed again alone (the export above includes it).
        deck = open(f"{entry}/job.inp").read()
        os.makedirs(f"{work}/ccx-matrices")
        open(f"{work}/ccx-matrices/job.inp", "w").write(deck)
        result["ccx_matrices_s"], _ = run(["ccx", "-i", "job"], cwd=f"{work}/ccx-matrices")

        stages = {"modes-50": ["modes", "--count", "50"]}
        for method, modes in [("guyan", 0), ("cb", 50), ("ccm", 50), ("macneal", 50)]:
            stages[f"{method}-{modes}"] = ["reduce", "--method", method, "--modes", str(modes)]
        for name, args in stages.items():
            samples = []
            for r in range(repeats):
                wall, text = run([rsi, args[0], case, *args[1:], "--ccx-cache", cache,
                                  "--out", f"{work}/{name}"])
                if args[0] == "modes":
                    s = {"wall_s": wall, "load_s": number(r"load ([0-9.]+) s", text),
                         "solve_s": number(r"modes ([0-9.]+) s", text),
                         "peak_MB": number(r"peak memory ([0-9.]+) MB", text)}
                else:
                    s = {"wall_s": wall, "load_s": number(r"loaded in ([0-9.]+) s", text),
                         "solve_s": number(r"built in ([0-9.]+) s", text),
                         "peak_MB": number(r"peak memory ([0-9.]+) MB", text),
                         "critical_dt": number(r"critical step ([0-9.e+-]+) s", text)}
                samples.append(s)
            result[name] = {k: statistics.median(x[k] for x in samples) for k in samples[0]}
            result[name]["samples"] = samples
            print(f"{name:12s} " + ", ".join(f"{k} {v:.4g}" for k, v in result[name].items()
                                               if k != "samples"), flush=True)

        # ccx's own eigensolver, 50 modes, same model (the deck's first step asks 20).
        lanczos = deck.split("*STEP")[0] + "*STEP, PERTURBATION\n*FREQUENCY\n50\n*END STEP\n"
        os.makedirs(f"{work}/ccx-modes")
        open(f"{work}/ccx-modes/job.inp", "w").write(lanczos)
        start_cpu = os.times()
        result["ccx_modes_50_s"], _ = run(["ccx", "-i", "job"], cwd=f"{work}/ccx-modes")
        end_cpu = os.times()
        result["ccx_modes_50_cpu_s"] = ((end_cpu.children_user - start_cpu.children_user)
                                        + (end_cpu.children_system - start_cpu.children_system))
        result["speedup_modes_vs_ccx"] = result["ccx_modes_50_s"] / result["modes-50"]["solve_s"]
        result["speedup_modes_wall_vs_ccx"] = result["ccx_modes_50_s"] / result["modes-50"]["wall_s"]
        print(f"ccx 50 modes {result['ccx_modes_50_s']:.1f} s wall "
              f"({result['ccx_modes_50_cpu_s']:.1f} s CPU); rsi's 50-mode solve is "
              f"{result['speedup_modes_vs_ccx']:.1f}x faster (whole rsi modes command incl. import: "
              f"{result['speedup_modes_wall_vs_ccx']:.1f}x)")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    json.dump(result, open(out_json, "w"), indent=1)
    print(f"wrote {out_json}")


if __name__ == "__main__":
    main()
