#!/usr/bin/env python3
"""Regenerates examples/cantilever.inp with the verification suite's meshgen:

    /usr/bin/python3 examples/gen_cantilever.py > examples/cantilever.inp

C3D20R cantilever L=10 x 1 x 1 (4 x 4 x 20 cells), E=210000, nu=0.3,
clamped at x=0, total tip load 1000 in -z as the consistent nodal loads of a
uniform shear traction on the end face x=10."""
import os
import sys

sys.dont_write_bytecode = True  # keep the source tree clean

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "tests", "verification"))
import meshgen as mg  # noqa: E402

L, B, H, P = 10.0, 1.0, 1.0, -1000.0
mesh = mg.box_mesh("C3D20R", (20, 4, 4), (L, B, H))
deck = mg.Deck(mesh, "Kontakt example: C3D20R cantilever with tip shear load")
deck.comments += [
    "Kontakt bundled example (quick start).  GENERATED FILE - do not edit by hand:",
    "  /usr/bin/python3 examples/gen_cantilever.py > examples/cantilever.inp",
    "(uses tests/verification/meshgen.py).",
    "Cantilever 10 x 1 x 1, C3D20R, 4 x 4 x 20 cells, E=210000, nu=0.3, clamped at x=0",
    "(node set FIX), total tip load 1000 in -z at x=10 as consistent nodal loads of a",
    "uniform shear traction (quad8 faces: corners -1/12, midsides 1/3 of the face load).",
    "Timoshenko: delta = P L^3/(3EI) + P L/(kappa G A) = 1.9196e+01 (downwards);",
    "ccx 2.20 gives u_z = -1.9040e+01 (work-average of the end face).",
]
deck.set_material(210000.0, 0.3, name="STEEL")
mesh.nsets["FIX"] = mesh.nsets["XMIN"]
mesh.nsets["TIP"] = sorted(n for n in mesh.nsets["XMAX"] if abs(mesh.nodes[n][1] - B / 2) < 1e-9)
# root elements: first layer along x, top row (largest z) -- highest bending stress
root = [e for e, conn in mesh.elements.items()
        if max(mesh.nodes[n][0] for n in conn) <= L / 20 + 1e-9
        and min(mesh.nodes[n][2] for n in conn) >= H * 3 / 4 - 1e-9]
mesh.elsets["ROOT"] = sorted(root)
for k in ("XMIN", "XMAX", "YMIN", "YMAX", "ZMIN", "ZMAX", "ALL", "BOUNDARY", "INTERIOR"):
    if k not in ("XMAX",):
        mesh.nsets.pop(k, None)
mesh.nsets["TIPFACE"] = mesh.nsets.pop("XMAX")
deck.boundary([("FIX", 1, 3)])
w = mesh.consistent_face_weights("TIPFACE")
area = sum(w.values())
deck.cload([(n, 3, P * wi / area) for n, wi in sorted(w.items())])
deck.node_print("TIP", "U")
deck.node_print("FIX", "RF", totals="YES")
deck.el_print("ROOT", "S")
deck.raw_step("*NODE FILE", "U", "*EL FILE", "S")
sys.stdout.write(deck.text())
