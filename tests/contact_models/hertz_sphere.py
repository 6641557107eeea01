"""Hertz point contact: an elastic sphere pressed on an elastic block, as a quarter model
(symmetry planes x = 0 and y = 0). The contact-heavy model of the contact benchmark: at a/h = 20
its contact zone holds about ten thousand lgc7 integration points. `half=True` mirrors both
meshes about x = 0 (symmetry plane y = 0 only: the model for tangential loads along x,
tests/contact_models/cattaneo.py); the cap's top is then also held in x.

Geometry (R = 1): the sphere's cap [0, W]^2 above the sphere z = R - sqrt(R^2 - x^2 - y^2)
(touching the block at the origin) up to the plane z = H; the block [0, L]^2 x [-D, 0]. Both are
meshed on graded lattices: element size h uniform over [0, 1.5 a] next to the contact (a = the
target contact radius), then growing by at most 15 % per element; the block's in-plane size is
1.25 h (non-matching interface), its depth and the cap's height graded the same way from the
interface.

Material: E = 1000, nu = 0.3 in both bodies: E* = E / (2 (1 - nu^2)) = 549.45.
Supports: u_x = 0 on x = 0 and u_y = 0 on y = 0 (both bodies), block bottom fixed; load: the
cap's top moved down by DELTA in `increments` equal increments (displacement control: no rigid
body mode before contact; the force comes from the reaction). DELTA = 0.012 gives a = 0.1 R.
Penalty K = 200 E* / a_target (K a / E* >= 100, verification.md §2.3).
Slave: the sphere (finer); master: the block top. Output: *NODE PRINT RF of the cap's top (the
load), U of the sphere's surface, *CONTACT FILE (nodal CPRESS on the slave nodes).

Closed form (Johnson, ch. 4) for the load P on the whole sphere (4 times the quarter's):
    a = (3 P R / (4 E*))^(1/3),   p0 = 3 P / (2 pi a^2),   p(r) = p0 sqrt(1 - r^2 / a^2)
"""
import math

import numpy as np

import two_body
from two_body import meshgen

RADIUS, YOUNG, POISSON = 1.0, 1000.0, 0.3
E_STAR = YOUNG / (2 * (1 - POISSON ** 2))
TARGET_RADIUS = 0.1
DELTA = 0.012
PENALTY = 200 * E_STAR / TARGET_RADIUS
CAP_WIDTH, CAP_HEIGHT, BLOCK_WIDTH, BLOCK_DEPTH = 0.4, 0.45, 0.6, 0.6
IN_PLANE, THROUGH = (1.2, 1.15), (0.3, 1.3)  # (uniform length / a, growth per element)


def closed_form(load, radius=RADIUS, e_star=E_STAR):
    """(a, p0) of Hertz point contact for the load P on the whole sphere (this model's radius
    and E* unless given)."""
    a = (3 * load * radius / (4 * e_star)) ** (1 / 3)
    return a, 3 * load / (2 * math.pi * a * a)


def graded_positions(length, h, grading):
    """Node positions 0 .. length: spacing h up to grading[0] * a, then growing by grading[1]
    per element (the last spacing stretched to end exactly at length, no sliver)."""
    uniform_length, growth = grading[0] * TARGET_RADIUS, grading[1]
    x = [0.0]
    step = h
    while x[-1] < length - 1e-12:
        if x[-1] >= uniform_length - 1e-12:
            step *= growth
        x.append(min(x[-1] + step, length))
    if len(x) > 2 and x[-1] - x[-2] < 0.5 * (x[-2] - x[-3]):
        del x[-2]
    return np.array(x)


def _lattice(element, xs, ys, zs, place):
    """A box mesh on the lattice xs x ys x zs, each node then moved by place(x, y, z)."""
    mesh = meshgen.box_mesh(element, n=(len(xs) - 1, len(ys) - 1, len(zs) - 1))
    grid = [np.linspace(0, 1, len(v)) for v in (xs, ys, zs)]
    for nid, (u, v, w) in mesh.nodes.items():
        mesh.nodes[nid] = np.array(place(np.interp(u, grid[0], xs), np.interp(v, grid[1], ys),
                                         np.interp(w, grid[2], zs)))
    return mesh


def element_size(ratio):
    """Element size h at the contact for a / h = ratio."""
    return TARGET_RADIUS / ratio


def mirrored(positions):
    """Positions -x_n .. 0 .. x_n of positions 0 .. x_n."""
    return np.concatenate([-positions[:0:-1], positions])


def hertz_sphere(element="C3D8", ratio=20, increments=6, contact_type="SURFACE TO SURFACE",
                 half=False):
    h = element_size(ratio)
    xs = graded_positions(CAP_WIDTH, h, IN_PLANE)
    zs = graded_positions(CAP_HEIGHT, h, THROUGH)
    xs_b = graded_positions(BLOCK_WIDTH, 1.25 * h, IN_PLANE)
    zs_b = graded_positions(BLOCK_DEPTH, 1.25 * h, THROUGH)
    ys, ys_b = xs, xs_b
    if half:
        xs, xs_b = mirrored(xs), mirrored(xs_b)

    def on_sphere(x, y, s):  # s: height above the sphere, graded from it
        bottom = RADIUS - math.sqrt(RADIUS ** 2 - x * x - y * y)
        return x, y, bottom + s / CAP_HEIGHT * (CAP_HEIGHT - bottom)

    cap = _lattice(element, xs, ys, zs, on_sphere)
    # the block's lattice zeta = 1 is its top (z = 0), graded towards it
    block = _lattice(element, xs_b, ys_b, zs_b[::-1], lambda x, y, d: (x, y, -d))
    symmetry = [("LOWER", "XMIN", 1, 1, 0.0), ("LOWER", "YMIN", 2, 2, 0.0),
                ("UPPER", "XMIN", 1, 1, 0.0), ("UPPER", "YMIN", 2, 2, 0.0)]
    if half:  # no plane x = 0: the cap's top holds x
        symmetry = [f for f in symmetry if f[1] != "XMIN"] + [("UPPER", "ZMAX", 1, 1, 0.0)]
    dt = 1.0 / increments
    model = two_body.TwoBodyModel(
        heading="Kontakt contact model: Hertz sphere on block, quarter model",
        lower=two_body.Body("LOWER", block, YOUNG, POISSON),
        upper=two_body.Body("UPPER", cap, YOUNG, POISSON),
        slave=("UPPER", "ZMIN"), master=("LOWER", "ZMAX"), contact_type=contact_type,
        penalty=PENALTY, tension=1.0, increment=(dt, 1.0, 1e-5, dt),
        fixed=[("LOWER", "ZMIN", 1, 3, 0.0)] + symmetry + [("UPPER", "ZMAX", 3, 3, -DELTA)],
        node_prints=[("UPPER", "ZMAX", "RF"), ("UPPER", "ZMIN", "U")], contact_file=True)
    model.notes = [f"Hertz point contact, generated by tests/contact_models: {element}, a/h = "
                   f"{ratio:g} (h = {h:g} at the contact), K = {PENALTY:.4g}, "
                   f"{increments} increments"]
    return model
