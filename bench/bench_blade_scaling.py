#!/usr/bin/python3
"""Scaling of the reductions with the size of the model (issue 11): the
project's gmsh blade (data/cases/blade3d.json) at several element sizes, each
reduced by Craig-Bampton, Craig-Chang-Martinez and MacNeal with 50 modes, and
its 50 lowest modes; the CLI's own times (medians of REPEATS runs), the peak
memory, and the observed exponent p of time ~ dofs^p (least squares on the
logarithms).

Usage: bench_blade_scaling.py RSI SOURCE_DIR OUT_JSON [REPEATS] [SIZES...]
Default sizes: 10 5 3.333 2.5 2 (4,101 to 87,282 dofs).
"""
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"failed ({p.returncode}): {' '.join(cmd)}\n{p.stdout}\n{p.stderr}")
    return p.stdout


def number(pattern, text):
    m = re.search(pattern, text)
    if not m:
        sys.exit(f"no '{pattern}' in:\n{text}")
    return float(m.group(1))


def slope(xs, ys):
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)


def main():
    rsi, src, out_json = sys.argv[1:4]
    repeats = int(sys.argv[4]) if len(sys.argv) > 4 else 3
    sizes = [float(s) for s in sys.argv[5:]] or [10, 5, 3.333, 2.5, 2]
    base = json.load(open(f"{src}/data/cases/blade3d.json"))
    base.pop("modal_campaign", None)
    work = tempfile.mkdtemp(prefix="rsi-bench-scaling-")
    cache = f"{work}/cache"
    rows = []
    try:
        for h in sizes:
            case = json.loads(json.dumps(base))
            case["component"]["source"]["gmsh_blade"]["element_size"] = h
            path = f"{work}/blade-{h}.json"
            json.dump(case, open(path, "w"))
            run([rsi, "export", path, "--ccx-cache", cache, "--out", f"{work}/export"])  # gmsh + ccx once
            row = {"element_size": h}
            for name, args in [("modes-50", ["modes", "--count", "50"]),
                               ("cb-50", ["reduce", "--method", "cb", "--modes", "50"]),
                               ("ccm-50", ["reduce", "--method", "ccm", "--modes", "50"]),
                               ("macneal-50", ["reduce", "--method", "macneal", "--modes", "50"])]:
                samples = []
                for _ in range(repeats):
                    text = run([rsi, args[0], path, *args[1:], "--ccx-cache", cache,
                                "--out", f"{work}/out"])
                    solve = number(r"modes ([0-9.]+) s" if args[0] == "modes"
                                   else r"built in ([0-9.]+) s", text)
                    samples.append((solve, number(r"peak memory ([0-9.]+) MB", text)))
                    row["dofs"] = int(number(r"(\d+) dofs", text) if args[0] == "modes"
                                      else number(r"(\d+) -> \d+ dofs", text))
                row[name] = {"seconds": statistics.median(s for s, _ in samples),
                             "peak_MB": statistics.median(m for _, m in samples)}
            rows.append(row)
            print(f"h {h:6.3f}: {row['dofs']:7d} dofs; " + ", ".join(
                f"{k} {v['seconds']:.2f} s ({v['peak_MB']:.0f} MB)" for k, v in row.items()
                if isinstance(v, dict)), flush=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    result = {"repeats": repeats, "rows": rows, "exponents": {}}
    for name in ["modes-50", "cb-50", "ccm-50", "macneal-50"]:
        p = slope([r["dofs"] for r in rows], [r[name]["seconds"] for r in rows])
        result["exponents"][name] = p
        print(f"{name}: time ~ dofs^{p:.2f}")
    json.dump(result, open(out_json, "w"), indent=1)
    print(f"wrote {out_json}")


if __name__ == "__main__":
    main()
