#!/usr/bin/python3
"""Independent check of `rsi modes` against the exported matrices.

Reads DIR/bladed-disk/{K,M}.mtx written by `rsi export` with scipy, solves
the dense generalized eigenproblem with scipy.linalg.eigh (LAPACK dsygvd
through SciPy's own bindings, no code of rsi involved), and compares with
MODES/modes.csv from `rsi modes --count N`: frequencies to 1e-6 relative
(issue 2 acceptance), and the first family: 22 modes centred on 44 +- 0.5 Hz
with nodal diameters 0 and 11 once, 1..10 twice.

Usage: check_exported_modes.py EXPORT_DIR MODES_CSV
"""
import csv
import sys
from collections import Counter

import numpy as np
import scipy.io
import scipy.linalg

export_dir, modes_csv = sys.argv[1], sys.argv[2]
K = scipy.io.mmread(f"{export_dir}/bladed-disk/K.mtx").toarray()
M = scipy.io.mmread(f"{export_dir}/bladed-disk/M.mtx").toarray()
with open(f"{export_dir}/bladed-disk/dofs.csv") as f:
    dofs = list(csv.DictReader(f))
with open(modes_csv) as f:
    rows = list(csv.DictReader(f))

failures = []
passes = []
def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    (passes if ok else failures).append(what)

n_boundary = sum(int(d["boundary"]) for d in dofs)
check(K.shape == M.shape == (len(dofs), len(dofs)), f"K, M are {K.shape}, dofs.csv has {len(dofs)} rows")
check(n_boundary == 44, f"{n_boundary} boundary dofs (44 expected: tip u, v of 22 blades)")

w2 = scipy.linalg.eigh(K, M, eigvals_only=True)
f_scipy = np.sqrt(np.abs(w2[: len(rows)])) / (2 * np.pi)
f_rsi = np.array([float(r["frequency_hz"]) for r in rows])
rel = np.max(np.abs(f_rsi - f_scipy) / f_scipy)
# Issue 2 acceptance: agreement to 1e-6 relative.
check(rel <= 1e-6, f"max relative difference of the lowest {len(rows)} frequencies, rsi vs scipy: {rel:.3e} (<= 1e-6)")

first = rows[:22]
mean = np.mean([float(r["frequency_hz"]) for r in first])
check(abs(mean - 44.0) <= 0.5, f"first family mean {mean:.6f} Hz (44 +- 0.5 Hz)")
count = Counter(int(r["nodal_diameter"]) for r in first)
expected = {d: (1 if d in (0, 11) else 2) for d in range(12)}
check(dict(count) == expected, f"first family nodal diameters {dict(sorted(count.items()))}")
gap = float(rows[22]["frequency_hz"]) / float(rows[21]["frequency_hz"])
check(gap > 2.0, f"next frequency {float(rows[22]['frequency_hz']):.3f} Hz, {gap:.2f} times the top of the family")

print(f"{len(passes)} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
