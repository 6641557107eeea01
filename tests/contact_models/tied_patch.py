"""Tied (bonded) patch tests on non-matching meshes (friction.md §5.4), bonded by *TIE, by a
PRESSURE-OVERCLOSURE=TIED surface-to-surface pair, or held by Coulomb stick (§5.5).

Two blocks: lower [0,1]^2 x [0,0.5] with 4 x 4 x 2 C3D8, upper [0,1]^2 x [0.5,1] with
5 x 5 x 2 C3D8 (the interface z = 0.5 does not match); small strain; slave = the upper body's
bottom (or, swapped, the lower body's top). Stresses are checked at every integration point.

Loads, each with a uniform exact state:
  tension  rollers on x = 0, y = 0 (both bodies) and z = 0; pressure -1 on the top: sigma_zz = 1.
           A bonded interface constrains the lateral contraction of both bodies alike only when
           nu/E is the same in both: equal materials (E 1000, nu 0.3) here.
  shear    self-equilibrated consistent nodal forces of a traction tau = 1: +x on the top, -x on
           the bottom, +z on x = 1 and -z on x = 0 (both bodies); 3-2-1 supports on three corners
           of the lower body's bottom. sigma_xz = tau for ANY pair of materials: lower E 1000,
           nu 0.3, upper E 3000, nu 0.1.
  compression_shear  pressure p = 1 on the top and the bottom plus the shear forces of tau (0.2
           by default; 3-2-1 supports): sigma_zz = -p, sigma_xz = tau. nu/E equal again, with
           different materials: lower E 1000, nu 0.1, upper E 3000, nu 0.3.
Bonds (`bond=`):
  tie      *TIE, NAME=BOND (ccx's MPCs).
  tied     *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED, K = 1e6, *FRICTION 1, 1e6 (lambda = K,
           thesis §5.5), TYPE=SURFACE TO SURFACE.
  friction LINEAR K = 1e6 with *FRICTION 0.3, 1e5 (a Coulomb pair, written surface to surface;
           solvers.write_deck gives the node-to-surface twin): compression_shear only, tau < mu p
           so that every point sticks with q = tau.
`matching=True` meshes the upper body like the lower one (4 x 4 x 2): the tie's slave nodes
then sit on master nodes, and an MPC tie must reproduce the exact state to round-off. On the
non-matching meshes a node-to-surface MPC tie does not (ccx 2.20: 10-20 % stress error).

Output: *EL PRINT S of both bodies, *NODE PRINT U of every node; no *NODE FILE request, so
kontakt's HDF5 holds U and S (at the integration points) in full precision.
"""
import two_body
from two_body import meshgen

LOADS = ("tension", "shear", "compression_shear")
BONDS = ("tie", "tied", "friction")
MATERIALS = {  # (E, nu) of lower, upper
    "tension": ((1000.0, 0.3), (1000.0, 0.3)),
    "shear": ((1000.0, 0.3), (3000.0, 0.1)),
    "compression_shear": ((1000.0, 0.1), (3000.0, 0.3)),
}
TAU = {"tension": 0.0, "shear": 1.0, "compression_shear": 0.2}  # default shear traction
PRESSURE = {"tension": -1.0, "shear": 0.0, "compression_shear": 1.0}  # on the top (and bottom)
LOWER_CELLS, UPPER_CELLS = (4, 4, 2), (5, 5, 2)
PENALTY = 1e6
TIED_FRICTION = (1.0, PENALTY)   # mu ignored by TIED (must be > 0), lambda = K
COULOMB_FRICTION = (0.3, 1e5)    # mu, lambda of the frictional stick patch test


def exact_stress(load, tau=None):
    """The uniform exact stress, ccx order xx, yy, zz, xy, xz, yz."""
    tau = TAU[load] if tau is None else tau
    return (0.0, 0.0, -PRESSURE[load], 0.0, tau, 0.0)


def _shear_forces(model, tau):
    """Consistent nodal forces of tau on every outer face but y = 0 and y = 1, summed per
    node and direction: [(body, node, dof, force)]."""
    faces = (("ZMAX", 1, 1.0), ("ZMIN", 1, -1.0), ("XMAX", 3, 1.0), ("XMIN", 3, -1.0))
    forces = {}
    for body in (model.lower, model.upper):
        for nset, dof, sign in faces:
            if (body is model.upper and nset == "ZMIN") or (body is model.lower and nset == "ZMAX"):
                continue  # the interface carries no external load
            for nid, w in body.mesh.consistent_face_weights(nset).items():
                key = (body.name, nid, dof)
                forces[key] = forces.get(key, 0.0) + sign * tau * w
    return [(b, n, d, f) for (b, n, d), f in sorted(forces.items())]


def _corner_sets(mesh):
    """Single-node sets C000, C100, C010 at the lower body's bottom corners (3-2-1 supports)."""
    for name, point in (("C000", (0, 0, 0)), ("C100", (1, 0, 0)), ("C010", (0, 1, 0))):
        mesh.nsets[name] = [mesh.nearest_node(point, "ZMIN")]


def _bond_fields(bond, load):
    """TwoBodyModel keyword arguments of a bond."""
    if bond == "tie":
        return dict(tie="BOND")
    if bond == "tied":
        return dict(law="TIED", penalty=PENALTY, friction=TIED_FRICTION)
    if load != "compression_shear":
        raise ValueError(f"a frictional patch test needs compression: load {load!r}")
    return dict(law="LINEAR", penalty=PENALTY, friction=COULOMB_FRICTION)


def tied_patch(load="tension", slave="upper", matching=False, bond="tie", tau=None):
    if load not in LOADS:
        raise ValueError(f"load {load!r}: one of {LOADS}")
    if bond not in BONDS:
        raise ValueError(f"bond {bond!r}: one of {BONDS}")
    tau = TAU[load] if tau is None else tau
    sides = {"upper": ("UPPER", "ZMIN"), "lower": ("LOWER", "ZMAX")}
    if slave not in sides:
        raise ValueError(f"slave {slave!r}: upper or lower")
    (e_lo, nu_lo), (e_up, nu_up) = MATERIALS[load]
    lower_mesh = meshgen.box_mesh("C3D8", n=LOWER_CELLS, size=(1.0, 1.0, 0.5))
    upper_mesh = meshgen.box_mesh("C3D8", n=LOWER_CELLS if matching else UPPER_CELLS,
                                  size=(1.0, 1.0, 0.5), origin=(0.0, 0.0, 0.5))
    if load == "tension":
        fixed = [("LOWER", "XMIN", 1, 1, 0.0), ("UPPER", "XMIN", 1, 1, 0.0),
                 ("LOWER", "YMIN", 2, 2, 0.0), ("UPPER", "YMIN", 2, 2, 0.0),
                 ("LOWER", "ZMIN", 3, 3, 0.0)]
        pressures = [("UPPER", "ZMAX", PRESSURE[load])]
    else:
        _corner_sets(lower_mesh)
        fixed = [("LOWER", "C000", 1, 3, 0.0), ("LOWER", "C100", 2, 3, 0.0),
                 ("LOWER", "C010", 3, 3, 0.0)]
        pressures = ([("UPPER", "ZMAX", PRESSURE[load]), ("LOWER", "ZMIN", PRESSURE[load])]
                     if PRESSURE[load] else [])
    model = two_body.TwoBodyModel(
        heading=f"Kontakt tied patch test: {load}, bond {bond}",
        lower=two_body.Body("LOWER", lower_mesh, e_lo, nu_lo),
        upper=two_body.Body("UPPER", upper_mesh, e_up, nu_up),
        slave=sides[slave], master=sides["lower" if slave == "upper" else "upper"],
        fixed=fixed, pressures=pressures,
        node_prints=[("LOWER", "ALL", "U"), ("UPPER", "ALL", "U")],
        el_prints=[("UPPER", "S"), ("LOWER", "S")], **_bond_fields(bond, load))
    if tau:
        model.cloads = _shear_forces(model, tau)
    cells = LOWER_CELLS if matching else UPPER_CELLS
    model.notes = [f"tied patch test (friction.md 5.4), generated by tests/contact_models: "
                   f"{load}, bond {bond}, slave {slave}, lower C3D8 {LOWER_CELLS}, upper C3D8 "
                   f"{cells}; exact stress {exact_stress(load, tau)} everywhere"]
    return model
