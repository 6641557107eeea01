"""Hüeber's two blocks: two elastic squares, one on top of the other, plane strain; the upper
one pressed down onto the lower by a prescribed settlement of its top, the lower one pushed in
and dragged down at its sides.

Figures carried over from the ccx test suite's hueeber1 deck (Hüeber's thesis, example p. 44);
the model below is built from them, not from the deck's text:
  - y is vertical. The lower block [0, s] x [0, s], the upper block [0, s] x [s, 2 s], s = 0.01;
    one element layer of thickness 0.001 in z with u_z = 0 at every node (plane strain).
  - lower block E = 15e9, nu = 0.2; upper block E = 20e9, nu = 0.4.
  - supports: the lower block's bottom (y = 0) fixed in x, y; the upper block's top (y = 2 s)
    fixed in x and moved down by u_y = -5e-7 (what presses the blocks together: the side loads
    alone pull the lower block's top away).
  - load: a uniform traction on the lower block's sides x = 0 and x = s, 1e5 inwards and 1e6
    downwards (1 N and 10 N per side over its 1e-5 area), as consistent nodal forces.
  - contact: frictionless, linear penalty K = 1e15, sigma_inf = 3 (the 'hard' decks 1/2); slave
    the lower block's top, master the upper block's bottom (the deck's *CONTACT PAIR lists the
    lower block's face first, and ccx takes the first surface as the slave).
  - mesh: the suite's deck has 60 x 60 elements in the lower block and 70 x 70 in the upper, so
    no interface node of one body meets one of the other. Scale f keeps that ratio with 6 f and
    7 f elements per side (f = 10: the deck's mesh); level k is f = 2^(k-1) (level 4: 48 and 56).
"""
import two_body
from two_body import meshgen

SIDE, THICKNESS = 0.01, 0.001
LOWER_YOUNG, LOWER_POISSON = 15e9, 0.2
UPPER_YOUNG, UPPER_POISSON = 20e9, 0.4
INWARD_TRACTION, DOWNWARD_TRACTION = 1e5, 1e6
TOP_SETTLEMENT = -5e-7  # u_y of the upper block's top
PENALTY, TENSION = 1e15, 3.0
LOWER_BASE, UPPER_BASE = 6, 7  # elements per side at level 1: the deck's 60 : 70
DECK_SCALE = 10  # the suite deck's 60 and 70 elements per side


def elements_per_side(level):
    """(lower, upper) elements per side of a mesh level."""
    return LOWER_BASE * 2 ** (level - 1), UPPER_BASE * 2 ** (level - 1)


def block_mesh(n, y0):
    """A C3D8 square [0, SIDE] x [y0, y0 + SIDE] of n x n elements, one layer thick."""
    return meshgen.box_mesh("C3D8", n=(n, n, 1), size=(SIDE, SIDE, THICKNESS),
                            origin=(0.0, y0, 0.0))


def side_loads(mesh):
    """[(node, dof, force)]: the traction on the sides x = 0 and x = SIDE as consistent nodal
    forces (inward in x, downward in y)."""
    out = []
    for nset, inward in (("XMIN", 1.0), ("XMAX", -1.0)):
        for node, area in sorted(mesh.consistent_face_weights(nset).items()):
            out += [(node, 1, inward * INWARD_TRACTION * area),
                    (node, 2, -DOWNWARD_TRACTION * area)]
    return out


def hueeber(level=2, contact_type="SURFACE TO SURFACE"):
    """The two blocks at a mesh level (elements_per_side)."""
    return blocks(2 ** (level - 1), contact_type, f"level {level}")


def blocks(scale, contact_type="SURFACE TO SURFACE", label=None):
    """The two blocks with 6 scale and 7 scale elements per side; prints U of the lower block's
    top and writes nodal contact results (frd / HDF5)."""
    n_lower, n_upper = LOWER_BASE * scale, UPPER_BASE * scale
    lower, upper = block_mesh(n_lower, 0.0), block_mesh(n_upper, SIDE)
    plane_strain = [(b, "ALL", 3, 3, 0.0) for b in ("LOWER", "UPPER")]
    model = two_body.TwoBodyModel(
        heading="Kontakt contact model: Hueeber's two blocks, plane strain",
        lower=two_body.Body("LOWER", lower, LOWER_YOUNG, LOWER_POISSON),
        upper=two_body.Body("UPPER", upper, UPPER_YOUNG, UPPER_POISSON),
        slave=("LOWER", "YMAX"), master=("UPPER", "YMIN"), contact_type=contact_type,
        penalty=PENALTY, tension=TENSION,
        fixed=plane_strain + [("LOWER", "YMIN", 1, 2, 0.0), ("UPPER", "YMAX", 1, 1, 0.0),
                              ("UPPER", "YMAX", 2, 2, TOP_SETTLEMENT)],
        cloads=[("LOWER", node, dof, force) for node, dof, force in side_loads(lower)],
        node_prints=[("LOWER", "YMAX", "U")], contact_file=True)
    label = label or f"scale {scale}"
    model.notes = [f"Hueeber's two blocks (ccx suite hueeber1; Hueeber's thesis p. 44), generated "
                   f"by tests/contact_models: {label}, lower {n_lower}^2, upper {n_upper}^2 "
                   f"C3D8, one layer, K = {PENALTY:g}"]
    return model

