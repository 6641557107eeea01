"""Hertz line contact: an elastic cylinder pressed on an elastic block, plane strain, as a
quarter model (symmetry plane x = 0), one element layer thick with u_z = 0 at every node.
`full_width=True` mirrors both meshes about x = 0 (no symmetry plane: the model for tangential
loading, tests/contact_models/cattaneo.py); the cylinder's axis plane is then also held in x.

Geometry (R = 1): the cylinder's part x in [0, 0.8 R] below its axis (the body between the
arc y = R - sqrt(R^2 - x^2), touching the block at the origin, the axis plane y = R and the cut
x = 0.8 R); the block [0, 2 R] x [-2 R, 0]. Both are meshed on graded lattices: element size h
uniform over [0, 1.5 b] next to the contact (b = the target half-width), then growing by at
most 15 % per element. The block's size is 1.25 h (non-matching interface). Thickness h.
Level k has b / h = 5 * 2^(k - 1) elements across the target half-width (5, 10, 20).

Material: E = 1000, nu = 0.3 in both bodies: E* = E / (2 (1 - nu^2)) = 549.45.
Supports: u_x = 0 on x = 0 (both bodies), block bottom fixed (x, y), u_z = 0 everywhere;
load: the cylinder's axis plane moved down by DELTA (displacement control: no rigid body mode
before contact; the force P comes from the reaction). DELTA = 0.02 gives b = 0.109 R.
Penalty by verification.md §2.3 (K a / E* >= 100 keeps the penalty penetration at the pole
below 1 % of the approach): K = 200 E* / b_target (factor 2 margin), 1.1e6.
Slave: the cylinder (finer); master: the block top. Output: *NODE PRINT RF of the axis plane
(the load), *CONTACT FILE (nodal CPRESS on the slave nodes, frd / HDF5).

Closed form (Johnson, ch. 4), P = load per unit length of the whole cylinder = 2 F / t
(F: reaction of the half model of thickness t):
    b = sqrt(4 P R / (pi E*)),   p0 = 2 P / (pi b),   p(x) = p0 sqrt(1 - x^2 / b^2)
"""
import math

import numpy as np

import two_body
from two_body import meshgen

RADIUS, YOUNG, POISSON = 1.0, 1000.0, 0.3
E_STAR = YOUNG / (2 * (1 - POISSON ** 2))
TARGET_HALF_WIDTH = 0.1
DELTA = 0.02
PENALTY = 200 * E_STAR / TARGET_HALF_WIDTH
CYLINDER_WIDTH, CYLINDER_HEIGHT, BLOCK_SIZE = 0.8, 1.0, 2.0
GROWTH = 1.15


def closed_form(load_per_length):
    """(b, p0) of Hertz line contact for the load per unit length P of the whole cylinder."""
    b = math.sqrt(4 * load_per_length * RADIUS / (math.pi * E_STAR))
    return b, 2 * load_per_length / (math.pi * b)


def graded_positions(length, h, uniform_length):
    """Node positions 0 .. length: spacing h up to uniform_length, then growing by GROWTH per
    element (the last spacing stretched to end exactly at length)."""
    x = [0.0]
    step = h
    while x[-1] < length - 1e-12:
        if x[-1] >= uniform_length - 1e-12:
            step *= GROWTH
        x.append(min(x[-1] + step, length))
    if len(x) > 2 and x[-1] - x[-2] < 0.5 * (x[-2] - x[-3]):
        del x[-2]  # no sliver at the end
    return np.array(x)


def _lattice_map(mesh, xs, ys, place):
    """Maps the unit-box mesh: lattice coordinate (xi, eta) -> place(x(xi), y(eta), zeta),
    x and y piecewise linear through the node positions xs, ys (midside nodes stay on the
    midpoints of their lattice edges)."""
    gx, gy = np.linspace(0, 1, len(xs)), np.linspace(0, 1, len(ys))
    for nid, (xi, eta, zeta) in mesh.nodes.items():
        mesh.nodes[nid] = np.array(place(np.interp(xi, gx, xs), np.interp(eta, gy, ys), zeta))


def element_size(level):
    """Element size h at the contact of a mesh level; also the slab thickness."""
    return TARGET_HALF_WIDTH / (5 * 2 ** (level - 1))


def mirrored(positions):
    """Positions -x_n .. 0 .. x_n of positions 0 .. x_n."""
    return np.concatenate([-positions[:0:-1], positions])


def hertz(element="C3D8", level=1, contact_type="SURFACE TO SURFACE", full_width=False):
    h = element_size(level)
    h_block = 1.25 * h
    xs_c = graded_positions(CYLINDER_WIDTH, h, 1.5 * TARGET_HALF_WIDTH)
    ys_c = graded_positions(CYLINDER_HEIGHT, h, 1.5 * TARGET_HALF_WIDTH)
    xs_b = graded_positions(BLOCK_SIZE, h_block, 1.5 * TARGET_HALF_WIDTH)
    if full_width:
        xs_c, xs_b = mirrored(xs_c), mirrored(xs_b)
    ys_b = graded_positions(BLOCK_SIZE, h_block, 1.5 * TARGET_HALF_WIDTH)
    cylinder = meshgen.box_mesh(element, n=(len(xs_c) - 1, len(ys_c) - 1, 1))
    block = meshgen.box_mesh(element, n=(len(xs_b) - 1, len(ys_b) - 1, 1))

    def on_cylinder(x, s, zeta):  # s: distance above the arc, fraction of the local height
        bottom = RADIUS - math.sqrt(RADIUS ** 2 - x * x)
        return x, bottom + s / CYLINDER_HEIGHT * (CYLINDER_HEIGHT - bottom), zeta * h

    _lattice_map(cylinder, xs_c, ys_c, on_cylinder)
    # the block's lattice eta = 1 is its top (y = 0), graded towards it
    _lattice_map(block, xs_b, ys_b[::-1], lambda x, d, zeta: (x, -d, zeta * h))
    plane_strain = [(b, "ALL", 3, 3, 0.0) for b in ("LOWER", "UPPER")]
    in_plane = ([("UPPER", "YMAX", 1, 1, 0.0)] if full_width
                else [("LOWER", "XMIN", 1, 1, 0.0), ("UPPER", "XMIN", 1, 1, 0.0)])
    model = two_body.TwoBodyModel(
        heading="Kontakt contact model: Hertz cylinder on block, plane strain",
        lower=two_body.Body("LOWER", block, YOUNG, POISSON),
        upper=two_body.Body("UPPER", cylinder, YOUNG, POISSON),
        slave=("UPPER", "YMIN"), master=("LOWER", "YMAX"), contact_type=contact_type,
        penalty=PENALTY, tension=1.0,
        fixed=plane_strain + in_plane + [("LOWER", "YMIN", 1, 2, 0.0),
                                         ("UPPER", "YMAX", 2, 2, -DELTA)],
        node_prints=[("UPPER", "YMAX", "RF")], contact_file=True)
    model.notes = [f"Hertz line contact, generated by tests/contact_models: {element}, level "
                   f"{level}, {'full width' if full_width else 'symmetry plane x = 0'}, "
                   f"h = {h:g} at the contact (b/h = {TARGET_HALF_WIDTH / h:g}), "
                   f"thickness {h:g}, K = {PENALTY:.4g}"]
    return model
