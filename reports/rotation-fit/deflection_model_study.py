#!/usr/bin/env python3
"""A parametric K(Omega) that holds: the tangent stiffness as a polynomial in
the static deflection's coordinates, not in Omega^2.

Total-Lagrangian solid elements have a tangent stiffness quadratic in the
displacement (the initial-displacement and initial-stress matrices), and the
spin softening and the centrifugal load stiffness are linear in s = Omega^2.
With the static deflection u(Omega) ~ V a(Omega) on m deflection shapes V
(ccx's deflections at the m highest fit speeds, orthonormalised),
  K(Omega) = K0 + sum_k a_k L_k + sum_{k<=l} a_k a_l Q_kl + s R,
m + m(m+1)/2 + 1 unknown matrices, fitted exactly at as many speeds.
a(Omega) at another speed: a cubic spline through the fit speeds (a(0) = 0),
in Omega or in s. Prints, at every speed of the cache not in the fit, the
relative error of the lowest eigenvalues against ccx's own K there, with a
taken from ccx's deflection there ("exact a") and from the spline.

Reads the ccx cache as fit_study.py does (the DECK-HASH-prestressed entries
`rsi modes --speeds` leaves, and the DECK-HASH-matrices entry at rest).
usage: deflection_model_study.py CACHE_DIR DECK_STEM M FIT_SPEEDS
  FIT_SPEEDS: comma-separated rad/s, ascending, M + M(M+1)/2 + 1 of them
"""
import glob
import os
import sys

import numpy as np
import scipy.sparse.linalg as sla
from scipy.interpolate import CubicSpline

from fit_study import model_part, read_matrix  # this script's folder


def deflection(entry, dofs):
    lines = open(os.path.join(entry, "job.dat")).read().split("\n")
    start = max(i for i, line in enumerate(lines) if "displacements (vx" in line)
    u = {}
    for line in lines[start + 1:]:
        f = line.split()
        if len(f) == 4:
            u[int(f[0])] = [float(x) for x in f[1:]]
        elif u and line.strip():
            break
    return np.array([u.get(node, [0.0, 0.0, 0.0])[direction - 1] for node, direction in dofs])


def main():
    cache, stem, m = sys.argv[1], sys.argv[2], int(sys.argv[3])
    fit = [float(w) for w in sys.argv[4].split(",")]
    if len(fit) != m + m * (m + 1) // 2 + 1:
        sys.exit(f"M = {m} needs {m + m * (m + 1) // 2 + 1} fit speeds")
    groups = {}
    for d in glob.glob(os.path.join(cache, stem + "-*-prestressed")):
        for line in open(os.path.join(d, "job.inp")):
            if "CENTRIF" in line:
                groups.setdefault(model_part(os.path.join(d, "job.inp")), {})[
                    round(np.sqrt(float(line.split(",")[2])), 6)] = d
    rests = {model_part(os.path.join(d, "job.inp")): d for d in glob.glob(os.path.join(cache, stem + "-*-matrices"))}
    for model, entries in groups.items():
        if model in rests and all(w in entries for w in fit):
            study(entries, rests[model], m, fit)


def study(entries, rest, m, fit):
    dofs = [tuple(int(x) for x in line.split(".")) for line in open(os.path.join(rest, "job.dof")) if line.strip()]
    n = len(dofs)
    speeds = sorted(entries)
    K = {0.0: read_matrix(os.path.join(rest, "job.sti"), n)}
    M = read_matrix(os.path.join(rest, "job.mas"), n)
    U = {0.0: np.zeros(n)}
    for w in speeds:
        K[w] = read_matrix(os.path.join(entries[w], "job.sti"), n)
        U[w] = deflection(entries[w], dofs)

    def lowest(k):
        return np.sort(sla.eigsh(k, k=5, M=M, sigma=0, which="LM", return_eigenvectors=False))

    V, _ = np.linalg.qr(np.column_stack([U[w] for w in fit[-m:]]))

    def features(a, w):
        return [*a] + [a[i] * a[j] for i in range(m) for j in range(i, m)] + [w * w]

    F = np.array([features(V.T @ U[w], w) for w in fit])
    Fi = np.linalg.inv(F)
    D = [K[w] - K[0.0] for w in fit]
    C = [sum(Fi[j, i] * D[i] for i in range(len(fit))) for j in range(len(fit))]
    nodes = [0.0] + fit
    a_nodes = np.array([V.T @ U[w] for w in nodes])
    spline_omega = CubicSpline(nodes, a_nodes)
    spline_s = CubicSpline(np.array(nodes) ** 2, a_nodes)
    print(f"{n} dofs; m = {m} deflection shapes (at {fit[-m:]} rad/s); fit speeds {fit}")
    for x in speeds:
        if x in fit:
            continue
        exact = lowest(K[x])
        rows = []
        for name, a in [("exact a", V.T @ U[x]), ("spline in Omega", spline_omega(x)), ("spline in s", spline_s(x * x))]:
            k = K[0.0] + sum(f * c for f, c in zip(features(a, x), C))
            da = np.linalg.norm(a - V.T @ U[x]) / np.linalg.norm(V.T @ U[x])
            rows.append(f"{name}: |da|/|a| {da:.1e}, max |lambda/lambda_ccx - 1| {np.abs(lowest(k) / exact - 1).max():.1e}")
        out_of_span = np.linalg.norm(U[x] - V @ (V.T @ U[x])) / np.linalg.norm(U[x])
        print(f"  {x:7.1f} rad/s (deflection {out_of_span:.1e} outside V): " + "; ".join(rows))


if __name__ == "__main__":
    main()
