"""Shape functions of the solid elements in ccx's node order, for checking generated meshes
(Jacobian signs, volumes). Written from the textbook definitions; node orders as in
tests/verification/meshgen.py (ccx's):

  hex    natural (xi, eta, zeta) in [-1, 1]^3, corners as in CORNERS["hex"];
         C3D20 midsides on the edges meshgen.EDGES["hex"] lists
  wedge  triangle coordinates (xi, eta) with L1 = 1 - xi - eta, L2 = xi, L3 = eta, and
         zeta in [-1, 1] (nodes 1-3 at zeta = -1, 4-6 at +1); C3D15 midsides as EDGES["wedge"]
  tet    volume coordinates L1 = 1 - xi - eta - zeta, L2 = xi, L3 = eta, L4 = zeta;
         C3D10 midsides as EDGES["tet"]

gradients() differentiates numerically (central differences): these functions are used for
signs and volumes, where 1e-8 relative accuracy is plenty."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "verification"))
import meshgen  # noqa: E402

CORNERS = {
    "hex": [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
            (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)],
    "wedge": [(0, 0, -1), (1, 0, -1), (0, 1, -1), (0, 0, 1), (1, 0, 1), (0, 1, 1)],
    "tet": [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)],
}


def _hex(quadratic, xi):
    x = np.asarray(xi, float)
    corners = np.array(CORNERS["hex"], float)
    linear = np.prod(1 + corners * x, axis=1) / 8
    if not quadratic:
        return linear
    n_corner = linear * (corners @ x - 2)
    mids = []
    for a, b in meshgen.EDGES["hex"]:
        m = (corners[a - 1] + corners[b - 1]) / 2  # one coordinate is 0 on an edge
        mids.append(np.prod(np.where(m == 0, 1 - x * x, 1 + m * x)) / 4)
    return np.concatenate([n_corner, mids])


def _wedge(quadratic, xi):
    s, t, z = xi
    tri = np.array([1 - s - t, s, t])
    if not quadratic:
        return np.concatenate([tri * (1 - z) / 2, tri * (1 + z) / 2])
    bottom = tri * ((2 * tri - 1) * (1 - z) - (1 - z * z)) / 2
    top = tri * ((2 * tri - 1) * (1 + z) - (1 - z * z)) / 2
    in_plane = [(0, 1), (1, 2), (2, 0)]
    mids = ([2 * tri[a] * tri[b] * (1 - z) for a, b in in_plane]
            + [2 * tri[a] * tri[b] * (1 + z) for a, b in in_plane]
            + [tri[a] * (1 - z * z) for a in range(3)])
    return np.concatenate([bottom, top, mids])


def _tet(quadratic, xi):
    s, t, u = xi
    vol = np.array([1 - s - t - u, s, t, u])
    if not quadratic:
        return vol
    mids = [4 * vol[a - 1] * vol[b - 1] for a, b in meshgen.EDGES["tet"]]
    return np.concatenate([vol * (2 * vol - 1), mids])


_BY_FAMILY = {"hex": _hex, "wedge": _wedge, "tet": _tet}


def shape(etype, xi):
    """Shape function values N_i(xi), i in ccx's node order."""
    return _BY_FAMILY[meshgen.FAMILY[etype]](etype in meshgen.QUADRATIC, xi)


def gradients(etype, xi, step=1e-6):
    """dN_i/dxi_j as an (n_nodes, 3) array, by central differences."""
    xi = np.asarray(xi, float)
    columns = []
    for j in range(3):
        d = np.zeros(3)
        d[j] = step
        columns.append((shape(etype, xi + d) - shape(etype, xi - d)) / (2 * step))
    return np.stack(columns, axis=1)


def volume_rule(etype):
    """[(natural point, weight)]: exact for the volume of straight-sided elements and
    accurate for gently curved quadratic ones (hex 3x3x3, wedge 3 x 3, tet 4 points)."""
    family = meshgen.FAMILY[etype]
    g = [(-np.sqrt(0.6), 5 / 9), (0.0, 8 / 9), (np.sqrt(0.6), 5 / 9)]
    if family == "hex":
        return [((a, b, c), wa * wb * wc) for a, wa in g for b, wb in g for c, wc in g]
    tri = [((1 / 6, 1 / 6), 1 / 6), ((2 / 3, 1 / 6), 1 / 6), ((1 / 6, 2 / 3), 1 / 6)]
    if family == "wedge":
        return [((s, t, z), w * wz) for (s, t), w in tri for z, wz in g]
    a, b = 0.5854101966249685, 0.1381966011250105
    return [(p, 1 / 24) for p in [(b, b, b), (a, b, b), (b, a, b), (b, b, a)]]


def check_points(etype):
    """Natural points where a valid element must have det J > 0: the volume-rule points (first,
    in volume_rule's order) and the corner nodes (where distorted elements fold first)."""
    return [p for p, _ in volume_rule(etype)] + [tuple(c) for c in CORNERS[meshgen.FAMILY[etype]]]
