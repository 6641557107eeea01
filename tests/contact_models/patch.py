"""The contact patch test of the thesis (§5.4, table 7) and its variants.

Two unit cubes stacked: lower [0,1]^3, upper [0,1]^2 x [1,2]. Thesis setup (the defaults):
upper coarse C3D10 (2 x 2 x 2 cells, 6 tetrahedra each), lower fine C3D20 (5 x 5 x 5), E =
2.1e5 (the thesis does not say; any E gives the same stresses), Poisson's ratio 0, unit
pressure on the upper top, upper top fixed in x and y, lower bottom fixed in x, y, z;
frictionless linear penalty K = 1e7, sigma_inf = 1; slave = the upper body's bottom.

Exact solution: with nu = 0 the supports do not restrain anything, so sigma_zz = -1 at every
point of both bodies, every other stress component 0, contact pressure 1 everywhere on the
interface, and a uniform penetration p/K = 1e-7.

Variants (all keep that exact solution):
  upper / lower element   any of C3D4 C3D6 C3D8 C3D10 C3D15 C3D20 C3D20R ...
  n_upper / n_lower       cells per direction (int or (nx, ny, nz)): mesh ratios
  slave                   "upper" (default) or "lower": swapped slave and master
  gap                     the upper body starts this far above the lower one: the load has
                          to close it first (the body is held only by contact)
  young_upper / _lower    Young's moduli of the bodies (with nu = 0 any pair keeps the
                          exact stresses)
  poisson                 Poisson's ratio of both bodies; above 0 the bodies expand sideways
                          (by nu / E of their width): both are held on the planes x = 0 and
                          y = 0 only, their other sides and the upper top are free, and the
                          frictionless interface lets them slide where the moduli differ, so
                          the exact stresses stay. The contact pressure is a small-strain
                          stress: force per undeformed area, 1 although the faces grew.
  increments              fixed increments of the load: later ones start from faces that
                          have already grown (and slid)
  distortion              fraction d of the cell size: every corner-node column of a body
                          whose (x, y) is inside the square moves in-plane by a random offset
                          up to d * h per component (seeded); columns stay vertical, so the
                          interface stays flat but its faces become general (non-affine)
                          quadrilaterals / triangles; midside nodes stay on straight edges.
Output requests: *EL PRINT S of both bodies, *CONTACT PRINT CSTR, CDIS, *CONTACT FILE (nodal
CPRESS in the frd / HDF5).
"""
import random

import numpy as np

import two_body
from two_body import meshgen

YOUNG, POISSON = 2.1e5, 0.0
PRESSURE, PENALTY, TENSION = 1.0, 1e7, 1.0


def _cells(n):
    return (n, n, n) if isinstance(n, int) else tuple(n)


def distort_columns(mesh, cells, fraction, seed):
    """Moves every interior corner-node column in-plane (see the module docstring); midside
    nodes are put back on the midpoints of their straight edges."""
    rng = random.Random(seed)
    h = min(1.0 / cells[0], 1.0 / cells[1])
    family = meshgen.FAMILY[mesh.etype]
    n_corner = meshgen.NCORNER[family]
    corners = {n for conn in mesh.elements.values() for n in conn[:n_corner]}
    offsets = {}
    for nid in sorted(corners):
        x, y = mesh.nodes[nid][:2]
        if min(x, y, 1 - x, 1 - y) < 1e-9:
            continue  # the square's sides stay where they are
        key = (round(x * cells[0]), round(y * cells[1]))
        if key not in offsets:
            offsets[key] = np.array([rng.uniform(-1, 1), rng.uniform(-1, 1), 0.0]) * fraction * h
        mesh.nodes[nid] = mesh.nodes[nid] + offsets[key]
    if mesh.etype in meshgen.QUADRATIC:
        for conn in mesh.elements.values():
            for j, (a, b) in enumerate(meshgen.EDGES[family]):
                mesh.nodes[conn[n_corner + j]] = 0.5 * (mesh.nodes[conn[a - 1]]
                                                        + mesh.nodes[conn[b - 1]])


def patch(upper="C3D10", lower="C3D20", n_upper=2, n_lower=5, slave="upper",
          distortion=0.0, seed=1, contact_type="SURFACE TO SURFACE", gap=0.0,
          young_upper=YOUNG, young_lower=YOUNG, poisson=POISSON,
          increments=1):
    cells_u, cells_l = _cells(n_upper), _cells(n_lower)
    lower_mesh = meshgen.box_mesh(lower, n=cells_l)
    upper_mesh = meshgen.box_mesh(upper, n=cells_u, origin=(0.0, 0.0, 1.0 + gap))
    if distortion:
        distort_columns(lower_mesh, cells_l, distortion, seed)
        distort_columns(upper_mesh, cells_u, distortion, seed + 1)
    sides = {"upper": ("UPPER", "ZMIN"), "lower": ("LOWER", "ZMAX")}
    if slave not in sides:
        raise ValueError(f"slave {slave!r}: upper or lower")
    if poisson:  # symmetry planes only: the sides may grow
        supports = [("LOWER", "ZMIN", 3, 3, 0.0)] + [
            (body, plane, dof, dof, 0.0) for body in ("LOWER", "UPPER")
            for plane, dof in (("XMIN", 1), ("YMIN", 2))]
    else:
        supports = [("LOWER", "ZMIN", 1, 3, 0.0), ("UPPER", "ZMAX", 1, 2, 0.0)]
    model = two_body.TwoBodyModel(
        heading="Kontakt contact model: patch test (thesis 5.4)",
        lower=two_body.Body("LOWER", lower_mesh, young_lower, poisson),
        upper=two_body.Body("UPPER", upper_mesh, young_upper, poisson),
        slave=sides[slave], master=sides["lower" if slave == "upper" else "upper"],
        contact_type=contact_type, penalty=PENALTY, tension=TENSION,
        fixed=supports,
        pressures=[("UPPER", "ZMAX", PRESSURE)],
        el_prints=[("UPPER", "S"), ("LOWER", "S")],
        contact_print="CSTR, CDIS", contact_file=True,
        increment=(1.0 / increments, 1.0, 1e-5, 1.0 / increments))
    model.notes = [f"patch test (thesis 5.4), generated by tests/contact_models: upper {upper} "
                   f"{cells_u}, lower {lower} {cells_l}, slave {slave}, distortion "
                   f"{distortion:g} (seed {seed}), gap {gap:g}, E {young_upper:g} / "
                   f"{young_lower:g}, nu {poisson:g}, {increments} increment(s); exact: sigma_zz = -1, CPRESS = 1"]
    return model
