#!/usr/bin/env python3
"""How well does a polynomial in Omega^2 hold ccx's prestressed stiffness?

Reads the ccx cache that `rsi modes CASE --speeds ...` (or --speed) filled:
the entries DECK-HASH-prestressed/ (the tangent K(Omega) after the nonlinear
centrifugal static step; Omega^2 read back from their job.inp) and the entry
DECK-HASH-matrices/ of the same model (K at rest). For each fit (Lagrange
interpolation of the matrices in s = Omega^2 through the fit speeds) and each
speed of the cache not among them, prints the relative error of the lowest
eigenvalues of the interpolated K against those of ccx's K at that speed
(same M: the prestressed step leaves it unchanged, checked here).

usage: fit_study.py CACHE_DIR DECK_STEM FIT_SPEEDS [FIT_SPEEDS ...]
  FIT_SPEEDS: comma-separated rad/s, e.g. 0,1000,2000
"""
import glob
import os
import sys

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as sla


def model_part(inp):
    text = open(inp).read()
    for marker in ("\n*NSET, NSET=RSI_ALL_NODES", "\n*STEP"):
        if marker in text:
            return text[: text.index(marker)]
    return text


def read_matrix(path, n):
    d = np.loadtxt(path)
    a = sp.coo_matrix((d[:, 2], (d[:, 0].astype(int) - 1, d[:, 1].astype(int) - 1)), shape=(n, n)).tocsc()
    return (a + a.T - sp.diags(a.diagonal())).tocsc()


def main():
    cache, stem, fits = sys.argv[1], sys.argv[2], [[float(w) for w in f.split(",")] for f in sys.argv[3:]]
    groups = {}
    for d in sorted(glob.glob(os.path.join(cache, stem + "-*-prestressed"))):
        for line in open(os.path.join(d, "job.inp")):
            if "CENTRIF" in line:
                speed = round(np.sqrt(float(line.split(",")[2])), 6)
                groups.setdefault(model_part(os.path.join(d, "job.inp")), {})[speed] = d
    rests = {model_part(os.path.join(d, "job.inp")): d
             for d in glob.glob(os.path.join(cache, stem + "-*-matrices"))}
    for model, entries in groups.items():
        if model in rests and len(entries) > 1:
            study(model, entries, rests[model], fits)


def study(model, entries, rest, fits):
    entries[0.0] = rest
    n = sum(1 for _ in open(os.path.join(rest, "job.dof")))
    K = {w: read_matrix(os.path.join(d, "job.sti"), n) for w, d in entries.items()}
    M = read_matrix(os.path.join(rest, "job.mas"), n)
    for w, d in entries.items():
        if w != 0.0:
            dm = abs(read_matrix(os.path.join(d, "job.mas"), n) - M).max()
            assert dm == 0.0, f"M differs at {w} rad/s by {dm}"
            break

    def lowest(k):
        return np.sort(sla.eigsh(k, k=6, M=M, sigma=0, which="LM", return_eigenvectors=False))

    exact = {w: lowest(K[w]) for w in sorted(K)}
    print(f"{n} dofs; speeds in the cache: {sorted(K)}")
    for w in sorted(K):
        print(f"  {w:7.1f} rad/s: f = {np.round(np.sqrt(np.abs(exact[w])) / (2 * np.pi), 2)} Hz")
    for nodes in fits:
        missing = [w for w in nodes if w not in K]
        if missing:
            print("fit", nodes, ": speeds not in the cache", missing)
            continue
        s = [w * w for w in nodes]
        for x in sorted(K):
            if x in nodes or x < min(nodes) or x > max(nodes):
                continue
            kx = None
            for i, wi in enumerate(nodes):
                li = np.prod([(x * x - s[j]) / (s[i] - s[j]) for j in range(len(nodes)) if j != i])
                kx = K[wi] * li if kx is None else kx + K[wi] * li
            err = lowest(kx) / exact[x] - 1
            print(f"fit through {nodes} at {x:7.1f} rad/s: lambda_fit/lambda_ccx - 1 = {np.round(err, 4)}")


if __name__ == "__main__":
    main()
