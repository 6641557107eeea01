"""meshgen -- small deck writer for the Kontakt analytical verification suite.

Everything here is written from scratch for Kontakt; no CalculiX decks or code
are copied.  Element conventions follow Abaqus / CalculiX (ccx manual,
section "Element Types" and *DLOAD face tables):

  hex   (C3D8, C3D8R, C3D8I, C3D20, C3D20R): corners 1-4 on the bottom face
        counter-clockwise seen from above (from nodes 5-8), 5-8 above them;
        C3D20 midsides 9:1-2 10:2-3 11:3-4 12:4-1 13:5-6 14:6-7 15:7-8 16:8-5
        17:1-5 18:2-6 19:3-7 20:4-8.
  wedge (C3D6, C3D15): triangle 1-2-3 counter-clockwise seen from 4-5-6,
        4-5-6 above 1-2-3; C3D15 midsides 7:1-2 8:2-3 9:3-1 10:4-5 11:5-6
        12:6-4 13:1-4 14:2-5 15:3-6.
  tet   (C3D4, C3D10): 1-2-3 counter-clockwise seen from node 4;
        C3D10 midsides 5:1-2 6:2-3 7:3-1 8:1-4 9:2-4 10:3-4.

Face numbers (P1..P6 of *DLOAD), by corner nodes:
  hex   1:1234 2:5876 3:1562 4:2673 5:3784 6:4851
  wedge 1:123  2:456  3:1254 4:2365 5:3146
  tet   1:123  2:142  3:243  4:341

Public API
  box_mesh(etype, n=(nx,ny,nz), size=(lx,ly,lz), origin=(0,0,0),
           perturb=0.0, seed=1)            -> Mesh
  cylinder_sector_mesh(a, b, t, nr, nth, nz, angle=90 deg, etype='C3D20')
                                            -> Mesh
  Mesh.faces_on(nset)                       -> [(elem, face_no)]
  Mesh.consistent_face_weights(nset)        -> {node: weight}, sum = area
  Deck(mesh) ... .write(path)               -> writes an .inp
"""

from __future__ import annotations

import math
import os
import random
from itertools import permutations

import numpy as np

# --------------------------------------------------------------------------
# element tables
# --------------------------------------------------------------------------
HEX_TYPES = ("C3D8", "C3D8R", "C3D8I", "C3D20", "C3D20R")
WEDGE_TYPES = ("C3D6", "C3D15")
TET_TYPES = ("C3D4", "C3D10")
ALL_TYPES = ("C3D4", "C3D6", "C3D8", "C3D8R", "C3D8I",
             "C3D10", "C3D15", "C3D20", "C3D20R")

FAMILY = {t: "hex" for t in HEX_TYPES}
FAMILY.update({t: "wedge" for t in WEDGE_TYPES})
FAMILY.update({t: "tet" for t in TET_TYPES})

QUADRATIC = {"C3D10", "C3D15", "C3D20", "C3D20R"}

# 1-based corner indices of each face
FACES = {
    "hex": {1: (1, 2, 3, 4), 2: (5, 8, 7, 6), 3: (1, 5, 6, 2),
            4: (2, 6, 7, 3), 5: (3, 7, 8, 4), 6: (4, 8, 5, 1)},
    "wedge": {1: (1, 2, 3), 2: (4, 5, 6), 3: (1, 2, 5, 4),
              4: (2, 3, 6, 5), 5: (3, 1, 4, 6)},
    "tet": {1: (1, 2, 3), 2: (1, 4, 2), 3: (2, 4, 3), 4: (3, 4, 1)},
}

# midside node edges (1-based corner indices), in element node order
EDGES = {
    "hex": ((1, 2), (2, 3), (3, 4), (4, 1), (5, 6), (6, 7), (7, 8), (8, 5),
            (1, 5), (2, 6), (3, 7), (4, 8)),
    "wedge": ((1, 2), (2, 3), (3, 1), (4, 5), (5, 6), (6, 4),
              (1, 4), (2, 5), (3, 6)),
    "tet": ((1, 2), (2, 3), (3, 1), (1, 4), (2, 4), (3, 4)),
}

NCORNER = {"hex": 8, "wedge": 6, "tet": 4}


def n_corners(etype: str) -> int:
    return NCORNER[FAMILY[etype]]


def face_nodes(etype: str, conn, face: int):
    """Global node ids of a face: corners followed by midsides (quadratic)."""
    fam = FAMILY[etype]
    corners = FACES[fam][face]
    ids = [conn[c - 1] for c in corners]
    if etype in QUADRATIC:
        nc = NCORNER[fam]
        k = len(corners)
        for i in range(k):
            a, b = corners[i], corners[(i + 1) % k]
            for j, (p, q) in enumerate(EDGES[fam]):
                if {p, q} == {a, b}:
                    ids.append(conn[nc + j])
                    break
            else:  # pragma: no cover
                raise RuntimeError("face edge not found")
    return ids


# --------------------------------------------------------------------------
# mesh container
# --------------------------------------------------------------------------
class Mesh:
    def __init__(self, etype: str):
        self.etype = etype
        self.nodes: dict[int, np.ndarray] = {}
        self.elements: dict[int, list[int]] = {}
        self.nsets: dict[str, list[int]] = {}
        self.elsets: dict[str, list[int]] = {}

    # geometry helpers ------------------------------------------------------
    def coords(self, nid: int) -> np.ndarray:
        return self.nodes[nid]

    def faces_on(self, nset: str):
        """(element, face number) for every element face whose nodes all lie
        in node set `nset`."""
        s = set(self.nsets[nset])
        fam = FAMILY[self.etype]
        out = []
        for eid, conn in self.elements.items():
            for f, corners in FACES[fam].items():
                if all(conn[c - 1] in s for c in corners):
                    out.append((eid, f))
        return out

    def face_area(self, eid: int, face: int) -> float:
        conn = self.elements[eid]
        ids = face_nodes(self.etype, conn, face)
        nc = len(FACES[FAMILY[self.etype]][face])
        p = [self.nodes[i] for i in ids[:nc]]
        if nc == 3:
            return 0.5 * np.linalg.norm(np.cross(p[1] - p[0], p[2] - p[0]))
        # planar-or-not bilinear quad: split into two triangles (exact for
        # the planar faces used here)
        return 0.5 * (np.linalg.norm(np.cross(p[1] - p[0], p[2] - p[0]))
                      + np.linalg.norm(np.cross(p[2] - p[0], p[3] - p[0])))

    def consistent_face_weights(self, nset: str) -> dict[int, float]:
        """Consistent nodal weights of a uniform unit traction over the faces
        lying in `nset` (flat faces with straight edges; parallelogram quads
        for the quadratic serendipity rule).  Sum of weights = total area.

          tri3 : 1/3 per corner       quad4 : 1/4 per corner
          tri6 : 0 corners, 1/3 mids  quad8 : -1/12 corners, 1/3 mids
        """
        w: dict[int, float] = {}
        for eid, f in self.faces_on(nset):
            ids = face_nodes(self.etype, self.elements[eid], f)
            nc = len(FACES[FAMILY[self.etype]][f])
            area = self.face_area(eid, f)
            quad = self.etype in QUADRATIC
            if nc == 3:
                wc, wm = (0.0, 1.0 / 3.0) if quad else (1.0 / 3.0, 0.0)
            else:
                wc, wm = (-1.0 / 12.0, 1.0 / 3.0) if quad else (0.25, 0.0)
            for i, nid in enumerate(ids):
                w[nid] = w.get(nid, 0.0) + area * (wc if i < nc else wm)
        return w

    def nearest_node(self, point, nset: str | None = None) -> int:
        cand = self.nsets[nset] if nset else self.nodes.keys()
        p = np.asarray(point, float)
        return min(cand, key=lambda n: float(np.linalg.norm(self.nodes[n] - p)))


# --------------------------------------------------------------------------
# generic builder: corners are keyed by lattice index, midsides by edge
# --------------------------------------------------------------------------
class _Builder:
    def __init__(self, etype):
        self.etype = etype
        self.fam = FAMILY[etype]
        self.corner_elems: list[tuple] = []   # tuples of corner keys

    def add(self, keys):
        self.corner_elems.append(tuple(keys))

    def build(self, corner_pos, corner_ref, mid_pos=None):
        """corner_pos(key)->actual xyz, corner_ref(key)->reference xyz used
        for set classification; mid_pos(k1,k2)->xyz of a midside (default:
        straight-edge midpoint of the actual corners).  Returns (mesh,
        ref) with ref: node id -> reference coordinates."""
        mesh = Mesh(self.etype)
        ids: dict = {}
        ref: dict[int, np.ndarray] = {}
        # corners first, in lattice order, only those used
        used = sorted({k for e in self.corner_elems for k in e})
        for k in used:
            nid = len(ids) + 1
            ids[k] = nid
            mesh.nodes[nid] = np.asarray(corner_pos(k), float)
            ref[nid] = np.asarray(corner_ref(k), float)
        quad = self.etype in QUADRATIC
        for eidx, keys in enumerate(self.corner_elems, start=1):
            keys = _orient(self.fam, list(keys), corner_pos)
            conn = [ids[k] for k in keys]
            if quad:
                for (a, b) in EDGES[self.fam]:
                    ka, kb = keys[a - 1], keys[b - 1]
                    ek = ("mid",) + tuple(sorted((ka, kb)))
                    if ek not in ids:
                        nid = len(ids) + 1
                        ids[ek] = nid
                        if mid_pos is None:
                            mesh.nodes[nid] = 0.5 * (mesh.nodes[ids[ka]] + mesh.nodes[ids[kb]])
                        else:
                            mesh.nodes[nid] = np.asarray(mid_pos(ka, kb), float)
                        ref[nid] = 0.5 * (ref[ids[ka]] + ref[ids[kb]])
                    conn.append(ids[ek])
            mesh.elements[eidx] = conn
        return mesh, ref


def _signed_volume(fam, pts):
    p = [np.asarray(x, float) for x in pts]
    if fam == "tet":
        return np.dot(np.cross(p[1] - p[0], p[2] - p[0]), p[3] - p[0])
    if fam == "wedge":
        c_bot = (p[0] + p[1] + p[2]) / 3
        c_top = (p[3] + p[4] + p[5]) / 3
        return np.dot(np.cross(p[1] - p[0], p[2] - p[0]), c_top - c_bot)
    c_bot = sum(p[:4]) / 4
    c_top = sum(p[4:]) / 4
    n = np.cross(p[2] - p[0], p[3] - p[1])
    return np.dot(n, c_top - c_bot)


def _orient(fam, keys, pos):
    if _signed_volume(fam, [pos(k) for k in keys]) > 0:
        return keys
    if fam == "tet":
        return [keys[0], keys[2], keys[1], keys[3]]
    if fam == "wedge":
        return [keys[0], keys[2], keys[1], keys[3], keys[5], keys[4]]
    return [keys[0], keys[3], keys[2], keys[1], keys[4], keys[7], keys[6], keys[5]]


def _split_cell(fam, c):
    """c: dict bits(i,j,k)->key of the 8 cell corners.  Returns corner-key
    tuples of the sub-elements (orientation fixed later)."""
    if fam == "hex":
        return [(c[0, 0, 0], c[1, 0, 0], c[1, 1, 0], c[0, 1, 0],
                 c[0, 0, 1], c[1, 0, 1], c[1, 1, 1], c[0, 1, 1])]
    if fam == "wedge":
        # diagonal (0,0)-(1,1) of every x-y face: conforming
        return [(c[0, 0, 0], c[1, 0, 0], c[1, 1, 0], c[0, 0, 1], c[1, 0, 1], c[1, 1, 1]),
                (c[0, 0, 0], c[1, 1, 0], c[0, 1, 0], c[0, 0, 1], c[1, 1, 1], c[0, 1, 1])]
    # Kuhn (Freudenthal) split: 6 tets around the main diagonal; the same
    # split in every cell is conforming
    out = []
    for perm in permutations(range(3)):
        v = [0, 0, 0]
        path = [tuple(v)]
        for ax in perm:
            v[ax] = 1
            path.append(tuple(v))
        out.append(tuple(c[p] for p in path))
    return out


# --------------------------------------------------------------------------
# structured box
# --------------------------------------------------------------------------
def box_mesh(etype, n=(2, 2, 2), size=(1.0, 1.0, 1.0), origin=(0.0, 0.0, 0.0),
             perturb=0.0, seed=1):
    """Structured box [origin, origin+size] with n cells per direction.

    Hex types: one element per cell; wedges: 2 per cell (x-y diagonal);
    tets: 6 per cell (Kuhn split).  `perturb` moves every interior corner
    node by a uniform random offset of up to perturb*h (h = smallest cell
    size) per component; quadratic midside nodes are placed at the
    straight-edge midpoints of the (perturbed) corners.

    Node sets: ALL, XMIN, XMAX, YMIN, YMAX, ZMIN, ZMAX, BOUNDARY, INTERIOR.
    Element set: EALL.
    """
    nx, ny, nz = n
    lx, ly, lz = size
    ox, oy, oz = origin
    fam = FAMILY[etype]
    h = min(lx / nx, ly / ny, lz / nz)
    rng = random.Random(seed)

    def ref(k):
        i, j, kk = k
        return (ox + lx * i / nx, oy + ly * j / ny, oz + lz * kk / nz)

    offs = {}
    for i in range(1, nx):
        for j in range(1, ny):
            for kk in range(1, nz):
                offs[(i, j, kk)] = np.array([rng.uniform(-1, 1) for _ in range(3)]) * perturb * h

    def pos(k):
        r = np.array(ref(k))
        return r + offs.get(k, 0.0)

    b = _Builder(etype)
    for i in range(nx):
        for j in range(ny):
            for kk in range(nz):
                c = {(a, bb, cc): (i + a, j + bb, kk + cc)
                     for a in (0, 1) for bb in (0, 1) for cc in (0, 1)}
                for e in _split_cell(fam, c):
                    b.add(e)
    mesh, refc = b.build(pos, ref)
    _box_sets(mesh, refc, origin, size)
    return mesh


def _box_sets(mesh, refc, origin, size):
    lo = np.asarray(origin, float)
    hi = lo + np.asarray(size, float)
    tol = 1e-9 * max(size)
    sets = {k: [] for k in ("XMIN", "XMAX", "YMIN", "YMAX", "ZMIN", "ZMAX")}
    for nid, r in refc.items():
        for ax, name in enumerate("XYZ"):
            if abs(r[ax] - lo[ax]) < tol:
                sets[name + "MIN"].append(nid)
            if abs(r[ax] - hi[ax]) < tol:
                sets[name + "MAX"].append(nid)
    mesh.nsets.update({k: sorted(v) for k, v in sets.items()})
    mesh.nsets["ALL"] = sorted(mesh.nodes)
    bnd = sorted(set().union(*[set(v) for v in sets.values()]))
    mesh.nsets["BOUNDARY"] = bnd
    mesh.nsets["INTERIOR"] = sorted(set(mesh.nodes) - set(bnd))
    mesh.elsets["EALL"] = sorted(mesh.elements)


# --------------------------------------------------------------------------
# cylinder sector (quarter annulus by default), hex20 / hex8
# --------------------------------------------------------------------------
def cylinder_sector_mesh(a, b, t, nr, nth, nz, angle=math.pi / 2, etype="C3D20"):
    """Annular sector a<=r<=b, 0<=theta<=angle, 0<=z<=t; hexahedra with
    local axes (r, theta, z).  Quadratic midside nodes lie exactly on the
    arcs (isoparametric mapping of the polar parameter lattice).

    Node sets: INNER (r=a), OUTER (r=b), THETA0 (y=0 plane), THETA1
    (theta=angle plane), ZMIN, ZMAX, ALL.  Element set EALL.
    """
    if FAMILY[etype] != "hex":
        raise ValueError("cylinder_sector_mesh supports hex types only")

    def par(k):  # k in doubled-lattice units for midsides handled below
        i, j, kk = k
        return (a + (b - a) * i / nr, angle * j / nth, t * kk / nz)

    def xyz(p):
        r, th, z = p
        return (r * math.cos(th), r * math.sin(th), z)

    def pos(k):
        return xyz(par(k))

    def mid(ka, kb):
        pa, pb = np.array(par(ka)), np.array(par(kb))
        return xyz(0.5 * (pa + pb))

    bld = _Builder(etype)
    for i in range(nr):
        for j in range(nth):
            for kk in range(nz):
                c = {(x, y, z): (i + x, j + y, kk + z)
                     for x in (0, 1) for y in (0, 1) for z in (0, 1)}
                bld.add(_split_cell("hex", c)[0])
    # refp: node id -> parameter coordinates (r, theta, z)
    mesh, refp = bld.build(pos, par, mid_pos=mid)
    tol = 1e-9
    sets = {"INNER": [], "OUTER": [], "THETA0": [], "THETA1": [], "ZMIN": [], "ZMAX": []}
    for nid, (r, th, z) in refp.items():
        if abs(r - a) < tol: sets["INNER"].append(nid)
        if abs(r - b) < tol: sets["OUTER"].append(nid)
        if abs(th) < tol: sets["THETA0"].append(nid)
        if abs(th - angle) < tol: sets["THETA1"].append(nid)
        if abs(z) < tol: sets["ZMIN"].append(nid)
        if abs(z - t) < tol: sets["ZMAX"].append(nid)
    mesh.nsets.update({k: sorted(v) for k, v in sets.items()})
    mesh.nsets["ALL"] = sorted(mesh.nodes)
    mesh.elsets["EALL"] = sorted(mesh.elements)
    return mesh


# --------------------------------------------------------------------------
# deck writer
# --------------------------------------------------------------------------
def _fmt(x: float) -> str:
    """Shortest round-trip repr, cut to ccx's 20-character field limit."""
    x = float(x)
    if x == 0.0:
        return "0."
    s = repr(x)
    digits = 16
    while len(s) > 20:
        digits -= 1
        s = f"{x:.{digits}g}"
    if "." not in s and "e" not in s:
        s += "."
    return s


def _id_lines(ids, per_line=8):
    ids = list(ids)
    return [", ".join(str(i) for i in ids[k:k + per_line]) + ","
            for k in range(0, len(ids), per_line)]


class Deck:
    """Accumulates keyword blocks; model data first, then one *STEP."""

    def __init__(self, mesh: Mesh, heading: str = "Kontakt verification deck"):
        self.mesh = mesh
        self.heading = heading
        self.comments: list[str] = []
        self.model_extra: list[str] = []
        self.step: list[str] = []
        self.material = None

    # model data ------------------------------------------------------------
    def set_material(self, E, nu, name="MAT"):
        self.material = (name, E, nu)

    def add_nset(self, name, ids):
        self.mesh.nsets[name] = sorted(set(ids))

    def add_elset(self, name, ids):
        self.mesh.elsets[name] = sorted(set(ids))

    # step data -------------------------------------------------------------
    def boundary(self, rows):
        """rows: (node or set, first dof, last dof[, value])"""
        self.step.append("*BOUNDARY")
        for r in rows:
            if len(r) == 4:
                self.step.append(f"{r[0]}, {r[1]}, {r[2]}, {_fmt(r[3])}")
            else:
                self.step.append(f"{r[0]}, {r[1]}, {r[2]}")

    def cload(self, rows):
        """rows: (node or set, dof, value)"""
        self.step.append("*CLOAD")
        for n, d, v in rows:
            self.step.append(f"{n}, {d}, {_fmt(v)}")

    def dload_pressure(self, faces, p):
        """faces: [(elem, face_no)], uniform pressure p (positive = push)."""
        self.step.append("*DLOAD")
        for e, f in faces:
            self.step.append(f"{e}, P{f}, {_fmt(p)}")

    def node_print(self, nset, keys="U", totals=None):
        extra = f", TOTALS={totals}" if totals else ""
        self.step += [f"*NODE PRINT, NSET={nset}{extra}", keys]

    def el_print(self, elset, keys="S"):
        self.step += [f"*EL PRINT, ELSET={elset}", keys]

    def raw_step(self, *lines):
        self.step += list(lines)

    # output ----------------------------------------------------------------
    def text(self) -> str:
        m = self.mesh
        L = [f"** {c}" for c in self.comments]
        L += ["*HEADING", self.heading, "*NODE, NSET=NALL"]
        for nid in sorted(m.nodes):
            x, y, z = m.nodes[nid]
            L.append(f"{nid}, {_fmt(x)}, {_fmt(y)}, {_fmt(z)}")
        L.append(f"*ELEMENT, TYPE={m.etype}, ELSET=EALL")
        for eid in sorted(m.elements):
            conn = [str(eid)] + [str(c) for c in m.elements[eid]]
            # ccx/Abaqus: at most 16 entries per line, continuation lines
            # after a trailing comma
            chunks = [conn[k:k + 16] for k in range(0, len(conn), 16)]
            for ci, ch in enumerate(chunks):
                tail = "," if ci < len(chunks) - 1 else ""
                L.append(", ".join(ch) + tail)
        for name, ids in m.nsets.items():
            if name in ("NALL",) or not ids:
                continue
            L.append(f"*NSET, NSET={name}")
            L += _id_lines(ids)
        for name, ids in m.elsets.items():
            if name == "EALL" or not ids:
                continue
            L.append(f"*ELSET, ELSET={name}")
            L += _id_lines(ids)
        if self.material:
            name, E, nu = self.material
            L += [f"*MATERIAL, NAME={name}", "*ELASTIC", f"{_fmt(E)}, {_fmt(nu)}",
                  f"*SOLID SECTION, ELSET=EALL, MATERIAL={name}"]
        L += self.model_extra
        L += ["*STEP", "*STATIC"] + self.step + ["*END STEP"]
        return "\n".join(L) + "\n"

    def write(self, path):
        with open(path, "w") as f:
            f.write(self.text())
        return path


def as_nlgeom(text: str, increments: str = "0.25, 1.") -> str:
    """The deck's *STEP made NLGEOM, with ccx's initial and total time on the *STATIC line."""
    return text.replace("*STEP\n*STATIC\n", f"*STEP, NLGEOM\n*STATIC\n{increments}\n")


def write_decks(out: str, decks: dict, nlgeom: dict | None = None) -> int:
    """Writes {name: deck text} into out and the NLGEOM ones into out/nlgeom (run_peer.py runs
    that folder with --nlgeom); says how many; returns main()'s exit code."""
    folders = [(out, decks)] + ([(os.path.join(out, "nlgeom"), nlgeom)] if nlgeom else [])
    for folder, texts in folders:
        os.makedirs(folder, exist_ok=True)
        for name, text in texts.items():
            with open(os.path.join(folder, name + ".inp"), "w") as f:
                f.write(text)
    print(", ".join(f"{len(texts)} decks in {folder}" for folder, texts in folders))
    return 0


# --------------------------------------------------------------------------
# integration points (for locating ccx-ordered integration-point output)
# --------------------------------------------------------------------------
def hex_shape(etype, xi, eta, zeta):
    """Shape functions of C3D8 / C3D20 at (xi, eta, zeta) in [-1,1]^3."""
    cn = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
          (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]
    if etype not in QUADRATIC:
        return np.array([(1 + a * xi) * (1 + b * eta) * (1 + c * zeta) / 8 for a, b, c in cn])
    N = []
    for a, b, c in cn:
        N.append((1 + a * xi) * (1 + b * eta) * (1 + c * zeta)
                 * (a * xi + b * eta + c * zeta - 2) / 8)
    for p, q in EDGES["hex"]:
        pa, pb = np.array(cn[p - 1]), np.array(cn[q - 1])
        m = (pa + pb) / 2  # one coordinate is 0
        f = 1.0
        for ax, val in enumerate((xi, eta, zeta)):
            f *= (1 - val * val) if m[ax] == 0 else (1 + m[ax] * val)
        N.append(f / 4)
    return np.array(N)


def hex_gauss_points(etype):
    """Integration points in the order ccx prints them: xi varies fastest,
    then eta, then zeta (Gauss-Legendre, 2 or 3 per direction; C3D8R: 1)."""
    if etype == "C3D8R":
        pts = [0.0]
    elif etype in ("C3D20",):
        pts = [-math.sqrt(0.6), 0.0, math.sqrt(0.6)]
    else:
        pts = [-1 / math.sqrt(3), 1 / math.sqrt(3)]
    return [(x, y, z) for z in pts for y in pts for x in pts]


def hex_ip_coords(mesh: Mesh, eid: int):
    X = np.array([mesh.nodes[n] for n in mesh.elements[eid]])
    return [hex_shape(mesh.etype, *g) @ X for g in hex_gauss_points(mesh.etype)]


def affine_map(mesh: Mesh, M, t=(0.0, 0.0, 0.0)):
    """Map every node x -> M x + t (in place); straight edges and planar faces
    stay straight/planar, elements become parallelepipeds (exact for
    constant-Jacobian element checks).  det(M) must be > 0."""
    M = np.asarray(M, float)
    if np.linalg.det(M) <= 0:
        raise ValueError("affine_map needs det(M) > 0")
    for nid in mesh.nodes:
        mesh.nodes[nid] = M @ mesh.nodes[nid] + np.asarray(t, float)
    return mesh
