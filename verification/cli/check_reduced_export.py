#!/usr/bin/python3
"""Issue 4 acceptance: the files of `rsi reduce` are consistent with those of
`rsi export`: T^T K T = K^ and T^T M T = M^ to 1e-10 relative (the products
in double precision: n eps ||T||^2 ||K|| against ||K^||, about 1e-12 here),
computed with scipy, nothing of rsi involved.

Usage: check_reduced_export.py EXPORT_DIR REDUCE_DIR
"""
import json
import sys

import numpy as np
import scipy.io

export_dir, reduce_dir = sys.argv[1], sys.argv[2]
K = scipy.io.mmread(f"{export_dir}/bladed-disk/K.mtx").tocsr()
M = scipy.io.mmread(f"{export_dir}/bladed-disk/M.mtx").tocsr()
T = scipy.io.mmread(f"{reduce_dir}/T.mtx").toarray()
K_hat = scipy.io.mmread(f"{reduce_dir}/K.mtx").toarray()
M_hat = scipy.io.mmread(f"{reduce_dir}/M.mtx").toarray()
with open(f"{reduce_dir}/basis.json") as f:
    basis = json.load(f)

passes, failures = 0, 0
def check(ok, what):
    global passes, failures
    print(("ok   " if ok else "FAIL ") + what)
    passes, failures = passes + ok, failures + (not ok)

check(T.shape == (K.shape[0], basis["reduced_dofs"]), f"T is {T.shape}, basis.json says {basis['reduced_dofs']} reduced dofs")
for name, full, reduced in (("K", K, K_hat), ("M", M, M_hat)):
    product = T.T @ (full @ T)
    error = np.abs(product - reduced).max() / np.abs(reduced).max()
    check(error <= 1e-10, f"max |T^T {name} T - {name}^| / max |{name}^| = {error:.3e} (<= 1e-10)")
print(f"{passes} passed, {failures} failed")
sys.exit(1 if failures else 0)
