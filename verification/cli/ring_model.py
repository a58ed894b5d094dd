#!/usr/bin/python3
"""Writes a small 3D bar model as a Matrix Market folder (rsi export's
layout) and its component case, optionally turned by a rotation, for the
end-to-end tests of the rubbing runs about any axis (rubbing_axis.sh).

Usage: ring_model.py OUT_DIR [ROTATION [KEY=JSON ...]]
ROTATION: "none" (the default), "cyclic" (x -> y -> z -> x: the axis z becomes x) or
"general" (0.7 rad about (1, 2, 3)/sqrt(14)). KEY=JSON sets a key of the
case's "rubbing" object (e.g. 'gap={"constant": -0.002}').

The model: 4 contact nodes on a ring of radius about 1 about z (the
boundary), 2 interior nodes at radius 0.6, bars of axial stiffness EA/L
between them (every contact node to both interior nodes, the interior nodes
to each other, the contact nodes in a ring) and an isotropic spring k_g to
the ground at every node, a lumped mass m a node. Its K is built from the
(rotated) coordinates, so the turned model is the model turned, not a
transformed matrix: K' = Q K Q^T up to the rounding of the coordinates.
Units N, mm, t, s.
"""
import json
import math
import os
import sys

EA = 1000.0  # N
K_GROUND = 50.0  # N/mm
MASS = 1e-3  # t

CONTACT = [(1.0, 0.3, 0.1), (1.05, 1.9, -0.2), (0.95, 3.5, 0.05), (1.0, 5.0, 0.15)]
INTERIOR = [(0.6, 1.0, 0.0), (0.6, 4.0, 0.05)]


def rotation(kind):
    if kind == "none":
        return [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    if kind == "cyclic":  # columns: the images of x, y, z are y, z, x
        return [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
    if kind == "general":  # Rodrigues: angle 0.7 about (1, 2, 3)/sqrt(14)
        n = math.sqrt(14.0)
        a = [1.0 / n, 2.0 / n, 3.0 / n]
        c, s = math.cos(0.7), math.sin(0.7)
        r = [[0.0] * 3 for _ in range(3)]
        for i in range(3):
            for j in range(3):
                r[i][j] = c * (i == j) + (1 - c) * a[i] * a[j]
        r[0][1] -= s * a[2]
        r[0][2] += s * a[1]
        r[1][0] += s * a[2]
        r[1][2] -= s * a[0]
        r[2][0] -= s * a[1]
        r[2][1] += s * a[0]
        return r
    raise SystemExit("ROTATION must be none, cyclic or general")


def apply(r, x):
    return [sum(r[i][k] * x[k] for k in range(3)) for i in range(3)]


def main():
    out = sys.argv[1]
    kind = sys.argv[2] if len(sys.argv) > 2 else "none"
    r = rotation(kind)
    points = [(rad * math.cos(phi), rad * math.sin(phi), z) for rad, phi, z in CONTACT + INTERIOR]
    points = [apply(r, p) for p in points]
    n_nodes = len(points)
    contact = list(range(len(CONTACT)))
    interior = list(range(len(CONTACT), n_nodes))
    bars = [(c, i) for c in contact for i in interior] + [(interior[0], interior[1])]
    bars += [(contact[k], contact[(k + 1) % len(contact)]) for k in range(len(contact))]
    n = 3 * n_nodes
    k = [[0.0] * n for _ in range(n)]
    for a, b in bars:
        d = [points[b][i] - points[a][i] for i in range(3)]
        length = math.sqrt(sum(x * x for x in d))
        e = [x / length for x in d]
        stiffness = EA / length
        for i in range(3):
            for j in range(3):
                v = stiffness * e[i] * e[j]
                k[3 * a + i][3 * a + j] += v
                k[3 * b + i][3 * b + j] += v
                k[3 * a + i][3 * b + j] -= v
                k[3 * b + i][3 * a + j] -= v
    for node in range(n_nodes):
        for i in range(3):
            k[3 * node + i][3 * node + i] += K_GROUND
    folder = os.path.join(out, "ring")
    os.makedirs(folder, exist_ok=True)
    lower = [(i, j, k[i][j]) for j in range(n) for i in range(j, n) if k[i][j] != 0.0]
    with open(os.path.join(folder, "K.mtx"), "w") as f:
        f.write("%%MatrixMarket matrix coordinate real symmetric\n")
        f.write("%d %d %d\n" % (n, n, len(lower)))
        for i, j, v in lower:
            f.write("%d %d %.17g\n" % (i + 1, j + 1, v))
    with open(os.path.join(folder, "M.mtx"), "w") as f:
        f.write("%%MatrixMarket matrix coordinate real symmetric\n")
        f.write("%d %d %d\n" % (n, n, n))
        for i in range(n):
            f.write("%d %d %.17g\n" % (i + 1, i + 1, MASS))
    with open(os.path.join(folder, "dofs.csv"), "w") as f:
        f.write("index,node,kind,boundary\n")
        for node in range(n_nodes):
            for i, kind_name in enumerate(("ux", "uy", "uz")):
                f.write("%d,%d,%s,%d\n" % (3 * node + i, node + 1, kind_name, node in contact))
    with open(os.path.join(folder, "nodes.csv"), "w") as f:
        f.write("node,x,y,z\n")
        for node, p in enumerate(points):
            f.write("%d,%.17g,%.17g,%.17g\n" % (node + 1, p[0], p[1], p[2]))
    axis = apply(r, [0.0, 0.0, 1.0])
    # The response: node 1 along the image of y (direction 3 after the cyclic turn).
    image_y = apply(r, [0.0, 1.0, 0.0])
    direction = max(range(3), key=lambda i: abs(image_y[i])) + 1
    rubbing = {
        "gap": {"oval": {"g_m": 0.01, "width": 0.15}},
        "friction_coefficient": 0.1,
        "rotation_speed": 100.0,
        "revolutions": 2.0,
        "steps_per_revolution": 200,
        "response": {"node": 1, "direction": direction},
    }
    for assignment in sys.argv[3:]:
        key, value = assignment.split("=", 1)
        rubbing[key] = json.loads(value)
    case = {
        "component": {
            "name": "ring",
            "source": {"matrix_market": "ring"},
            "units": "N, mm, t, s",
            "rotation_axis": axis,
        },
        "rubbing": rubbing,
    }
    with open(os.path.join(out, "ring.json"), "w") as f:
        json.dump(case, f, indent=2)


main()
