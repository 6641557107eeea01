"""Validity checks of a generated two-body contact model; each returns a list of problems
(empty: valid).

  element_jacobians   det J > 0 at every volume-rule point and corner node of every element
  conformity          no face is shared by more than two elements, shared faces have the
                      same nodes (midsides included), and the boundary is closed: every
                      boundary edge belongs to exactly two boundary faces (no hanging nodes)
  outward_boundary    the volume enclosed by the boundary faces, oriented by ccx's face node
                      order, equals the elements' volume: positive, so every boundary face
                      normal points out of the body
  contact_surfaces    every SLAVE / MASTER face is a boundary face, its normal points away
                      from its element, and the two surfaces face each other (mean normals
                      opposite)
"""
import collections

import numpy as np

import shape_functions
from shape_functions import meshgen

# ccx's face node order (corners): the right-hand normal points out of the element
OUTWARD_CORNERS = {
    "hex": {1: (4, 3, 2, 1), 2: (5, 6, 7, 8), 3: (1, 2, 6, 5), 4: (2, 3, 7, 6),
            5: (3, 4, 8, 7), 6: (4, 1, 5, 8)},
    "wedge": {1: (1, 3, 2), 2: (4, 5, 6), 3: (1, 2, 5, 4), 4: (2, 3, 6, 5), 5: (3, 1, 4, 6)},
    "tet": {1: (1, 3, 2), 2: (1, 2, 4), 3: (2, 3, 4), 4: (1, 4, 3)},
}


def _xyz(mesh, ids):
    return np.array([mesh.nodes[n] for n in ids])


def element_volumes(mesh):
    """{element: (volume, smallest det J at the check points)}."""
    ids = sorted(mesh.elements)
    x = np.array([_xyz(mesh, mesh.elements[e]) for e in ids])          # (elements, nodes, 3)
    rule = shape_functions.volume_rule(mesh.etype)
    weights = np.array([w for _, w in rule])
    points = shape_functions.check_points(mesh.etype)  # the rule's points come first
    grads = np.array([shape_functions.gradients(mesh.etype, p) for p in points])  # (p, n, 3)
    det = np.linalg.det(np.einsum("enk,pnj->epkj", x, grads))          # (elements, points)
    volume = det[:, :len(rule)] @ weights
    return {e: (v, d) for e, v, d in zip(ids, volume, det.min(axis=1))}


def element_jacobians(mesh, volumes=None):
    volumes = volumes or element_volumes(mesh)
    return [f"element {e}: det J = {d:.3g} <= 0" for e, (_, d) in sorted(volumes.items())
            if d <= 0][:10]


def _faces(mesh):
    """{corner node set: [(element, face number, all face nodes)]}."""
    faces = collections.defaultdict(list)
    for eid, conn in mesh.elements.items():
        for f in meshgen.FACES[meshgen.FAMILY[mesh.etype]]:
            nodes = meshgen.face_nodes(mesh.etype, conn, f)
            corners = len(meshgen.FACES[meshgen.FAMILY[mesh.etype]][f])
            faces[frozenset(nodes[:corners])].append((eid, f, frozenset(nodes)))
    return faces


def boundary_faces(mesh):
    """{(element, face number)} of the faces that belong to one element only."""
    return {(users[0][0], users[0][1]) for users in _faces(mesh).values() if len(users) == 1}


def conformity(mesh):
    problems = []
    edges = collections.Counter()
    for corners, users in _faces(mesh).items():
        if len(users) > 2:
            problems.append(f"face {sorted(corners)} shared by {len(users)} elements")
        elif len(users) == 2 and users[0][2] != users[1][2]:
            problems.append(f"face {sorted(corners)}: elements {users[0][0]} and {users[1][0]} "
                            "have different midside nodes")
        elif len(users) == 1:
            eid, f, _ = users[0]
            ring = OUTWARD_CORNERS[meshgen.FAMILY[mesh.etype]][f]
            conn = mesh.elements[eid]
            for a, b in zip(ring, ring[1:] + ring[:1]):
                edges[frozenset((conn[a - 1], conn[b - 1]))] += 1
    open_edges = [sorted(e) for e, n in edges.items() if n != 2]
    if open_edges:
        problems.append(f"{len(open_edges)} boundary edges not shared by exactly two boundary "
                        f"faces (hanging nodes or holes), e.g. {open_edges[0]}")
    return problems


def _outward_polygon(mesh, eid, f):
    """Face nodes in boundary order (corner, midside, corner, ...), oriented outward."""
    family = meshgen.FAMILY[mesh.etype]
    conn = mesh.elements[eid]
    ring = OUTWARD_CORNERS[family][f]
    ids = [conn[c - 1] for c in ring]
    if mesh.etype not in meshgen.QUADRATIC:
        return _xyz(mesh, ids)
    n_corner = meshgen.NCORNER[family]
    polygon = []
    for a, b in zip(ring, ring[1:] + ring[:1]):
        j = next(j for j, e in enumerate(meshgen.EDGES[family]) if set(e) == {a, b})
        polygon += [conn[a - 1], conn[n_corner + j]]
    return _xyz(mesh, polygon)


def _face_centre(polygon, quadratic):
    """The face's point at its local centre: corners' mean (linear faces); for quadratic ones
    the serendipity / tri6 value -1/4 sum(corners) + 1/2 sum(mids), -1/9 ... + 4/9 ..."""
    corners, mids = polygon[0::2], polygon[1::2]
    if not quadratic:
        return polygon.mean(axis=0)
    if len(corners) == 4:
        return -corners.sum(axis=0) / 4 + mids.sum(axis=0) / 2
    return -corners.sum(axis=0) / 9 + 4 * mids.sum(axis=0) / 9


def _fan(mesh, eid, f):
    """Outward triangles (centre, p_i, p_i+1) that cover the face."""
    p = _outward_polygon(mesh, eid, f)
    c = _face_centre(p, mesh.etype in meshgen.QUADRATIC)
    return [(c, p[i], p[(i + 1) % len(p)]) for i in range(len(p))]


def face_normal(mesh, eid, f):
    """Unit outward normal of a face (area-weighted over its fan triangles)."""
    n = sum(np.cross(a - c, b - c) for c, a, b in _fan(mesh, eid, f))
    return n / np.linalg.norm(n)


def outward_boundary(mesh, volumes=None):
    volumes = volumes or element_volumes(mesh)
    enclosed = 0.0
    for eid, f in boundary_faces(mesh):
        enclosed += sum(np.dot(c, np.cross(a, b)) for c, a, b in _fan(mesh, eid, f)) / 6
    total = sum(v for v, _ in volumes.values())
    if total <= 0 or abs(enclosed - total) > 1e-2 * abs(total):
        return [f"boundary encloses {enclosed:.6g}, elements add up to {total:.6g} "
                "(boundary faces not all outward, or elements inverted)"]
    return []


def contact_surfaces(model):
    problems = []
    means = {}
    for surface, (body, nset) in (("SLAVE", model.slave), ("MASTER", model.master)):
        mesh = model.body(body).mesh
        boundary = boundary_faces(mesh)
        faces = mesh.faces_on(nset)
        if not faces:
            problems.append(f"{surface}: no faces on {body} {nset}")
            continue
        total = np.zeros(3)
        for eid, f in faces:
            if (eid, f) not in boundary:
                problems.append(f"{surface}: face {f} of {body} element {eid} is inside the body")
            n = face_normal(mesh, eid, f)
            centroid = _xyz(mesh, mesh.elements[eid]).mean(axis=0)
            if np.dot(n, _outward_polygon(mesh, eid, f).mean(axis=0) - centroid) <= 0:
                problems.append(f"{surface}: face {f} of {body} element {eid} points inward")
            total += n
        means[surface] = total / np.linalg.norm(total)
    if len(means) == 2 and np.dot(means["SLAVE"], means["MASTER"]) > -0.5:
        problems.append(f"SLAVE and MASTER do not face each other (mean normals "
                        f"{np.round(means['SLAVE'], 3)} and {np.round(means['MASTER'], 3)})")
    return problems


def check_model(model):
    """Every problem of the model: per body element_jacobians, conformity, outward_boundary;
    then contact_surfaces. Empty list: valid."""
    problems = []
    for body in (model.lower, model.upper):
        volumes = element_volumes(body.mesh)
        for check in (element_jacobians(body.mesh, volumes), conformity(body.mesh),
                      outward_boundary(body.mesh, volumes)):
            problems += [f"{body.name}: {p}" for p in check]
    return problems + contact_surfaces(model)
