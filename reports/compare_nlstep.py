#!/usr/bin/env python3
"""Compare an rsi Rotor 37 rubbing history with NLstep's own run of the same
case (NLstep's example 03_bladeCasingRubbing, CONFIG = 'PLAUSIBLE', run under
GNU Octave): response of node 1353 direction 2, spectrum, contact states,
normal force. Writes figures and report.md into --out.

Usage (from the repository root; /usr/bin/python3 has numpy, scipy,
matplotlib):

  /usr/bin/python3 reports/compare_nlstep.py \\
      --rsi /work/scratch/r37-mn50-nlstep/history.csv \\
      --nlstep reports/nlstep-rotor37/nlstep_plausible.csv.gz \\
      --former-sign /work/scratch/r37-mn50-with/history.csv \\
      --fine /work/scratch/r37-mn50-2000/history.csv \\
      --nlstep-fine reports/nlstep-rotor37/nlstep_plausible_2000.csv.gz \\
      --nlstep-finer reports/nlstep-rotor37/nlstep_plausible_4000.csv.gz \\
      --mu0-nlstep reports/nlstep-rotor37/nlstep_mu0_{1000,2000,4000}.csv.gz \\
      --mu0-rsi /work/scratch/r37-mn50-mu0/history.csv \\
                /work/scratch/r37-mn50-mu0-2000/history.csv \\
      --out reports/nlstep-rotor37

Only --rsi, --nlstep and --out are required; each optional run adds rows
to the tables (and, for the frictionless short runs, a section).

--nlstep (and --nlstep-fine) take either the compact file written by
--pack (below) or NLstep's output folder as the Octave driver writes it
(response.csv, contact_states.csv, lambda_n_per_node.csv, gap_per_node.csv,
contact_state_per_node.csv). The frictionless short runs come from
driver/run_rotor37_response.m, packed with --pack-response.

Packing NLstep's output folder into the compact files committed with the
report (10 significant digits):

  /usr/bin/python3 reports/compare_nlstep.py --pack /work/nlstep-run/out \\
      --out reports/nlstep-rotor37 [--pack-name nlstep_plausible] [--pack-every 1]

writes
  NAME.csv.gz: t_s, u_1353_2_mm, n_contact, n_stick, n_slip,
    sum_lambda_n_N, max_lambda_n_N (largest per-node lambda_n), min_gap_mm
    (smallest gap of the 16 nodes), max_gap_closed_mm (largest gap of a
    closed node; nan without contact), n_closed_gap_pos (closed nodes with
    a gap above 1e-6 mm); every --pack-every-th time level;
  NAME_first_contact.csv: lambda_n and gap of every node, every step, from
    5 steps before the first contact to 40 after;
  NAME_node188_contact.csv.gz (unless --pack-no-node188): node 188's closed
    samples (gap, forces, slip velocity, state);
  NAME_rom_frequencies.csv, NAME_summary.txt: copies.

  /usr/bin/python3 reports/compare_nlstep.py --pack-response RESPONSE.csv \\
      --pack-every K --pack-name NAME --out DIR
packs driver/run_rotor37_response.m's output (every K-th row).

rsi histories: columns t, u_<node>_<dir>, gap_1..16, lambda_1..16,
lambda_t1_k, lambda_t2_k pairs, ... ; a summary.json beside the history
supplies the integration time. A closed rsi contact (lambda_n > 0) counts
as slip when sqrt(lambda_t1^2 + lambda_t2^2) >= mu lambda_n (1 - 1e-9),
mu = 0.15, as stick otherwise.
"""
import argparse
import gzip
import io
import json
import os
import re
import shutil
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MU = 0.15
OMEGA = 1344.0                       # rad/s
T_REV = 2.0 * np.pi / OMEGA          # s
G_M = 0.356                          # mm
GAP_OPEN = 1e-6                      # mm: a closed node with g above this counts as 'open gap'
WINDOWS = (0.5, 1, 2, 5, 10, 20, 50)  # revolutions
SLIP_TOL = 1e-9
DPI = 110
COLORS = {"nlstep": "k", "rsi": "tab:red", "former": "tab:blue",
          "fine": "tab:orange", "nlstep_fine": "tab:green",
          "nlstep_finer": "tab:brown"}

# ---------------------------------------------------------------- reading


def _open_text(path):
    if path.endswith(".gz"):
        return io.TextIOWrapper(gzip.open(path, "rb"), encoding="ascii")
    return open(path, "r", encoding="ascii")


def _load_csv(path):
    with _open_text(path) as f:
        header = f.readline().strip().split(",")
        data = np.loadtxt(f, delimiter=",", ndmin=2)
    return header, data


def read_rsi(path, label, key, mu=MU):
    header, d = _load_csv(path)
    col = {h: i for i, h in enumerate(header)}
    iu = [i for i, h in enumerate(header) if h.startswith("u_")][0]
    ig = [i for i, h in enumerate(header) if re.fullmatch(r"gap_\d+", h)]
    il = [i for i, h in enumerate(header) if re.fullmatch(r"lambda_\d+", h)]
    nn = len(il)
    it1 = [col["lambda_t1_%d" % (k + 1)] for k in range(nn)]
    it2 = [col["lambda_t2_%d" % (k + 1)] for k in range(nn)]
    gap, lam = d[:, ig], d[:, il]
    lt = np.hypot(d[:, it1], d[:, it2])
    closed = lam > 0
    slip = closed & (lt >= mu * lam * (1.0 - SLIP_TOL))
    stick = closed & ~slip
    s = _series(label, key, d[:, 0], d[:, iu], closed.sum(1), stick.sum(1),
                slip.sum(1), lam.sum(1), lam.max(1), gap.min(1),
                np.where(closed, gap, -np.inf).max(1),
                (closed & (gap > GAP_OPEN)).sum(1))
    s["path"] = path
    s["response_column"] = header[iu]
    s["ratio_closed"] = (lt[closed] / (mu * lam[closed])) if closed.any() \
        else np.zeros(0)
    k0 = int(np.argmax(closed.any(1)))
    rows = np.arange(max(k0 - 5, 0), min(k0 + 41, len(d)))
    s["first"] = dict(t=d[rows, 0], lam=lam[rows], gap=gap[rows])
    sj = os.path.join(os.path.dirname(os.path.abspath(path)), "summary.json")
    if os.path.exists(sj):
        with open(sj) as f:
            s["summary"] = json.load(f)
    return s


def _series(label, key, t, u, nc, nstick, nslip, sumlam, maxlam, mingap,
            maxgapc, ngpos):
    maxgapc = np.where(np.isfinite(maxgapc), maxgapc, np.nan)
    return dict(label=label, key=key, t=np.asarray(t, float),
                u=np.asarray(u, float), nc=np.asarray(nc, int),
                nstick=np.asarray(nstick, int), nslip=np.asarray(nslip, int),
                sumlam=np.asarray(sumlam, float),
                maxlam=np.asarray(maxlam, float),
                mingap=np.asarray(mingap, float),
                maxgapc=np.asarray(maxgapc, float),
                ngpos=np.asarray(ngpos, int))


def _nlstep_folder_arrays(folder):
    """Per-step arrays from the Octave driver's CSV files."""
    _, resp = _load_csv(os.path.join(folder, "response.csv"))
    _, cs = _load_csv(os.path.join(folder, "contact_states.csv"))
    _, ln = _load_csv(os.path.join(folder, "lambda_n_per_node.csv"))
    _, gp = _load_csv(os.path.join(folder, "gap_per_node.csv"))
    _, st = _load_csv(os.path.join(folder, "contact_state_per_node.csv"))
    ln, gp, st = ln[:, 1:], gp[:, 1:], st[:, 1:]
    closed = st > 0
    if not np.array_equal(closed, ln > 0):
        print("warning: NLstep CSTATE>0 differs from lambda_n>0 in %d samples"
              % np.sum(closed != (ln > 0)), file=sys.stderr)
    cols = dict(
        t_s=resp[:, 0], u_1353_2_mm=resp[:, 1],
        n_contact=cs[:, 1], n_stick=cs[:, 2], n_slip=cs[:, 3],
        sum_lambda_n_N=cs[:, 4], max_lambda_n_N=ln.max(1),
        min_gap_mm=gp.min(1),
        max_gap_closed_mm=np.where(closed, gp, -np.inf).max(1),
        n_closed_gap_pos=(closed & (gp > GAP_OPEN)).sum(1))
    return cols


COMPACT_COLS = ("t_s", "u_1353_2_mm", "n_contact", "n_stick", "n_slip",
                "sum_lambda_n_N", "max_lambda_n_N", "min_gap_mm",
                "max_gap_closed_mm", "n_closed_gap_pos")
INT_COLS = ("n_contact", "n_stick", "n_slip", "n_closed_gap_pos")


def read_nlstep(path, label, key):
    if os.path.isdir(path):
        c = _nlstep_folder_arrays(path)
    else:
        header, d = _load_csv(path)
        c = {h: d[:, i] for i, h in enumerate(header)}
    s = _series(label, key, c["t_s"], c["u_1353_2_mm"], c["n_contact"],
                c["n_stick"], c["n_slip"], c["sum_lambda_n_N"],
                c["max_lambda_n_N"], c["min_gap_mm"],
                c["max_gap_closed_mm"], c["n_closed_gap_pos"])
    s["path"] = path
    if os.path.isdir(path):
        if os.path.exists(os.path.join(path, "summary.txt")):
            with open(os.path.join(path, "summary.txt")) as f:
                s["summary_txt"] = f.read()
        if os.path.exists(os.path.join(path, "rom_frequencies.csv")):
            h, d = _load_csv(os.path.join(path, "rom_frequencies.csv"))
            s["rom"] = {x: d[:, i] for i, x in enumerate(h)}
    base = path[:-len(".csv.gz")] if path.endswith(".csv.gz") else None
    if base and os.path.exists(base + "_node188_contact.csv.gz"):
        h, d = _load_csv(base + "_node188_contact.csv.gz")
        s["node188"] = {x: d[:, i] for i, x in enumerate(h)}
    if base and os.path.exists(base + "_first_contact.csv"):
        h, d = _load_csv(base + "_first_contact.csv")
        il = [i for i, x in enumerate(h) if x.startswith("lambda_n_")]
        ig = [i for i, x in enumerate(h) if x.startswith("g_")]
        s["first"] = dict(t=d[:, 1], lam=d[:, il], gap=d[:, ig],
                          nodes=[h[i][len("lambda_n_"):-2] for i in il])
    if base and os.path.exists(base + "_rom_frequencies.csv"):
        h, d = _load_csv(base + "_rom_frequencies.csv")
        s["rom"] = {x: d[:, i] for i, x in enumerate(h)}
    if base and os.path.exists(base + "_summary.txt"):
        with open(base + "_summary.txt") as f:
            s["summary_txt"] = f.read()
    return s


def _fmt(x):
    if isinstance(x, (int, np.integer)):
        return "%d" % x
    if not np.isfinite(x):
        return "nan"
    return "%.10g" % x


def _write_gz(path, header, rows):
    with open(path, "wb") as raw:
        with gzip.GzipFile(filename="", mode="wb", fileobj=raw, mtime=0,
                           compresslevel=9) as gz:
            gz.write((",".join(header) + "\n").encode())
            for r in rows:
                gz.write((",".join(_fmt(x) for x in r) + "\n").encode())


def pack(folder, out, name, every, node188=True):
    os.makedirs(out, exist_ok=True)
    c = _nlstep_folder_arrays(folder)
    n = len(c["t_s"])
    idx = np.arange(0, n, every)
    cols = []
    for h in COMPACT_COLS:
        v = c[h][idx]
        cols.append(v.astype(int) if h in INT_COLS else v)
    rows = zip(*[[int(x) for x in v] if h in INT_COLS else list(v)
                 for h, v in zip(COMPACT_COLS, cols)])
    p = os.path.join(out, name + ".csv.gz")
    _write_gz(p, COMPACT_COLS, rows)
    print("wrote", p, os.path.getsize(p), "bytes,", len(idx), "rows")
    # the first closing of the oval: lambda_n and g of every node, every
    # step, from 5 steps before the first contact to 40 after
    _pack_first_contact(folder, out, name)
    # node 188: the closed samples (all of them, every step)
    if node188:
        _pack_node188(folder, out, name)
    for src, dst in (("rom_frequencies.csv", "_rom_frequencies.csv"),
                     ("summary.txt", "_summary.txt")):
        if os.path.exists(os.path.join(folder, src)):
            shutil.copyfile(os.path.join(folder, src),
                            os.path.join(out, name + dst))
            print("wrote", os.path.join(out, name + dst))


def pack_response(path, out, name, every):
    """Compact copy of run_rotor37_response.m's output (every k-th row)."""
    h, d = _load_csv(path)
    cols = ("t_s", "u_1353_2_mm", "sum_lambda_n_N", "steps_per_rev", "mu")
    idx = [h.index(x) for x in cols]
    rows = ([float(r[idx[0]]), float(r[idx[1]]), float(r[idx[2]]),
             int(r[idx[3]]), float(r[idx[4]])] for r in d[::every])
    os.makedirs(out, exist_ok=True)
    p = os.path.join(out, name + ".csv.gz")
    _write_gz(p, cols, rows)
    print("wrote", p, os.path.getsize(p), "bytes")


def read_short(path, kind):
    """A short run: NLstep's compact response file or an rsi history."""
    if kind == "nlstep":
        h, d = _load_csv(path)
        c = {x: d[:, i] for i, x in enumerate(h)}
        return dict(path=path, t=c["t_s"], u=c["u_1353_2_mm"],
                    sumlam=c["sum_lambda_n_N"], spr=int(c["steps_per_rev"][0]),
                    mu=float(c["mu"][0]), code="NLstep")
    s = read_rsi(path, "", "short")
    sm = s.get("summary", {})
    spr = int(round(T_REV / sm["dt"])) if "dt" in sm else 0
    return dict(path=path, t=s["t"], u=s["u"], sumlam=s["sumlam"], spr=spr,
                mu=None, code="rsi")


def _pack_first_contact(folder, out, name):
    h, ln = _load_csv(os.path.join(folder, "lambda_n_per_node.csv"))
    _, gp = _load_csv(os.path.join(folder, "gap_per_node.csv"))
    nodes = [x[len("node"):-len("_N")] for x in h[1:]]
    k0 = int(np.argmax((ln[:, 1:] > 0).any(1)))
    rows = range(max(k0 - 5, 0), k0 + 41)
    nh = ["step", "t_s"] + ["lambda_n_%s_N" % n for n in nodes] + \
        ["g_%s_mm" % n for n in nodes]
    p = os.path.join(out, name + "_first_contact.csv")
    with open(p, "w") as f:
        f.write(",".join(nh) + "\n")
        for k in rows:
            f.write(",".join(["%d" % k] + [_fmt(x) for x in ln[k, :1]]
                             + [_fmt(x) for x in ln[k, 1:]]
                             + [_fmt(x) for x in gp[k, 1:]]) + "\n")
    print("wrote", p)


def _pack_node188(folder, out, name):
    h, d = _load_csv(os.path.join(folder, "gap_node188.csv"))
    col = {x: i for i, x in enumerate(h)}
    keep = d[:, col["state"]] > 0
    nh = ("t_s", "g_mm", "lambda_n_N", "lambda_t1_N", "lambda_t2_N",
          "gamma_t1_mm_s", "gamma_t2_mm_s", "state")
    rows = ([float(r[col[x]]) if x != "state" else int(r[col[x]])
             for x in nh] for r in d[keep])
    p = os.path.join(out, name + "_node188_contact.csv.gz")
    _write_gz(p, nh, rows)
    print("wrote", p, os.path.getsize(p), "bytes,", int(keep.sum()), "rows")

# ------------------------------------------------------------ computation


def window_mask(t, a_rev, b_rev):
    tol = 1e-6 * T_REV   # the compact file's t has 10 significant digits
    return (t >= a_rev * T_REV - tol) & (t <= b_rev * T_REV + tol)


def e2(a, b, m):
    return np.linalg.norm(a[m] - b[m]) / np.linalg.norm(b[m])


def einf(a, b, m):
    return np.max(np.abs(a[m] - b[m])) / np.max(np.abs(b[m]))


def check_same_instants(a, b):
    if len(a["t"]) != len(b["t"]) or np.max(np.abs(a["t"] - b["t"])) > 1e-6 * T_REV:
        raise SystemExit("%s and %s are not sampled at the same instants"
                         % (a["path"], b["path"]))


def steady(s):
    y = s["u"][window_mask(s["t"], 45, 50)]
    return dict(n=len(y), mean=y.mean(), min=y.min(), max=y.max(),
                rms=np.sqrt(np.mean(y ** 2)), std=y.std())


def spectrum(s):
    """One-sided amplitude spectrum over exactly the last 5 revolutions:
    the samples at t in [45 T, 50 T), mean removed, rectangular window."""
    t, u = s["t"], s["u"]
    i0 = int(np.argmin(np.abs(t - 45 * T_REV)))
    i1 = int(np.argmin(np.abs(t - 50 * T_REV)))
    x = u[i0:i1].copy()
    x -= x.mean()
    n = len(x)
    dt = (t[i1] - t[i0]) / n
    a = 2.0 * np.abs(np.fft.rfft(x)) / n
    a[0] /= 2.0
    f = np.fft.rfftfreq(n, dt)
    return f, a, n, 1.0 / (n * dt)


def top_lines(f, a, k=5):
    pk = [i for i in range(1, len(a) - 1) if a[i] >= a[i - 1] and a[i] > a[i + 1]]
    pk.sort(key=lambda i: -a[i])
    return [(f[i], a[i]) for i in pk[:k]]


def contact_stats(s):
    t = s["t"]
    last = window_mask(t, 45, 50)
    has = s["nc"] > 0
    st = dict(
        samples=len(t), steps_contact=int(has.sum()),
        closed=int(s["nc"].sum()), slip=int(s["nslip"].sum()),
        stick=int(s["nstick"].sum()), max_nc=int(s["nc"].max()),
        max_sum=float(s["sumlam"].max()), max_lam=float(s["maxlam"].max()),
        min_gap=float(s["mingap"].min()),
        max_gap_closed=float(np.nanmax(s["maxgapc"])) if has.any() else np.nan,
        closed_gap_pos=int(s["ngpos"].sum()),
        first_contact_rev=float(t[np.argmax(has)] / T_REV) if has.any() else np.nan,
        frac_steps_last5=float(has[last].mean()),
        mean_nc_last5=float(s["nc"][last].mean()),
        mean_stick_last5=float(s["nstick"][last].mean()),
        mean_slip_last5=float(s["nslip"][last].mean()),
        mean_sum_last5=float(s["sumlam"][last].mean()),
        max_sum_last5=float(s["sumlam"][last].max()),
        impulse=float(np.sum(s["sumlam"]) * (t[1] - t[0])),
        impulse_last5=float(np.sum(s["sumlam"][last]) * (t[1] - t[0])),
        max_sum_first_half=float(s["sumlam"][window_mask(t, 0, 0.5)].max()),
        max_lam_first_half=float(s["maxlam"][window_mask(t, 0, 0.5)].max()),
        impulse_first_half=float(np.sum(s["sumlam"][window_mask(t, 0, 0.5)])
                                 * (t[1] - t[0])))
    return st


def per_rev_e2(a, b, nrev=50):
    return np.array([e2(a["u"], b["u"], window_mask(b["t"], r, r + 1))
                     for r in range(nrev)])


def best_shift(a, b, a_rev, b_rev, smax=30):
    m = np.where(window_mask(b["t"], a_rev, b_rev))[0]
    best = None
    for sh in range(-smax, smax + 1):
        mm = m[(m + sh >= 0) & (m + sh < len(a["u"]))]
        v = np.linalg.norm(a["u"][mm + sh] - b["u"][mm]) / np.linalg.norm(b["u"][mm])
        if best is None or v < best[0]:
            best = (v, sh)
    return best

# ---------------------------------------------------------------- figures


def _save(fig, out, name):
    """PNG at DPI, reduced to a 128-colour palette (a quarter to a half of
    the RGBA size; the plots use few colours)."""
    p = os.path.join(out, name)
    buf = io.BytesIO()
    fig.savefig(buf, dpi=DPI, format="png")
    plt.close(fig)
    buf.seek(0)
    try:
        from PIL import Image
        im = Image.open(buf).convert("RGB")
        im.quantize(colors=128, method=Image.Quantize.MEDIANCUT).save(p, optimize=True)
    except Exception:  # no Pillow: the RGBA PNG as matplotlib wrote it
        with open(p, "wb") as f:
            f.write(buf.getvalue())
    return name


def fig_response(runs, ref, out):
    fig, ax = plt.subplots(2, 1, figsize=(10, 6.4), sharex=True,
                           gridspec_kw=dict(height_ratios=[2, 1]))
    step = 4   # every 4th sample: 250 a revolution, 12,500 points a line
    for s in runs[:2]:
        ax[0].plot(s["t"][::step] / T_REV, s["u"][::step], lw=0.4,
                   color=COLORS[s["key"]], label=s["label"])
    d = runs[1]["u"] - ref["u"]
    ax[1].plot(ref["t"][::step] / T_REV, d[::step], lw=0.4, color="tab:purple")
    ax[0].set_ylabel("u(1353, y) [mm]")
    ax[1].set_ylabel("rsi - NLstep, 1000/rev [mm]")
    ax[1].set_xlabel("revolutions (t / T, T = 2 pi / 1344 rad/s = 4.675 ms)")
    ax[0].legend(loc="upper right", fontsize=8)
    ax[0].set_title("Response over 50 revolutions (every 4th sample plotted)")
    for a in ax:
        a.grid(alpha=0.3)
    fig.tight_layout()
    return _save(fig, out, "response_50rev.png")


def fig_last2(runs, ref, out):
    fig, ax = plt.subplots(2, 1, figsize=(10, 6.4), sharex=True,
                           gridspec_kw=dict(height_ratios=[2, 1]))
    for s in runs:
        m = window_mask(s["t"], 48, 50)
        lw = 1.2 if s["key"] in ("nlstep", "rsi") else 0.8
        ls = "-" if s["key"] in ("nlstep", "rsi", "former") else "--"
        ax[0].plot(s["t"][m] / T_REV, s["u"][m], lw=lw, ls=ls,
                   color=COLORS[s["key"]], label=s["label"])
    m = window_mask(ref["t"], 48, 50)
    ax[1].plot(ref["t"][m] / T_REV, runs[1]["u"][m] - ref["u"][m],
               color="tab:purple", lw=0.9)
    ax[0].set_ylabel("u(1353, y) [mm]")
    ax[1].set_ylabel("rsi - NLstep, 1000/rev [mm]")
    ax[1].set_xlabel("revolutions")
    ax[0].legend(loc="upper right", fontsize=7)
    ax[0].set_title("Last 2 revolutions (every sample)")
    for a in ax:
        a.grid(alpha=0.3)
    fig.tight_layout()
    return _save(fig, out, "response_last2rev.png")


def fig_spectrum(runs, out, fmax=5000.0):
    fig, ax = plt.subplots(figsize=(10, 4.6))
    frev = 1.0 / T_REV
    for k in range(1, int(fmax / frev) + 1):
        ax.axvline(k * frev, color="0.85", lw=0.5, zorder=0)
    for s, mk, off in zip(runs[:2], ("o", "x"), (0.0, 0.0)):
        f, a, n, df = spectrum(s)
        m = (f <= fmax) & (f > 0)
        ax.semilogy(f[m] + off, a[m], marker=mk, ms=3, lw=0.7,
                    color=COLORS[s["key"]], label=s["label"])
    ax.set_ylim(1e-5, 10)
    ax.set_xlim(0, fmax)
    ax.set_xlabel("frequency [Hz] (grey: multiples of f_rev = %.2f Hz)" % frev)
    ax.set_ylabel("amplitude [mm]")
    ax.set_title("Spectrum of the last 5 revolutions (%d samples, mean removed, "
                 "rectangular window, df = %.2f Hz)" % (n, df))
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    return _save(fig, out, "spectrum_last5rev.png")


def _per_rev(s, field, fn, nrev=50):
    return np.array([fn(s[field][window_mask(s["t"], r, r + 1)])
                     for r in range(nrev)])


def fig_contacts(runs, out):
    a, b = runs[0], runs[1]
    fig, ax = plt.subplots(3, 1, figsize=(10, 8.6))
    r = np.arange(50) + 0.5
    for s, ls in ((a, "-"), (b, "--")):
        c = COLORS[s["key"]]
        ax[0].plot(r, _per_rev(s, "nc", np.mean), ls, color=c, marker="o", ms=3,
                   label="%s: in contact" % s["label"])
        ax[0].plot(r, _per_rev(s, "nslip", np.mean), ls, color=c, marker="^",
                   ms=3, alpha=0.6, label="%s: slip" % s["label"])
        ax[0].plot(r, _per_rev(s, "nstick", np.mean), ls, color=c, marker="s",
                   ms=3, alpha=0.6, label="%s: stick" % s["label"])
    ax[0].set_xlabel("revolution")
    ax[0].set_ylabel("nodes (mean over the revolution)")
    ax[0].set_title("Contact nodes per step, mean over each revolution")
    ax[0].legend(fontsize=7, ncol=2)
    for k, (s, ls) in enumerate(((a, "-"), (b, "-"))):
        m = window_mask(s["t"], 48, 50)
        x = s["t"][m] / T_REV
        axk = ax[1 + k]
        axk.step(x, s["nc"][m], where="mid", color="k", lw=0.9, label="in contact")
        axk.step(x, s["nslip"][m], where="mid", color="tab:red", lw=0.8, label="slip")
        axk.step(x, s["nstick"][m], where="mid", color="tab:blue", lw=0.8, label="stick")
        axk.set_ylabel("nodes")
        axk.set_title("%s, last 2 revolutions, every step" % s["label"])
        axk.legend(fontsize=7, loc="upper right")
        axk.set_ylim(-0.5, 16.5)
    ax[2].set_xlabel("revolutions")
    for x in ax:
        x.grid(alpha=0.3)
    fig.tight_layout()
    return _save(fig, out, "contact_states.png")


def fig_force(runs, out):
    fig, ax = plt.subplots(2, 1, figsize=(10, 6.4))
    r = np.arange(50) + 0.5
    for s in runs[:2]:
        c = COLORS[s["key"]]
        ax[0].plot(r, _per_rev(s, "sumlam", np.max) / 1e3, "-o", ms=3, color=c,
                   label="%s: max over the revolution" % s["label"])
        ax[0].plot(r, _per_rev(s, "sumlam", np.mean) / 1e3, "--s", ms=3, color=c,
                   label="%s: mean over the revolution" % s["label"])
        m = window_mask(s["t"], 48, 50)
        ax[1].plot(s["t"][m] / T_REV, s["sumlam"][m] / 1e3, color=c, lw=0.9,
                   label=s["label"])
    ax[0].set_xlabel("revolution")
    ax[0].set_ylabel("sum of lambda_n [kN]")
    ax[0].set_title("Total normal contact force (16 nodes)")
    ax[1].set_xlabel("revolutions")
    ax[1].set_ylabel("sum of lambda_n [kN]")
    ax[1].set_title("Last 2 revolutions, every step")
    for x in ax:
        x.grid(alpha=0.3)
        x.legend(fontsize=7)
    fig.tight_layout()
    return _save(fig, out, "normal_force.png")


def fig_per_rev_error(pairs, out):
    fig, ax = plt.subplots(figsize=(10, 4.2))
    r = np.arange(50) + 0.5
    for lab, v, c in pairs:
        ax.semilogy(r, v, "-o", ms=3, color=c, label=lab)
    ax.set_xlabel("revolution")
    ax.set_ylabel("e2 over the revolution")
    ax.set_title("Relative L2 difference of the response, revolution by revolution")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.tight_layout()
    return _save(fig, out, "e2_per_revolution.png")

# ----------------------------------------------------------------- report


def _rel(a, b):
    return (a - b) / abs(b)


def table(header, rows):
    s = "| " + " | ".join(header) + " |\n"
    s += "|" + "|".join("---" for _ in header) + "|\n"
    for r in rows:
        s += "| " + " | ".join(str(x) for x in r) + " |\n"
    return s


SHORT = {"nlstep": "NLstep 1000/rev", "nlstep_fine": "NLstep 2000/rev",
         "nlstep_finer": "NLstep 4000/rev", "rsi": "rsi 1000/rev",
         "fine": "rsi 2000/rev", "former": "rsi former sign 1000/rev"}


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--rsi", help="rsi history.csv, NLstep's sliding sign, 1000 steps/rev")
    p.add_argument("--nlstep", help="NLstep, 1000 steps/rev: compact .csv.gz or output folder")
    p.add_argument("--former-sign", help="optional rsi history, former sign (with_rotation)")
    p.add_argument("--fine", help="optional rsi history at 2000 steps/rev, rows every 2nd step")
    p.add_argument("--nlstep-fine", help="optional NLstep at 2000 steps/rev (compact, every 2nd step)")
    p.add_argument("--nlstep-finer", help="optional NLstep at 4000 steps/rev (compact, every 4th step)")
    p.add_argument("--out", required=True, help="output folder")
    p.add_argument("--command", help="command line to print in report.md (default: this one)")
    p.add_argument("--pack", metavar="NLSTEP_OUT_DIR",
                   help="pack NLstep's output folder into compact files in --out and exit")
    p.add_argument("--pack-name", default="nlstep_plausible")
    p.add_argument("--pack-every", type=int, default=1,
                   help="keep every k-th time level (2 for a 2000 steps/rev run)")
    p.add_argument("--pack-no-node188", action="store_true",
                   help="do not write NAME_node188_contact.csv.gz")
    p.add_argument("--pack-response", metavar="CSV",
                   help="pack run_rotor37_response.m's output into --out/NAME.csv.gz and exit")
    p.add_argument("--mu0-nlstep", nargs="+", default=[],
                   help="NLstep frictionless short runs (packed responses), any steps/rev")
    p.add_argument("--mu0-rsi", nargs="+", default=[],
                   help="rsi frictionless short runs (history.csv), any steps/rev")
    args = p.parse_args()
    if args.pack_response:
        pack_response(args.pack_response, args.out, args.pack_name, args.pack_every)
        return
    if args.pack:
        pack(args.pack, args.out, args.pack_name, args.pack_every,
             not args.pack_no_node188)
        return
    if not (args.rsi and args.nlstep):
        p.error("--rsi and --nlstep are required (or --pack)")
    os.makedirs(args.out, exist_ok=True)

    nl = read_nlstep(args.nlstep, "NLstep (Octave), 1000 steps/rev", "nlstep")
    rs = read_rsi(args.rsi, "rsi MacNeal-50, NLstep's sign, 1000 steps/rev", "rsi")
    check_same_instants(rs, nl)
    R = {"nlstep": nl, "rsi": rs}
    if args.nlstep_fine:
        R["nlstep_fine"] = read_nlstep(args.nlstep_fine, "NLstep (Octave), 2000 steps/rev", "nlstep_fine")
    if args.nlstep_finer:
        R["nlstep_finer"] = read_nlstep(args.nlstep_finer, "NLstep (Octave), 4000 steps/rev", "nlstep_finer")
    if args.fine:
        R["fine"] = read_rsi(args.fine, "rsi MacNeal-50, NLstep's sign, 2000 steps/rev", "fine")
    if args.former_sign:
        R["former"] = read_rsi(args.former_sign, "rsi MacNeal-50, former sign (with_rotation)", "former")
    for s in R.values():
        check_same_instants(s, nl)
    order = [R[k] for k in ("nlstep", "nlstep_fine", "nlstep_finer", "rsi", "fine", "former") if k in R]
    plot_runs = [nl, rs] + [R[k] for k in ("fine", "nlstep_fine", "nlstep_finer", "former") if k in R]

    figs = dict(resp=fig_response(plot_runs, nl, args.out),
                last2=fig_last2(plot_runs, nl, args.out),
                spec=fig_spectrum(plot_runs, args.out),
                cont=fig_contacts(plot_runs, args.out),
                force=fig_force(plot_runs, args.out))

    # pairs (a, b): e2, e_inf of a against b
    pairs = [("rsi", "nlstep"), ("former", "nlstep"), ("fine", "nlstep"),
             ("rsi", "fine"), ("nlstep", "nlstep_fine"),
             ("nlstep_fine", "nlstep_finer"), ("fine", "nlstep_fine"),
             ("fine", "nlstep_finer")]
    pairs = [(a, b) for a, b in pairs if a in R and b in R]
    err = {}
    prev = {}
    for a, b in pairs:
        err[(a, b)] = [(e2(R[a]["u"], R[b]["u"], window_mask(R[b]["t"], 0, w)),
                        einf(R[a]["u"], R[b]["u"], window_mask(R[b]["t"], 0, w)))
                       for w in WINDOWS]
        prev[(a, b)] = per_rev_e2(R[a], R[b])
    pr_plot = [("rsi 1000/rev vs NLstep 1000/rev", prev[("rsi", "nlstep")], COLORS["rsi"])]
    for (a, b), c in ((("fine", "nlstep_fine"), "tab:olive"),
                      (("fine", "nlstep_finer"), "tab:purple"),
                      (("rsi", "fine"), COLORS["fine"]),
                      (("nlstep", "nlstep_fine"), COLORS["nlstep_fine"]),
                      (("nlstep_fine", "nlstep_finer"), "tab:cyan")):
        if (a, b) in prev:
            pr_plot.append(("%s vs %s" % (SHORT[a], SHORT[b]), prev[(a, b)], c))
    figs["perrev"] = fig_per_rev_error(pr_plot, args.out)

    mu0 = [read_short(x, "nlstep") for x in args.mu0_nlstep] + \
        [read_short(x, "rsi") for x in args.mu0_rsi]
    ctx = dict(
        mu0=mu0,
        cmd=args.command or _command_line(),
        figs=figs, R=R, order=order, pairs=pairs, err=err, prev=prev,
        ss={s["key"]: steady(s) for s in order},
        sp={s["key"]: spectrum(s) for s in order},
        cst={s["key"]: contact_stats(s) for s in order},
        shift_last5=best_shift(rs, nl, 45, 50),
        shift_10_20=best_shift(rs, nl, 10, 20),
        pre=(int(np.argmax(nl["nc"] > 0)),
             float(np.abs(nl["u"][:np.argmax(nl["nc"] > 0)]).max()),
             float(np.abs(rs["u"][:np.argmax(nl["nc"] > 0)]).max())),
        nl_omega50=("%.6f" % nl["rom"]["omega_rad_s"][-1]) if "rom" in nl else "?",
        rsi_omega_max=("%.6f" % rs["summary"]["omega_max"])
        if "omega_max" in rs.get("summary", {}) else "?")
    text = build_report(ctx)
    with open(os.path.join(args.out, "report.md"), "w") as f:
        f.write(text)
    print("wrote", os.path.join(args.out, "report.md"))
    for v in figs.values():
        print("wrote", os.path.join(args.out, v),
              os.path.getsize(os.path.join(args.out, v)), "bytes")


def _command_line():
    """This invocation, one option a line."""
    parts = ["/usr/bin/python3 " + (os.path.relpath(sys.argv[0])
                                   if os.path.exists(sys.argv[0]) else sys.argv[0])]
    for x in sys.argv[1:]:
        if x.startswith("--"):
            parts.append(x)
        else:
            parts[-1] += " " + x
    return " \\\n    ".join(parts)


def _timing(s):
    return s.get("summary", {}).get("integration_seconds")


def _nl_timing(s):
    m = re.search(r"integration alone ([0-9.]+) s wall \(([0-9.]+) s cpu\)",
                  s.get("summary_txt", ""))
    return (float(m.group(1)), float(m.group(2))) if m else (None, None)


def _first_closing(s):
    """(node index, row) of the first closed node in s['first']."""
    f = s["first"]
    closed = f["lam"] > 0
    r0 = int(np.argmax(closed.any(1)))
    j = int(np.argmax(closed[r0]))
    return j, r0


def build_report(c):
    R, order, err, prev = c["R"], c["order"], c["err"], c["prev"]
    ss, sp, cst, figs = c["ss"], c["sp"], c["cst"], c["figs"]
    nl, rs = R["nlstep"], R["rsi"]
    L = []
    w = L.append
    w(HEADER.format(cmd=c["cmd"]))
    w(RUN_SECTION)
    w(SIGN_SECTION)

    w("## Results\n\n")
    w("All numbers below are computed by `reports/compare_nlstep.py` from the "
      "files named in the command above; NLstep's from the compact files "
      "`nlstep_plausible*.csv.gz` (10 significant digits of the Octave "
      "driver's CSV export). Every run is compared at the same 50,001 "
      "instants t_k = k T/1000 (T = 2π/1344 s = %.6f ms): the runs at 2000 "
      "and 4000 steps a revolution are recorded every 2nd and every 4th step. "
      "Short names: NLstep 1000/rev is NLstep's run as its example sets it "
      "up; rsi 1000/rev is `rsi simulate data/cases/rotor37-rubbing.json "
      "--method macneal --modes 50` (NLstep's sliding sign); \"former sign\" "
      "is the same with `\"tip_sliding\": \"with_rotation\"`.\n\n" % (T_REV * 1e3))

    # ---- errors
    w("### Response u(1353, y): differences over windows [0, k T]\n\n")
    w("e₂ = ‖a − b‖₂ / ‖b‖₂ and e_∞ = max|a − b| / max|b| over the samples "
      "with t ≤ k T.\n\n")
    hdr = ["a", "b"] + ["%g rev" % x for x in WINDOWS]
    for idx, name in ((0, "e₂"), (1, "e_∞")):
        rows = [[SHORT[a], SHORT[b]] + ["%.4f" % v[idx] for v in err[(a, b)]]
                for a, b in c["pairs"]]
        w("**%s**\n\n" % name + table(hdr, rows) + "\n")
    sel = [1, 2, 3, 5, 10, 13, 20, 30, 40, 50]
    rows = [[SHORT[a], SHORT[b]] + ["%.4f" % prev[(a, b)][r - 1] for r in sel]
            for a, b in c["pairs"] if a != "former"]
    w("**e₂ per revolution** (revolution r is t ∈ [(r−1) T, r T]; all 50 in "
      "the figure below)\n\n" + table(["a", "b"] + ["rev %d" % r for r in sel], rows) + "\n")
    w("![response over 50 revolutions](%s)\n\n" % figs["resp"])
    w("![last 2 revolutions](%s)\n\n" % figs["last2"])
    w("![e2 per revolution](%s)\n\n" % figs["perrev"])

    # ---- steady state
    w("### Steady state: last 5 revolutions (t ∈ [45 T, 50 T], %d samples)\n\n"
      % ss["nlstep"]["n"])
    K = ("mean", "min", "max", "rms", "std")
    rows = [[s["label"]] + ["%.4f" % ss[s["key"]][k] for k in K] for s in order]
    for s in order:
        if s["key"] != "nlstep":
            rows.append(["rel. diff. %s vs NLstep 1000/rev" % SHORT[s["key"]]]
                        + ["%+.4f" % _rel(ss[s["key"]][k], ss["nlstep"][k]) for k in K])
    w(table(["run", "mean [mm]", "min [mm]", "max [mm]", "RMS [mm]", "std [mm]"], rows))
    w("\nrel. diff. = (x − x_NLstep) / |x_NLstep|; std is the population "
      "standard deviation (RMS² = mean² + std²).\n\n")

    # ---- spectrum
    f, a, n, df = sp["nlstep"]
    w("### Dominant frequencies, last 5 revolutions\n\n")
    w("FFT of exactly 5 revolutions (%d samples, t ∈ [45 T, 50 T)), mean "
      "removed, rectangular window, one-sided amplitude 2|X_k|/N; Δf = %.2f Hz "
      "= f_rev/5, f_rev = %.2f Hz. The 5 largest local maxima of each "
      "spectrum, as frequency (multiple of f_rev): amplitude:\n\n"
      % (n, df, 1.0 / T_REV))
    rows = []
    for s in order:
        ff, aa, _, _ = sp[s["key"]]
        rows.append([s["label"]] + ["%.2f Hz (%.0f): %.4f mm" % (x, x * T_REV, y)
                                    for x, y in top_lines(ff, aa)])
    w(table(["run", "1", "2", "3", "4", "5"], rows))
    w("\n![spectrum](%s)\n\n" % figs["spec"])

    # ---- contact
    w("### Contact\n\n")
    w("NLstep's states are its own `CSTATE` (closed if λ_n > 0; slip if "
      "|λ_T| ≥ μ λ_n, else stick; set in `JORproj` of `sim_contact3D.m`). "
      "For rsi the history holds λ_n, λ_t1, λ_t2 per node and this script "
      "classifies: closed if λ_n > 0; slip if √(λ_t1² + λ_t2²) ≥ μ λ_n "
      "(1 − 1e−9), μ = 0.15; stick otherwise. A node-sample is one node at "
      "one recorded instant; g is a node's normal gap (mm, > 0 open).\n\n")
    keys = [("steps_contact", "instants with ≥ 1 closed node", "%d"),
            ("first_contact_rev", "first contact [rev]", "%.3f"),
            ("closed", "closed node-samples", "%d"),
            ("slip", "slip node-samples", "%d"),
            ("stick", "stick node-samples", "%d"),
            ("max_nc", "max closed nodes at one instant", "%d"),
            ("max_sum", "max total normal force Σλ_n [N]", "%.0f"),
            ("max_lam", "max per-node λ_n [N]", "%.0f"),
            ("impulse", "normal impulse ∫Σλ_n dt, 50 rev [N s]", "%.2f"),
            ("min_gap", "min gap, all nodes and instants [mm]", "%.3e"),
            ("max_gap_closed", "max gap of a closed node [mm]", "%.3e"),
            ("closed_gap_pos", "closed node-samples with g > 1e−6 mm", "%d"),
            ("max_lam_first_half", "first half rev: max per-node λ_n [N]", "%.0f"),
            ("max_sum_first_half", "first half rev: max Σλ_n [N]", "%.0f"),
            ("impulse_first_half", "first half rev: ∫Σλ_n dt [N s]", "%.3f"),
            ("frac_steps_last5", "last 5 rev: fraction of instants with contact", "%.3f"),
            ("mean_nc_last5", "last 5 rev: mean closed nodes", "%.2f"),
            ("mean_stick_last5", "last 5 rev: mean stick nodes", "%.2f"),
            ("mean_slip_last5", "last 5 rev: mean slip nodes", "%.2f"),
            ("mean_sum_last5", "last 5 rev: mean Σλ_n [N]", "%.0f"),
            ("max_sum_last5", "last 5 rev: max Σλ_n [N]", "%.0f"),
            ("impulse_last5", "last 5 rev: ∫Σλ_n dt [N s]", "%.2f")]
    rows = [[lab] + [fm % cst[s["key"]][k] for s in order] for k, lab, fm in keys]
    w(table(["quantity"] + [SHORT[s["key"]] for s in order], rows))
    w("\nAll counts, maxima and integrals are over the 50,001 recorded "
      "instants (for the 2000 and 4000 steps/rev runs: every 2nd and 4th "
      "step only).\n\n")
    w("![contact states](%s)\n\n" % figs["cont"])
    w("![normal force](%s)\n\n" % figs["force"])

    # ---- first closing
    if "first" in nl:
        j, r0 = _first_closing(nl)
        node = nl["first"]["nodes"][j]
        jr, rr0 = _first_closing(rs)
        ft, rt = nl["first"]["t"], rs["first"]["t"]
        w("### The first closing (node %s)\n\n" % node)
        w("The first node to close in NLstep is node %s, at t = %.4f T; in "
          "rsi it is boundary node %d (the 16 nodes in the same order) at "
          "t = %.4f T. λ_n and g of node %s at the same instants (NLstep: "
          "`nlstep_plausible_first_contact.csv`; rsi: its history):\n\n" % (
              node, ft[r0] / T_REV, jr + 1, rs["first"]["t"][rr0] / T_REV, node))
        rows = []
        for k in range(r0 - 2, r0 + 10):
            t = ft[k]
            i = int(np.argmin(np.abs(rt - t)))
            rows.append(["%.4f" % (t / T_REV), "%.1f" % rs["first"]["lam"][i, j],
                         "%+.6f" % rs["first"]["gap"][i, j],
                         "%.1f" % (nl["first"]["lam"][k, j] if nl["first"]["lam"][k, j] > 0 else 0.0),
                         "%+.6f" % nl["first"]["gap"][k, j]])
        w(table(["t / T", "rsi λ_n [N]", "rsi g [mm]", "NLstep λ_n [N]",
                 "NLstep g [mm]"], rows))
        extra = []
        for key in ("nlstep_fine", "nlstep_finer"):
            if key in R and "first" in R[key]:
                jj, k0 = _first_closing(R[key])
                extra.append("%s closes node %s at t = %.5f T with g = %+.6f mm "
                             "(the step before: %+.6f mm)" % (
                                 SHORT[key], R[key]["first"]["nodes"][jj],
                                 R[key]["first"]["t"][k0] / T_REV,
                                 R[key]["first"]["gap"][k0, jj],
                                 R[key]["first"]["gap"][k0 - 1, jj]))
        # the first instant after closing where NLstep's force falls below rsi's
        cross = None
        for k in range(r0, len(ft)):
            i = int(np.argmin(np.abs(rt - ft[k])))
            if nl["first"]["lam"][k, j] < rs["first"]["lam"][i, j]:
                cross = k - r0
                break
        i0 = int(np.argmin(np.abs(rt - ft[r0])))
        c["first_info"] = dict(node=node, g_nl=nl["first"]["gap"][r0, j],
                               g_prev=nl["first"]["gap"][r0 - 1, j],
                               lam_nl=nl["first"]["lam"][r0, j],
                               lam_rs=rs["first"]["lam"][i0, j], cross=cross)
        w("\nNLstep closes the node at the gap of the step before (g = %+.6f mm "
          "at the last open step, %+.6f mm at the first closed one) and keeps "
          "g there while the force builds up; rsi closes it at g = 0. %s.\n\n"
          % (nl["first"]["gap"][r0 - 1, j], nl["first"]["gap"][r0, j],
             "; ".join(extra) if extra else ""))

    # ---- stick in NLstep
    n188 = nl.get("node188")
    w("### Stick in NLstep's states\n\n")
    if n188 is not None:
        st = n188["state"]
        lt = np.hypot(n188["lambda_t1_N"], n188["lambda_t2_N"])
        gt = np.hypot(n188["gamma_t1_mm_s"], n188["gamma_t2_mm_s"])
        ratio = lt / (MU * n188["lambda_n_N"])
        mk, ms = st == 1, st == 2
        nslip_rule = int(np.sum(ratio >= 1 - SLIP_TOL))
        w("Node 188 is the one node whose tangential forces and slip velocity "
          "NLstep's export holds (`nlstep_plausible_node188_contact.csv.gz`): "
          "%d closed samples, %d flagged stick and %d slip by NLstep. Stick-"
          "flagged: |λ_T|/(μ λ_n) ∈ [%.10f, %.10f], slip speed |γ_T| ∈ "
          "[%.4g, %.4g] mm/s. Slip-flagged: |λ_T|/(μ λ_n) ∈ [%.10f, %.10f], "
          "|γ_T| ∈ [%.4g, %.4g] mm/s. (r Ω at node 188: %.4g mm/s.) Every "
          "stick-flagged sample is on the Coulomb circle to the 10 digits of "
          "the export and slides as fast as the slip-flagged ones: the split "
          "is decided below the export's resolution, by NLstep's strict test "
          "|λ_T| ≥ μ λ_n at the edge of the disc (its solver tolerance is "
          "1e−6). The rsi rule above "
          "(slip if |λ_T| ≥ μ λ_n (1 − 1e−9)) calls %d of these %d samples "
          "slip.\n\n" % (
              len(st), mk.sum(), ms.sum(), ratio[mk].min(), ratio[mk].max(),
              gt[mk].min(), gt[mk].max(), ratio[ms].min(), ratio[ms].max(),
              gt[ms].min(), gt[ms].max(), 623.104 * OMEGA, nslip_rule, len(st)))
    rr = rs["ratio_closed"]
    w("rsi: all %d closed node-samples have √(λ_t1² + λ_t2²)/(μ λ_n) in "
      "[%.16f, %.16f]; its own certificate (`summary.json`) counts %s stick "
      "and %s slip contact-steps. So rsi has no sticking contact in this "
      "run, and at node 188 NLstep's stick flags mark sliding samples; "
      "NLstep's export has no tangential data for the other 15 nodes.\n\n" % (
          len(rr), rr.min(), rr.max(),
          rs.get("summary", {}).get("stick_contact_steps", "?"),
          rs.get("summary", {}).get("slip_contact_steps", "?")))

    w(discussion(c))
    return "".join(L)


def _aperiodic(s, k=1000):
    """max |u(t) - u(t - T)| over revolutions 41-50 (k samples a revolution)."""
    m = np.where(window_mask(s["t"], 40, 50))[0]
    m = m[m >= k]
    return float(np.max(np.abs(s["u"][m] - s["u"][m - k])))


def _ranges(v):
    """[3, 4, 5, 9] -> '3-5, 9'."""
    out, start = [], None
    for i, x in enumerate(v):
        if start is None:
            start = x
        if i == len(v) - 1 or v[i + 1] != x + 1:
            out.append("%d" % start if start == x else "%d-%d" % (start, x))
            start = None
    return ", ".join(out) if out else "none"


def discussion(c):
    R, err, prev, ss, cst, sp = c["R"], c["err"], c["prev"], c["ss"], c["cst"], c["sp"]
    nl, rs = R["nlstep"], R["rsi"]
    cn, cr = cst["nlstep"], cst["rsi"]
    E = lambda a, b, wdw=50, k=0: err[(a, b)][WINDOWS.index(wdw)][k]
    have = lambda a, b: (a, b) in err
    L = []
    w = L.append

    # ------------------------------------------------------------ how close
    w("## How close\n\n")
    w("- Response over the 50 revolutions, rsi 1000/rev against NLstep "
      "1000/rev: e₂ = %.4f, e_∞ = %.4f. Over 0.5, 1, 2, 5, 10, 20, 50 "
      "revolutions e₂ = %s.\n" % (
          E("rsi", "nlstep"), E("rsi", "nlstep", 50, 1),
          ", ".join("%.4f" % v[0] for v in err[("rsi", "nlstep")])))
    if have("former", "nlstep"):
        w("- With the former sliding sign (`with_rotation`): e₂ = %.3f over "
          "the 50 revolutions, steady mean %.3f mm against NLstep's %.3f mm, "
          "largest spectral line at %.0f f_rev instead of %.0f f_rev.\n" % (
              E("former", "nlstep"), ss["former"]["mean"], ss["nlstep"]["mean"],
              top_lines(*sp["former"][:2])[0][0] * T_REV,
              top_lines(*sp["nlstep"][:2])[0][0] * T_REV))
    w("- Steady state (last 5 revolutions), rsi relative to NLstep: mean "
      "%+.2f %%, min %+.2f %%, max %+.2f %%, RMS %+.2f %%, std %+.2f %%.\n"
      % tuple(100 * _rel(ss["rsi"][k], ss["nlstep"][k])
              for k in ("mean", "min", "max", "rms", "std")))
    t1, t2 = top_lines(*sp["nlstep"][:2]), top_lines(*sp["rsi"][:2])
    w("- Spectrum: the same five largest lines, at %s f_rev in NLstep and "
      "%s f_rev in rsi; the largest, %.2f Hz = 2 f_rev (2Ω/2π), is %.4f mm "
      "in NLstep and %.4f mm in rsi (%+.2f %%).\n" % (
          ", ".join("%.0f" % (x * T_REV) for x, _ in t1),
          ", ".join("%.0f" % (x * T_REV) for x, _ in t2),
          t1[0][0], t1[0][1], t2[0][1], 100 * _rel(t2[0][1], t1[0][1])))
    w("- Contact, rsi relative to NLstep: first contact at the same instant "
      "(%.3f rev); instants with contact %+.2f %%; closed "
      "node-samples %+.2f %%; max Σλ_n %+.2f %%; max per-node λ_n %+.2f %%; "
      "normal impulse over 50 revolutions %+.2f %%, over the first half "
      "revolution %+.2f %%.\n\n" % (
          cr["first_contact_rev"],
          100 * _rel(cr["steps_contact"], cn["steps_contact"]),
          100 * _rel(cr["closed"], cn["closed"]),
          100 * _rel(cr["max_sum"], cn["max_sum"]),
          100 * _rel(cr["max_lam"], cn["max_lam"]),
          100 * _rel(cr["impulse"], cn["impulse"]),
          100 * _rel(cr["impulse_first_half"], cn["impulse_first_half"])))

    # ------------------------------------------------------- why not closer
    w("## Why not closer\n\n")
    if have("rsi", "fine"):
        w("**1. rsi's step is not the cause.** rsi at 1000 against 2000 steps a "
          "revolution: e₂ = %.4f over the 50 revolutions. rsi 2000/rev against "
          "NLstep 1000/rev: e₂ = %.4f (rsi 1000/rev: %.4f).\n\n" % (
              E("rsi", "fine"), E("fine", "nlstep"), E("rsi", "nlstep")))
    w("**2. What else is the same.** Both codes use the same ccx matrices "
      "and a MacNeal ROM with 50 free-interface modes: NLstep's highest "
      "kept frequency is ω₅₀ = %s rad/s (`nlstep_plausible_rom_frequencies.csv`), "
      "rsi's ω_max %s rad/s (`summary.json`). Both put 2ζω_j on the modal "
      "coordinates and none on the boundary, step the modes with the same "
      "leapfrog (central differences, damping centred) and solve the "
      "massless boundary statically at every time level, and start from "
      "rest. Before the first contact (%d samples) max|u| is %g mm in "
      "NLstep and %g mm in rsi.\n\n" % (
          c.get("nl_omega50", "?"), c.get("rsi_omega_max", "?"),
          c["pre"][0], c["pre"][1], c["pre"][2]))
    w("**3. The contact formulations differ.** NLstep (`sim_contact3D.m`) "
      "decides which contacts are active from the predicted gap (line 571: "
      "open if `gpre > 0` and the previous λ_n ≤ 0) and imposes, on the "
      "active ones, the Signorini–Coulomb conditions on the velocity level: "
      "γ_n = u̇_b,n + ġ_imp = 0 while λ_n > 0 (augmented-Lagrangian "
      "projected Jacobi, relative tolerance 1e−6). A contact therefore "
      "closes at the gap of the last open step (between 0 and one step's "
      "approach) and keeps that gap, changed only by the discrete "
      "integration of γ_n, while it stays closed. rsi imposes the "
      "displacement-level conditions (g ≥ 0, λ_n ≥ 0, g λ_n = 0) at every "
      "step. In the data:\n\n")
    rows = []
    for k in ("nlstep", "nlstep_fine", "nlstep_finer", "rsi", "fine"):
        if k in cst:
            x = cst[k]
            fg = lambda v: ("%+.4f (%.1f %%)" % (v, 100 * v / G_M)) if abs(v) > 1e-6 \
                else "%+.1e" % v
            rows.append([SHORT[k], fg(x["min_gap"]), fg(x["max_gap_closed"]),
                         "%d of %d (%.0f %%)" % (x["closed_gap_pos"], x["closed"],
                                                  100.0 * x["closed_gap_pos"] / x["closed"])])
    w(table(["run", "min gap [mm] (% of g_m)", "max gap of a closed node [mm] (% of g_m)",
             "closed node-samples with g > 1e−6 mm"], rows))
    w("\nNLstep's penetration reaches %.4f mm (%.1f %% of g_m), and most "
      "of its closed node-samples sit at a positive gap, up to %+.4f mm "
      "(%.1f %% of g_m): it carries normal force across an open gap. rsi's "
      "gap while closed stays within [%.1e, %.1e] mm.\n\n" % (
          cn["min_gap"], 100 * abs(cn["min_gap"]) / G_M,
          cn["max_gap_closed"], 100 * cn["max_gap_closed"] / G_M,
          cr["min_gap"], cr["max_gap_closed"]))
    fi = c.get("first_info")
    if fi:
        w("The first closing (the table of node %s above) shows the "
          "mechanism: NLstep closes node %s at g = %+.6f mm (its last open "
          "step had %+.6f mm) and keeps it there; its first force is %.0f N "
          "against rsi's %.0f N at g = 0 (%+.0f %%)%s.\n\n" % (
              fi["node"], fi["node"], fi["g_nl"], fi["g_prev"], fi["lam_nl"],
              fi["lam_rs"], 100 * _rel(fi["lam_nl"], fi["lam_rs"]),
              ("; NLstep's force falls below rsi's %d steps later" % fi["cross"])
              if fi["cross"] is not None else ""))
    w("NLstep has more contact than rsi by every measure in the contact "
      "table (NLstep relative to rsi: instants with contact %+.1f %%, closed "
      "node-samples %+.1f %%, max per-node λ_n %+.1f %%, max Σλ_n %+.1f %%, "
      "normal impulse %+.1f %%) and a larger steady response (max %+.1f %%, "
      "mean %+.1f %%), consistent in direction with a contact that closes "
      "early and holds force across an open gap.\n\n" % (
          100 * _rel(cn["steps_contact"], cr["steps_contact"]),
          100 * _rel(cn["closed"], cr["closed"]),
          100 * _rel(cn["max_lam"], cr["max_lam"]),
          100 * _rel(cn["max_sum"], cr["max_sum"]),
          100 * _rel(cn["impulse"], cr["impulse"]),
          100 * _rel(ss["nlstep"]["max"], ss["rsi"]["max"]),
          100 * _rel(ss["nlstep"]["mean"], ss["rsi"]["mean"])))
    if "nlstep_fine" in R:
        w(NLSTEP_STEP_TEXT(c, E, have))
    w(MU0_TEXT(c))
    prv = prev[("rsi", "nlstep")]
    imax = int(np.argmax(prv))
    sh5, sh10 = c["shift_last5"], c["shift_10_20"]
    w("**Growth of e₂ with the window.** e₂ of rsi 1000/rev against NLstep "
      "1000/rev is %.4f over the first half revolution and %.4f over the "
      "first; per revolution it rises to %.4f in revolution %d and is "
      "%.4f-%.4f over revolutions 31-50, so the cumulative e₂ rises to "
      "%.4f at 20 revolutions and falls to %.4f at 50. It is not a growing "
      "phase drift: the best integer time shift of rsi's history against "
      "NLstep's is %d samples over revolutions 46-50 (e₂ %.4f) and %d "
      "samples over revolutions 11-20 (e₂ %.4f). The difference is one of "
      "amplitude and waveform; per revolution e₂ exceeds 0.05 in "
      "revolutions %s and in none after. "
      "Neither response is exactly periodic: over revolutions 41-50, "
      "max|u(t) − u(t − T)| is %.3f mm in NLstep and %.3f mm in rsi.\n\n"
      % (E("rsi", "nlstep", 0.5), E("rsi", "nlstep", 1), prv[imax], imax + 1,
         prv[30:].min(), prv[30:].max(), E("rsi", "nlstep", 20),
         E("rsi", "nlstep", 50), sh5[1], sh5[0], sh10[1], sh10[0],
         _ranges(np.where(prv > 0.05)[0] + 1), _aperiodic(nl), _aperiodic(rs)))

    w(SUMMARY_TEXT(c, E))

    # --------------------------------------------------------------- timings
    t_nl, t_nl_cpu = _nl_timing(nl)
    t_rs = _timing(rs)
    w("## Timings\n\n")
    if t_nl is None:
        t_nl, t_nl_cpu = float("nan"), float("nan")
    w("- NLstep 1000/rev, integration alone (the `sim_contact3D` call, "
      "tic/toc in the driver): %.1f s wall (%.1f s CPU), one thread, GNU "
      "Octave 7.3.0. The whole example script (FE import, ROM with `eigs`, "
      "integration, plots, `anim.frd`): 103.6 s.\n" % (t_nl, t_nl_cpu))
    if t_rs:
        w("- rsi MacNeal-50, 1000/rev: `integration_seconds` %.2f s "
          "(`summary.json`; the CLI records every sample and checks the "
          "energy balance at each), basis %.1f s.\n" % (
              t_rs, rs["summary"].get("basis_seconds", float("nan"))))
        w("- Ratio in this run: %.1f s / %.2f s = %.0fx. Each side was "
          "timed once, on a shared 2-core virtual machine; "
          "`bench/RESULTS.md` holds the benchmark medians for rsi.\n" % (
              t_nl, t_rs, t_nl / t_rs))
    extra = []
    for k in ("nlstep_fine", "nlstep_finer"):
        if k in R:
            a, b = _nl_timing(R[k])
            if a:
                extra.append("%s %.1f s wall (%.1f s CPU)" % (SHORT[k], a, b))
    if extra:
        w("- The refined NLstep runs, integration alone: %s; measured while "
          "other processes loaded the machine (load average 4-10), for "
          "orientation only.\n" % "; ".join(extra))
    w("\n")
    return "".join(L)


def NLSTEP_STEP_TEXT(c, E, have):
    R, err, prev, ss, cst = c["R"], c["err"], c["prev"], c["ss"], c["cst"]
    ref = "fine" if "fine" in R else "rsi"
    keys = [k for k in ("nlstep", "nlstep_fine", "nlstep_finer") if k in R]
    L = []
    w = L.append
    w("**4. NLstep's step.** NLstep was rerun at %s steps a revolution (its "
      "example with only `numberOfTimeStepsPerRevolution` changed: "
      "`STEPS_PER_REV` of `driver/setup_and_run.sh`), recorded at the same "
      "instants. Against %s (rsi's most resolved run; rsi 1000/rev differs "
      "from it by e₂ = %.4f):\n\n" % (
          " and ".join({"nlstep_fine": "2000", "nlstep_finer": "4000"}[k]
                       for k in keys[1:]), SHORT[ref],
          E("rsi", "fine") if "fine" in R else 0.0))
    rows = []
    for k in keys:
        a = e2(R[k]["u"], R[ref]["u"], window_mask(R[ref]["t"], 0, 50))
        pr = per_rev_e2(R[k], R[ref])
        x, y = cst[k], cst[ref]
        rows.append([SHORT[k], "%.4f" % a,
                     " / ".join("%.4f" % pr[r - 1] for r in (1, 5, 13, 20, 35, 50)),
                     "%+.3f" % (ss[k]["max"] - ss[ref]["max"]),
                     "%+.3f" % (ss[k]["mean"] - ss[ref]["mean"]),
                     "%+.0f" % (x["max_lam"] - y["max_lam"]),
                     "%+.0f" % (x["max_sum"] - y["max_sum"]),
                     "%+.1f" % (x["impulse"] - y["impulse"]),
                     "%+d" % (x["steps_contact"] - y["steps_contact"])])
    w(table(["NLstep run", "e₂, 50 rev", "e₂ in revolutions 1 / 5 / 13 / 20 / 35 / 50",
             "Δ max, last 5 rev [mm]", "Δ mean, last 5 rev [mm]",
             "Δ max per-node λ_n [N]", "Δ max Σλ_n [N]", "Δ impulse [N s]",
             "Δ instants with contact"], rows))
    w("\nΔ = NLstep − %s. NLstep against itself: " % SHORT[ref])
    sel = [(a, b) for a, b in (("nlstep", "nlstep_fine"), ("nlstep_fine", "nlstep_finer"))
           if (a, b) in err]
    w("; ".join("%s vs %s e₂ = %.4f over 50 revolutions (revolution 13: %.4f, "
                "revolution 50: %.4f)" % (SHORT[a], SHORT[b], E(a, b),
                                          prev[(a, b)][12], prev[(a, b)][49])
                for a, b in sel))
    w(".\n\n")
    # what follows NLstep's step and what does not
    ks = keys
    g0, g1 = cst[ks[0]], cst[ks[-1]]
    e_last = e2(R[ks[-1]]["u"], R[ref]["u"], window_mask(R[ref]["t"], 0, 50))
    p0, p1 = per_rev_e2(R[ks[0]], R[ref]), per_rev_e2(R[ks[-1]], R[ref])
    w("From %s to %s (a step %d times smaller) NLstep's penetration falls from "
      "%.4f to %.4f mm and its largest positive gap under load from %.4f to "
      "%.4f mm, and NLstep's own histories converge (e₂ between successive "
      "refinements %s). Its steady statistics move towards rsi's (Δ mean "
      "%+.3f → %+.3f mm, Δ max %+.3f → %+.3f mm), and so does the end of the "
      "run (e₂ in revolution 50: %.4f → %.4f). Not every measure does: "
      "the peak total normal force goes %s N (rsi %.0f N). And e₂ against rsi over the "
      "50 revolutions goes %s, and in revolutions 5, 13 and 20 it goes %s: "
      "it does not fall with the step as the gap offsets do. The "
      "penetration and the gap offsets of NLstep's velocity-level contact "
      "at its default step therefore explain part of the difference (the "
      "steady level and the late revolutions), not the e₂ ≈ %.3f that "
      "remains with them %.0f-%.0f times smaller.\n\n" % (
          SHORT[ks[0]], SHORT[ks[-1]],
          {"nlstep": 1, "nlstep_fine": 2, "nlstep_finer": 4}[ks[-1]],
          g0["min_gap"], g1["min_gap"], g0["max_gap_closed"], g1["max_gap_closed"],
          ", ".join("%.4f" % E(a, b) for a, b in sel),
          ss[ks[0]]["mean"] - ss[ref]["mean"], ss[ks[-1]]["mean"] - ss[ref]["mean"],
          ss[ks[0]]["max"] - ss[ref]["max"], ss[ks[-1]]["max"] - ss[ref]["max"],
          p0[49], p1[49],
          " → ".join("%.0f" % cst[k]["max_sum"] for k in ks), cst[ref]["max_sum"],
          " → ".join("%.4f" % e2(R[k]["u"], R[ref]["u"], window_mask(R[ref]["t"], 0, 50))
                     for k in ks),
          "; ".join(" → ".join("%.4f" % per_rev_e2(R[k], R[ref])[r - 1] for k in ks)
                    for r in (5, 13, 20)),
          e_last,
          min(g0["min_gap"] / g1["min_gap"], g0["max_gap_closed"] / g1["max_gap_closed"]),
          max(g0["min_gap"] / g1["min_gap"], g0["max_gap_closed"] / g1["max_gap_closed"])))
    return "".join(L)


def SUMMARY_TEXT(c, E):
    """What the data says about the explanation 'rsi is converged, the rest
    is the contact formulation (NLstep's velocity level, penetration)'."""
    R, cst = c["R"], c["cst"]
    if not ("fine" in R and "nlstep_finer" in R and c["mu0"]):
        return ""
    ref = R["fine"]
    ks = [k for k in ("nlstep", "nlstep_fine", "nlstep_finer") if k in R]
    e50 = [e2(R[k]["u"], ref["u"], window_mask(ref["t"], 0, 50)) for k in ks]
    e2r = [e2(R[k]["u"], ref["u"], window_mask(ref["t"], 0, 2)) for k in ks]
    rr = [x for x in c["mu0"] if x["code"] == "rsi"]
    r0 = max(rr, key=lambda x: x["spr"])
    nls = sorted([x for x in c["mu0"] if x["code"] == "NLstep"], key=lambda x: x["spr"])
    m0 = [e2(x["u"], r0["u"], window_mask(r0["t"], 0, 2)) for x in nls]
    return (
        "**In short.** rsi is converged in its step (1000 against 2000 steps "
        "a revolution: e₂ = %.4f). NLstep's contact is enforced on the "
        "velocity level; at its default step its penetration reaches %.4f mm "
        "and its gap under load %+.4f mm. These offsets shrink with its step "
        "(%.4f and %+.4f mm at 4000 steps a revolution), and with them the "
        "differences in the steady level and the late revolutions. Without "
        "friction NLstep converges to rsi (e₂ over 2 revolutions %s at 1000, "
        "2000, 4000 steps a revolution). With friction it does not: e₂ over "
        "2 revolutions %s, over 50 revolutions %s. So the explanation \"rsi "
        "is converged, the rest is NLstep's velocity-level contact with its "
        "penetration\" holds for the part that depends on NLstep's step. The "
        "larger part, e₂ ≈ %.2f over the 50 revolutions at every NLstep step "
        "tried, does not depend on it; over the first 2 revolutions the "
        "step-independent difference appears only with friction. Its cause "
        "is not identified by these runs.\n\n" % (
            E("rsi", "fine"), cst["nlstep"]["min_gap"], cst["nlstep"]["max_gap_closed"],
            cst[ks[-1]]["min_gap"], cst[ks[-1]]["max_gap_closed"],
            ", ".join("%.4f" % v for v in m0), ", ".join("%.4f" % v for v in e2r),
            ", ".join("%.4f" % v for v in e50), min(e50)))


def MU0_TEXT(c):
    """The frictionless short runs against the most resolved rsi one."""
    runs = c["mu0"]
    R = c["R"]
    rr = [x for x in runs if x["code"] == "rsi"]
    if not rr or len(runs) < 2:
        return ""
    ref = max(rr, key=lambda x: x["spr"])
    nrev = int(round(ref["t"][-1] / T_REV))
    wins = [x for x in (0.5, 1, 2, 5) if x <= nrev]
    refF = R["fine"] if "fine" in R else R["rsi"]
    stepkey = {1000: "nlstep", 2000: "nlstep_fine", 4000: "nlstep_finer"}
    rows = []
    dt = ref["t"][1] - ref["t"][0]
    mh = window_mask(ref["t"], 0, 0.5)
    for x in sorted(runs, key=lambda x: (x["code"], x["spr"])):
        if len(x["t"]) != len(ref["t"]) or np.max(np.abs(x["t"] - ref["t"])) > 1e-6 * T_REV:
            raise SystemExit("%s: not at the instants of %s" % (x["path"], ref["path"]))
        if x is ref:
            e0 = ["(reference)"] * len(wins)
        else:
            e0 = ["%.4f" % e2(x["u"], ref["u"], window_mask(ref["t"], 0, w)) for w in wins]
        k = stepkey.get(x["spr"]) if x["code"] == "NLstep" else None
        if x["code"] == "rsi":
            k = "fine" if x["spr"] == 2000 and "fine" in R else ("rsi" if x["spr"] == 1000 else None)
        if k in R and R[k] is not refF:
            e1 = ["%.4f" % e2(R[k]["u"], refF["u"], window_mask(refF["t"], 0, w)) for w in wins]
        else:
            e1 = ["(reference)" if R.get(k) is refF else ""] * len(wins)
        rows.append(["%s %d/rev" % (x["code"], x["spr"])] + e0 + e1 +
                    ["%.4f" % (np.sum(x["sumlam"][mh]) * dt)])
    hdr = (["run"] + ["μ = 0: e₂ %g rev" % w for w in wins] +
           ["μ = 0.15: e₂ %g rev" % w for w in wins] + ["μ = 0: ∫Σλ_n dt, first half rev [N s]"])
    L = []
    w = L.append
    w("**5. Without friction.** To separate the normal contact law from "
      "friction, both codes were rerun over %d revolutions with μ = 0 "
      "(NLstep: `MU=0 REVOLUTIONS=%d DRIVER=response` of "
      "`driver/setup_and_run.sh`, i.e. the example's lines 103 and 190 "
      "edited, files `nlstep_mu0_*.csv.gz`; rsi: the case with "
      "`friction_coefficient` 0 and `revolutions` %d). e₂ against %s "
      "(μ = 0) and, for comparison, the same windows of the μ = 0.15 runs "
      "against %s:\n\n" % (nrev, nrev, nrev, "rsi %d/rev" % ref["spr"], SHORT[refF["key"]]))
    w(table(hdr, rows))
    nls = sorted([x for x in runs if x["code"] == "NLstep"], key=lambda x: x["spr"])
    if len(nls) >= 2:
        wl = wins[-1]
        a = [e2(x["u"], ref["u"], window_mask(ref["t"], 0, wl)) for x in nls]
        b = []
        for x in nls:
            k = stepkey.get(x["spr"])
            if k in R:
                b.append(e2(R[k]["u"], refF["u"], window_mask(refF["t"], 0, wl)))
        imp = [np.sum(x["sumlam"][mh]) * dt for x in nls]
        w("\nWithout friction NLstep converges to rsi as its step is refined: "
          "over %g revolutions e₂ = %s at %s steps a revolution (a factor "
          "%s per halving, as for a first-order error), and its normal impulse of the "
          "first closing approaches rsi's (%s against %.4f N s). With friction "
          "the same windows give e₂ = %s: they do not shrink. Over these "
          "revolutions, the part of the difference that does not go away "
          "with NLstep's step comes with friction. These runs do not show which difference in the frictional "
          "contact causes it: both codes use the same frame (e_t2 = e_n × e_t1), "
          "the same slip (the node's tangential velocity plus (0, −r Ω) in "
          "(t1, t2); rsi: its increment over the step, `reduced/rigid_casing.hpp`) "
          "and Coulomb's law opposing it.\n\n" % (
              wl, ", ".join("%.4f" % v for v in a),
              ", ".join("%d" % x["spr"] for x in nls),
              ", ".join("%.1f" % (a[i] / a[i + 1]) for i in range(len(a) - 1)),
              ", ".join("%.4f" % v for v in imp),
              np.sum(ref["sumlam"][mh]) * dt,
              ", ".join("%.4f" % v for v in b)))
    return "".join(L)


HEADER = """# Rotor 37 blade/casing rubbing: rsi against NLstep

Generated by `reports/compare_nlstep.py` (the sections "What was run" and
"Sign conventions" are its fixed text; everything from "Results" on is
computed by it). Command:

```
{cmd}
```

"""

RUN_SECTION = """## What was run

The case: NASA Rotor 37 blade, CalculiX model of NLstep's example
(`../shared/external/rotor37/README.md`): 61,098 dofs, 16 tip contact nodes
(48 boundary dofs), oval rigid casing g_m = 0.356 mm, μ = 0.15, Ω = 1344
rad/s, 0.5 % modal damping on the 50 kept modes and none on the boundary,
zero initial conditions, 50 revolutions at 1000 steps a revolution (Δt =
4.674989068e−6 s), response node 1353 direction 2 (global y, mm).

**NLstep** (Monjaraz-Tec, Gross, Krack, Comput. Struct. 260 (2022) 106698):
its own example `EXAMPLES/03_bladeCasingRubbing/bladeCasingRubbing.m`,
unmodified, `CONFIG = 'PLAUSIBLE'`, MacNeal (MCN) ROM with 50
free-interface modes (98 coordinates), run under GNU Octave 7.3.0 (Debian),
CalculiX ccx 2.20 for the matrices, one thread.

| code | source | commit |
|---|---|---|
| NLstep | github.com/maltekrack/NLstep | `bba497dadf90a93d1677a811efcad47f28b40b82` (2025-06-17) |
| NLvib | upstream NLvib commit as held by the fork github.com/julianjurai/NLvib-py (the stored snapshot of maltekrack/NLvib ends 2024-02-22 and lacks `CMS_ROM.m` and `FEmodel.m`, which NLstep needs) | `c7e90068784cf498a45542521a9a1489fd659420` (Malte Krack, 2025-06-17) |

**The one code change, in NLvib** (`SRC/MechanicalSystems/CMS_ROM.m`, MCN
branch, line 289): `[~,ind] = sort(om); PHI = PHI(:,ind);` becomes
`[om,ind] = sort(om); PHI = PHI(:,ind);`. Octave 7.3's `eigs(K,M,nm,'sm')`
returns the eigenvalues in descending order (MATLAB's come ascending). The
original line sorts the mode shapes but not `om`, so mode j would be paired
with ω₅₁₋ⱼ in the reduced stiffness and in the residual flexibility. The CB
branch of the same file already sorts `om` with the shapes. After the fix the
ROM's frequencies equal ccx's Lanczos frequencies (312.1227, 922.8062, ...
Hz), and `driver/check_rom_vs_fe.m` finds the ROM equal to the full FE model
to 1.2e−10 (relative) in statics, 8.3e−7 at 200 Hz and 1.6e−5 at 600 Hz at
node 1353-y and the 48 contact dofs. NLstep itself runs unchanged.

**rsi**: `rsi simulate` with MacNeal's method and 50 modes on the same ccx
matrices (case `data/cases/rotor37-rubbing.json`, `"tip_sliding":
"against_rotation"`, NLstep's sliding sign). The repository's HEAD
when the rsi runs were made (2026-11-27, 05:21-05:25 UTC) was `4290ec5`;
the working tree then also held uncommitted edits of
`reference/model/case_file.{cpp,hpp}`. The frictionless rsi runs (05:46)
used the same binary.

### Reproduce

NLstep side (`driver/` here; pass git directories of NLstep and of the
NLvib fork, e.g. from `git clone --bare`; the scripts download nothing):

```
bash reports/nlstep-rotor37/driver/setup_and_run.sh NLSTEP_GIT NLVIB_GIT WORK
#   extracts NLstep bba497d and NLvib c7e9006 (NLvib's SRC into NLstep/SRC/NLvib),
#   applies the one-line CMS_ROM.m fix with sed, runs ccx on a copy of
#   ../shared/external/rotor37/blade.{inp,msh} (R37_DECK_DIR overrides),
#   checks blade.dof against NLstep's, runs driver/run_rotor37_plausible.m
#   -> WORK/out/*.csv, summary.txt (the integration timed with tic/toc)
STEPS_PER_REV=2000 bash reports/nlstep-rotor37/driver/setup_and_run.sh NLSTEP_GIT NLVIB_GIT WORK2000
STEPS_PER_REV=4000 bash reports/nlstep-rotor37/driver/setup_and_run.sh NLSTEP_GIT NLVIB_GIT WORK4000
/usr/bin/python3 reports/compare_nlstep.py --pack WORK/out --out reports/nlstep-rotor37
/usr/bin/python3 reports/compare_nlstep.py --pack WORK2000/out --pack-every 2 --pack-no-node188 \\
    --pack-name nlstep_plausible_2000 --out reports/nlstep-rotor37
/usr/bin/python3 reports/compare_nlstep.py --pack WORK4000/out --pack-every 4 --pack-no-node188 \\
    --pack-name nlstep_plausible_4000 --out reports/nlstep-rotor37
# frictionless, 2 revolutions, at 1000, 2000, 4000 steps/rev:
MU=0 REVOLUTIONS=2 STEPS_PER_REV=1000 DRIVER=response \\
    bash reports/nlstep-rotor37/driver/setup_and_run.sh NLSTEP_GIT NLVIB_GIT WORKMU0_1000
/usr/bin/python3 reports/compare_nlstep.py --pack-response WORKMU0_1000/out/response_short.csv \\
    --pack-every 1 --pack-name nlstep_mu0_1000 --out reports/nlstep-rotor37
#   (likewise 2000 and 4000 with --pack-every 2 and 4)
```

The 1000 steps/rev files were packed from the Octave run described in
`nlstep_plausible_summary.txt` (the integration alone: 52.6 s). The 2000
and 4000 steps/rev runs were made for this report with the same prepared
tree and driver, with the example's line 191
(`numberOfTimeStepsPerRevolution = 1e3;`) edited in the working copy,
which is what `STEPS_PER_REV` does; the frictionless runs also set
line 103 (`mu = 0;`) and line 190 (`numberOfRevolutions = 2;`) and used
`driver/run_rotor37_response.m`. ARPACK (`eigs`) starts from a random
vector, so a rerun's ROM differs at round-off: a rerun of the 1000
steps/rev case from the mirrors agreed with the committed response to
5.1e−11 mm, and a fresh `setup_and_run.sh` (extraction from the mirrors, the
sed fix, ccx, `MU=0 REVOLUTIONS=2 DRIVER=response`) reproduced the
frictionless 1000 steps/rev response to 2.0e−12 mm.

rsi side (the two variants are the case with one or two keys changed; the
deck path is made absolute because the copies live elsewhere):

```
build/cli/rsi simulate data/cases/rotor37-rubbing.json --method macneal --modes 50 --out /work/scratch/r37-mn50-nlstep
/usr/bin/python3 -c "
import json, os
c = json.load(open('data/cases/rotor37-rubbing.json'))
c['component']['source']['calculix_deck'] = os.path.abspath('../shared/external/rotor37/blade.inp')
c['rubbing']['tip_sliding'] = 'with_rotation'
json.dump(c, open('/work/scratch/r37-with.json', 'w'), indent=1)
c['rubbing']['tip_sliding'] = 'against_rotation'
c['rubbing']['steps_per_revolution'] = 2000
c['rubbing']['output_every'] = 2
json.dump(c, open('/work/scratch/r37-2000.json', 'w'), indent=1)
c['rubbing']['friction_coefficient'] = 0.0
c['rubbing']['revolutions'] = 2
json.dump(c, open('/work/scratch/r37-mu0-2000.json', 'w'), indent=1)
c['rubbing']['steps_per_revolution'] = 1000
del c['rubbing']['output_every']
json.dump(c, open('/work/scratch/r37-mu0.json', 'w'), indent=1)"
build/cli/rsi simulate /work/scratch/r37-with.json --method macneal --modes 50 --out /work/scratch/r37-mn50-with
build/cli/rsi simulate /work/scratch/r37-2000.json --method macneal --modes 50 --out /work/scratch/r37-mn50-2000
# frictionless, 2 revolutions
build/cli/rsi simulate /work/scratch/r37-mu0.json --method macneal --modes 50 --out /work/scratch/r37-mn50-mu0
build/cli/rsi simulate /work/scratch/r37-mu0-2000.json --method macneal --modes 50 --out /work/scratch/r37-mn50-mu0-2000
```

Committed in this folder: `nlstep_plausible.csv.gz` (NLstep's per-step
response and contact summary, 10 significant digits: t_s, u_1353_2_mm,
n_contact, n_stick, n_slip, sum_lambda_n_N, and, so that the contact table
can be recomputed, max_lambda_n_N, min_gap_mm, max_gap_closed_mm,
n_closed_gap_pos), `nlstep_plausible_first_contact.csv` (λ_n and g of the
16 nodes around the first closing), `nlstep_plausible_node188_contact.csv.gz`
(node 188's closed samples: forces, slip velocity, state),
`nlstep_plausible_rom_frequencies.csv` and `nlstep_plausible_summary.txt`
(the driver's outputs, copied); the same, without node 188, for the 2000
and 4000 steps/rev runs (`nlstep_plausible_2000*`, `nlstep_plausible_4000*`,
every 2nd and 4th step); `nlstep_mu0_{1000,2000,4000}.csv.gz` (the
frictionless 2-revolution runs: response and Σλ_n); `driver/` (the two
Octave drivers, the ROM check, the set-up script; no NLstep or NLvib
source). The rsi histories (38 MB each)
are not committed; the commands above rewrite them.

"""

SIGN_SECTION = """## Sign conventions confirmed in NLstep's code

From `EXAMPLES/03_bladeCasingRubbing/bladeCasingRubbing.m` (NLstep
`bba497d`):

```
145            r = pos(1)+1i*pos(2);
146            radius_mm = abs(r);
147            phi_rad = angle(r);
153            en = [-pos(1);-pos(2);0]; en = en/norm(en);
154            et1 = [0;0;1];
155            et2 = cross(en,et1);
160            theta = @(t) Omrot_rad_s*t(:).' + phi_rad;
161            imposedGap = @(t) gmean_mm*(1-...
162                2*exp(-((mod(theta(t),pi)/pi-.5)/.15).^2));
164            imposedGapVelocity = @(t) [ ...
165                4*Omrot_rad_s*gmean_mm/(pi*.15)*(mod(theta(t),pi)/pi-.5)/.15.*...
166                exp(-((mod(theta(t),pi)/pi-.5)/.15).^2); ...
167                zeros(1,length(t)); ...
168                -radius_mm*Omrot_rad_s*ones(1,length(t))];
181 R = blkdiag(R{:},eye(bladeROM.n-3*nc));
182 apply_transform(bladeROM,R);
```

and `SRC/sim_contact3D.m`:

```
 13 %   K_bb * q_b + K_bi * q_i - lambda = fex_b(t),
 36 %   g = q_b + g_imp(t),
 37 %   gamma = u_b + gamma_imp(t),
566     gpre = qb_km1 + dt*ub_km12 + gimp(:,k);
571     isOpen = gpre(iN) > 0 & lamNpre <= 0;
598     c = Kbbdtinv*(fex_k(IB)-Kbi*qi_k) - qb_km1/dt + gamimp(:,k);
677     gam = Kbbdtinv*lam + c;
678     ub_km12 = gam - gamimp(:,k);
681     qb_k = qb_km1 + ub_km12*dt;
819     lamp = projC( lam -  epsAL.*(G*lam+c), mu, lam0);
```

- Frame per contact node: e_n = −(x, y, 0)/r (a displacement along e_n opens
  the gap), e_t1 = (0, 0, 1), e_t2 = e_n × e_t1 = (−sin φ, cos φ, 0).
- Gap g = q_b,n + g_imp(t), g_imp = g_m (1 − 2 exp(−((mod(θ, π)/π − 1/2)/0.15)²)),
  θ = Ω t + φ: a counter-clockwise gap phase for Ω > 0.
- Slip velocity γ = u_b + γ_imp with γ_imp = (ġ_imp, 0, −r Ω): a tip at rest
  slides at −r Ω e_t2 relative to the casing, the sliding of a clockwise
  rotor; friction (projection on the disc of radius μ λ_n, opposing γ_T)
  pushes the blade along +e_t2. In NLstep's run all 206,260 slip-flagged
  node-samples have λ_t2 > 0 and γ_t2 < 0, cos∠(λ_T, γ_T) ∈ [−1, −0.998].
- rsi's `"tip_sliding": "against_rotation"` reproduces this sliding with the
  same gap phase; `"with_rotation"` (the former default) reverses the
  casing's sliding (γ_imp,t2 = +r Ω).

"""


if __name__ == "__main__":
    main()
