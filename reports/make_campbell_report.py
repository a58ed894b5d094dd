#!/usr/bin/python3
"""Report of a rotating blade's Campbell diagram (`rsi modes CASE --speeds
FROM:TO:COUNT --out DIR`): campbell.png and campbell.md.

Usage: make_campbell_report.py DIR [TITLE]
Reads DIR/campbell.csv (speed_rad_s, mode, frequency_hz: the lowest
frequencies of K(Omega) at each speed, mode i the i-th lowest) and
DIR/crossings.csv (mode, engine_order, speed_rad_s, frequency_hz: where
EO Omega / 2 pi meets mode i); writes DIR/campbell.png and DIR/campbell.md,
each whole (a temporary file, then a rename). Every number in the text is
read from those files. Missing or malformed input: `make_campbell_report.py:
error: ...` on stderr, exit status 1.

The oval casing of the rubbing cases has two lobes: it forces at the even
engine orders (solid lines); the odd ones (dotted) are drawn for reading.
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

NAME = "make_campbell_report.py"


def fail(message):
    sys.stderr.write(f"{NAME}: error: {message}\n")
    sys.exit(1)


def read(path, columns):
    try:
        with open(path) as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        fail(f"cannot read {path}: {e.strerror}")
    if not rows or any(c not in rows[0] for c in columns):
        fail(f"{path}: expected the columns {', '.join(columns)}")
    try:
        return [{c: float(r[c]) for c in columns} for r in rows]
    except ValueError:
        fail(f"{path}: a value is not a number")


def write_whole(path, write):
    tmp = path + ".tmp"
    write(tmp)
    os.replace(tmp, path)


def main():
    if len(sys.argv) not in (2, 3):
        fail("usage: make_campbell_report.py DIR [TITLE]")
    out = sys.argv[1]
    title = sys.argv[2] if len(sys.argv) == 3 else "Campbell diagram"
    table = read(os.path.join(out, "campbell.csv"), ["speed_rad_s", "mode", "frequency_hz"])
    crossings = read(os.path.join(out, "crossings.csv"),
                     ["mode", "engine_order", "speed_rad_s", "frequency_hz"])
    speeds = sorted({r["speed_rad_s"] for r in table})
    modes = sorted({int(r["mode"]) for r in table})
    f = {(r["speed_rad_s"], int(r["mode"])): r["frequency_hz"] for r in table}
    top = max(r["frequency_hz"] for r in table if int(r["mode"]) <= min(5, len(modes)))

    fig, ax = plt.subplots(figsize=(8, 6))
    for i in modes[:5]:
        ax.plot(speeds, [f[(w, i)] for w in speeds], "o-", ms=3, label=f"mode {i}")
    for k in range(1, 11):
        ax.plot([0, speeds[-1]], [0, k * speeds[-1] / (2 * math.pi)], "k-" if k % 2 == 0 else "k:",
                lw=0.7)
        w_label = min(speeds[-1], 2 * math.pi * top * 1.05 / k)
        ax.text(w_label, k * w_label / (2 * math.pi), f" {k}", fontsize=7, va="bottom")
    for c in crossings:
        if c["mode"] <= 3:
            ax.plot(c["speed_rad_s"], c["frequency_hz"], "rx", ms=6)
    ax.set_xlim(0, speeds[-1])
    ax.set_ylim(0, top * 1.1)
    ax.set_xlabel("rotation speed Omega [rad/s]")
    ax.set_ylabel("frequency of the rotating blade [Hz]")
    ax.set_title(f"{title}: K(Omega) from ccx at {len(speeds)} speeds; engine orders 1-10 "
                 "(even solid: the oval casing's)", fontsize=9)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    write_whole(os.path.join(out, "campbell.png"), lambda p: fig.savefig(p, dpi=120, format="png"))

    lines = [f"# {title}", "",
             f"The {len(modes)} lowest frequencies of the blade spinning at {len(speeds)} speeds "
             f"from {speeds[0]:g} to {speeds[-1]:g} rad/s (`campbell.csv`, K(Omega) from ccx's "
             "perturbation step after its nonlinear static step under the centrifugal load), and "
             "where the engine orders 1-10 cross the three lowest (`crossings.csv`, linear "
             "interpolation between grid speeds).", "",
             "| mode | at rest [Hz] | at " + f"{speeds[-1]:g}" + " rad/s [Hz] | ratio |", "|---|---|---|---|"]
    for i in modes[:5]:
        lines.append(f"| {i} | {f[(speeds[0], i)]:.1f} | {f[(speeds[-1], i)]:.1f} | "
                     f"{f[(speeds[-1], i)] / f[(speeds[0], i)]:.3f} |")
    lines += ["", "| mode | engine order | speed [rad/s] | speed [rpm] | frequency [Hz] | "
              "mode at rest would cross at [rad/s] |", "|---|---|---|---|---|---|"]
    for c in crossings:
        if c["mode"] > 3:
            continue
        i, k = int(c["mode"]), int(c["engine_order"])
        rest = 2 * math.pi * f[(speeds[0], i)] / k
        lines.append(f"| {i} | {k} | {c['speed_rad_s']:.1f} | {c['speed_rad_s'] * 30 / math.pi:.0f} | "
                     f"{c['frequency_hz']:.1f} | {rest:.1f}" + (" (beyond the range)" if rest > speeds[-1] else "") + " |")
    found = {(int(c["mode"]), int(c["engine_order"])) for c in crossings}
    gone = [(i, k, 2 * math.pi * f[(speeds[0], i)] / k) for i in modes[:3] for k in range(1, 11)
            if 2 * math.pi * f[(speeds[0], i)] / k <= speeds[-1] and (i, k) not in found]
    if gone:
        lines += ["", "Crossings the blade at rest would have in this range and the rotating blade "
                  "has not (its mode has risen above the order's line up to the last speed):", ""]
        lines += [f"- mode {i}, engine order {k}: at rest {w:.1f} rad/s ({w * 30 / math.pi:.0f} rpm); "
                  f"at {speeds[-1]:g} rad/s the mode is at {f[(speeds[-1], i)]:.1f} Hz, the order at "
                  f"{k * speeds[-1] / (2 * math.pi):.1f} Hz" for i, k, w in gone]
    lines.append("")
    write_whole(os.path.join(out, "campbell.md"), lambda p: open(p, "w").write("\n".join(lines)))
    print(f"wrote {out}/campbell.png and {out}/campbell.md")


if __name__ == "__main__":
    main()
