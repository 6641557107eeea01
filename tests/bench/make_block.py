#!/usr/bin/python3
"""Writes a linear-elastic cantilever block deck for benchmarks (our own deck, generated from
scratch): L x 1 x 1 (L = 10), steel (E = 210000, nu = 0.3), clamped at x = 0 (*BOUNDARY 1-3 on
every node of that face), loaded on the end face x = L by either
  --load cload     a total shear force `load` in -z spread evenly over the end-face nodes
                   (*CLOAD; the default: bending), or
  --load pressure  a pressure `load / area` on the end faces of the last element layer
                   (*DLOAD, face P4 of C3D8 / C3D20: axial compression),
one *STEP with *STATIC and *NODE PRINT of U for the end-face centre line only (so output stays
cheap). C3D8 or C3D20 on an nx x ny x ny grid with nx = 10 ny, the smallest grid with at least
--dofs degrees of freedom. With `plastic` rows the steel also gets a *PLASTIC hardening curve."""
import argparse
import math


def grid_size(element, dofs):
    """(nx, ny, nz) with nx = 10 ny and about `dofs` degrees of freedom."""
    for n in range(1, 400):
        nx, ny = 10 * n, n
        if element == "C3D8":
            nodes = (nx + 1) * (ny + 1) ** 2
        else:  # corner nodes + one midside node per edge
            corners = (nx + 1) * (ny + 1) ** 2
            edges = nx * (ny + 1) ** 2 + 2 * (nx + 1) * ny * (ny + 1)
            nodes = corners + edges
        if 3 * nodes >= dofs:
            return nx, ny, ny
    raise ValueError("too many dofs")


def write_block(path, element, dofs, nlgeom=False, load=1000.0, load_type="cload", plastic=()):
    """Writes the deck; `plastic`: (yield stress, equivalent plastic strain) rows of *PLASTIC,
    none for an elastic block. Returns (degrees of freedom, elements)."""
    nx, ny, nz = grid_size(element, dofs)
    quadratic = element == "C3D20"
    m = 2 if quadratic else 1  # node lattice step per element
    NX, NY, NZ = m * nx + 1, m * ny + 1, m * nz + 1
    ids = {}

    def used(i, j, k):  # a quadratic lattice point is a node if at most one index is odd
        return not quadratic or (i % 2) + (j % 2) + (k % 2) <= 1

    lines = ["** Kontakt benchmark block (tests/bench/make_block.py)", "*NODE, NSET=NALL"]
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                if used(i, j, k):
                    ids[i, j, k] = len(ids) + 1
                    lines.append(f"{ids[i, j, k]}, {10.0 * i / (NX - 1):.9g}, "
                                 f"{j / (NY - 1):.9g}, {k / (NZ - 1):.9g}")
    lines.append(f"*ELEMENT, TYPE={element}, ELSET=EALL")
    corner = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    edges = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4),
             (0, 4), (1, 5), (2, 6), (3, 7)]
    eid = 0
    end_elements = []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                base = [(m * (i + a), m * (j + b), m * (k + c)) for a, b, c in corner]
                nodes = [ids[p] for p in base]
                if quadratic:
                    for a, b in edges:
                        p, q = base[a], base[b]
                        nodes.append(ids[tuple((x + y) // 2 for x, y in zip(p, q))])
                eid += 1
                if i == nx - 1:
                    end_elements.append(eid)
                text = f"{eid}, " + ", ".join(map(str, nodes))
                if len(nodes) > 15:  # continuation line, as in ccx decks
                    head = ", ".join(map(str, nodes[:15]))
                    text = f"{eid}, {head},\n" + ", ".join(map(str, nodes[15:]))
                lines.append(text)
    fix = [n for (i, j, k), n in ids.items() if i == 0]
    tip = sorted(n for (i, j, k), n in ids.items() if i == NX - 1)
    centre = sorted(n for (i, j, k), n in ids.items() if i == NX - 1 and j == (NY - 1) // 2)
    lines.append("*NSET, NSET=FIX")
    lines += [", ".join(map(str, fix[s:s + 16])) for s in range(0, len(fix), 16)]
    lines.append("*NSET, NSET=TIPLINE")
    lines += [", ".join(map(str, centre[s:s + 16])) for s in range(0, len(centre), 16)]
    lines.append("*NSET, NSET=TIP")
    lines += [", ".join(map(str, tip[s:s + 16])) for s in range(0, len(tip), 16)]
    lines += ["*MATERIAL, NAME=STEEL", "*ELASTIC", "210000, 0.3"]
    if plastic:
        lines += ["*PLASTIC"] + [f"{s:.12g}, {e:.12g}" for s, e in plastic]
    lines += ["*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL",
              "*BOUNDARY", "FIX, 1, 3"]
    lines += ["*STEP, NLGEOM", "*STATIC", "0.25, 1.0"] if nlgeom else ["*STEP", "*STATIC"]
    if load_type == "pressure":  # face 4 (nodes 2-6-7-3) is the x = +1 face of C3D8/C3D20
        lines += ["*DLOAD"] + [f"{e}, P4, {load:.12g}" for e in end_elements]
    else:
        lines += ["*CLOAD", f"TIP, 3, {-load / len(tip):.12g}"]
    lines += ["*NODE PRINT, NSET=TIPLINE", "U", "*END STEP"]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return 3 * len(ids), eid


if __name__ == "__main__":
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("path")
    p.add_argument("--element", choices=["C3D8", "C3D20"], default="C3D8")
    p.add_argument("--dofs", type=int, default=300000)
    p.add_argument("--load", choices=["cload", "pressure"], default="cload")
    p.add_argument("--magnitude", type=float, default=1000.0, help="total force (end area is 1)")
    a = p.parse_args()
    n_dofs, n_el = write_block(a.path, a.element, a.dofs, load=a.magnitude, load_type=a.load)
    print(f"{a.path}: {a.element}, {n_el} elements, {n_dofs} dofs")
