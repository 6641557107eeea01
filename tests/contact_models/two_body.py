"""Two meshed bodies and one penalty contact pair (frictionless, with Coulomb friction or TIED)
or a *TIE between them, written as a ccx/Abaqus deck. The model classes (cube, punch, patch,
hertz, ...) fill a TwoBodyModel; this file knows nothing about any particular model.

Numbering: the lower body's nodes and elements come first (ids 1..n), the upper body's
follow (offset by the lower body's counts). Node and element sets are named BODY_SET, e.g.
LOWER_ZMIN, UPPER_ZMAX (the sets of tests/verification/meshgen.py's box meshes); each body's
elements form the element set LOWER / UPPER.

Contact: `*SURFACE INTERACTION, NAME=CONTACT` with `*SURFACE BEHAVIOR,
PRESSURE-OVERCLOSURE=LINEAR` (K, sigma_inf) or `=TIED` (K only: bonded, no slip limit, tension
allowed; surface to surface only, and ccx requires a *FRICTION card for its stick slope) and
one `*CONTACT PAIR, INTERACTION=CONTACT, TYPE=...` with the face-based surfaces SLAVE and
MASTER (the boundary faces of one body whose corner nodes all lie in a node set). No SCHEME=
parameter is written: ccx does not know it; kontakt gets the scheme from `--scheme`. With `tie`
set, the bodies are bonded by `*TIE, NAME=tie` (slave SLAVE, master MASTER; ccx's MPC tie,
default position tolerance) instead.
"""
import math
import os
import sys
from dataclasses import dataclass, field

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "verification"))
import meshgen  # noqa: E402

CONTACT_TYPES = ("SURFACE TO SURFACE", "NODE TO SURFACE")
LAWS = ("LINEAR", "TIED")  # PRESSURE-OVERCLOSURE=


@dataclass
class Body:
    name: str                 # LOWER or UPPER: prefix of its sets, name of its element set
    mesh: meshgen.Mesh
    young: float
    poisson: float


@dataclass
class TwoBodyModel:
    """Everything a deck needs. Sets are named (body name, set of that body's mesh)."""
    heading: str
    lower: Body
    upper: Body
    slave: tuple              # (body name, node set): faces of that body on the set
    master: tuple
    contact_type: str = "SURFACE TO SURFACE"
    penalty: float = 1e7      # K, pressure per unit overclosure
    law: str = "LINEAR"       # PRESSURE-OVERCLOSURE= (LAWS)
    tension: float = 1.0      # sigma_inf (ccx: tension at large clearance, node to surface)
    nlgeom: bool = False
    increment: tuple = (1.0, 1.0, 1e-5, 1.0)  # *STATIC: initial, period, minimum, maximum
    max_increments: int = 100             # *STEP, INC=
    fixed: list = field(default_factory=list)      # [(body, nset, first dof, last dof, value)]
    pressures: list = field(default_factory=list)  # [(body, nset, pressure)] on boundary faces
    cloads: list = field(default_factory=list)     # [(body, node of that body, dof, force)]
    node_prints: list = field(default_factory=list)  # [(body, nset, "U" / "U,RF" ...)]
    el_prints: list = field(default_factory=list)    # [(body, "S")]: the whole body
    contact_print: str = ""   # e.g. "CSTR,CDIS" (empty: no *CONTACT PRINT)
    contact_file: bool = False  # *NODE FILE U and *CONTACT FILE CDIS,CSTR (frd / HDF5 fields)
    notes: list = field(default_factory=list)       # ** comment lines at the top of the deck
    friction: tuple = None    # (mu, lambda): *FRICTION of the interaction
    # further *STEPs after the first: [(increment tuple, [(body, nset, first dof, last dof,
    # value)])], each adding prescribed displacements (loads and supports carry over)
    later_steps: list = field(default_factory=list)
    tie: str = ""             # *TIE name: the bodies are tied (MPCs), no contact pair

    def body(self, name):
        return {self.lower.name: self.lower, self.upper.name: self.upper}[name]

    def node_offset(self, name):
        return 0 if name == self.lower.name else max(self.lower.mesh.nodes)

    def element_offset(self, name):
        return 0 if name == self.lower.name else max(self.lower.mesh.elements)

    def faces(self, name, nset):
        """[(global element id, face number)] of the body's faces on the node set."""
        off = self.element_offset(name)
        return [(off + e, f) for e, f in self.body(name).mesh.faces_on(nset)]

    def node_set(self, name, nset):
        off = self.node_offset(name)
        return [off + n for n in self.body(name).mesh.nsets[nset]]

    def with_contact_type(self, contact_type):
        """A copy of the model with another *CONTACT PAIR TYPE (everything else shared)."""
        if contact_type not in CONTACT_TYPES:
            raise ValueError(f"contact type {contact_type!r}: one of {CONTACT_TYPES}")
        copy = TwoBodyModel(**self.__dict__)
        copy.contact_type = contact_type
        return copy

    def write(self, path):
        with open(path, "w") as f:
            f.write(deck_text(self))
        return path


def rotate_translate(mesh, angle_deg, centre, translation):
    """Rotates every node of the mesh about the vertical axis through `centre` (x, y) by
    angle_deg (counter-clockwise seen from +z), then translates it (in place)."""
    c, s = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    rot = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    pivot = np.array([centre[0], centre[1], 0.0])
    for nid, x in mesh.nodes.items():
        mesh.nodes[nid] = rot @ (x - pivot) + pivot + np.asarray(translation, float)


def _set_name(body, nset):
    return f"{body}_{nset}"


def deck_text(model):
    fmt = meshgen._fmt
    lines = [f"** {n}" for n in model.notes]
    lines += ["*HEADING", model.heading, "*NODE, NSET=NALL"]
    for body in (model.lower, model.upper):
        off = model.node_offset(body.name)
        for nid in sorted(body.mesh.nodes):
            x, y, z = body.mesh.nodes[nid]
            lines.append(f"{off + nid}, {fmt(x)}, {fmt(y)}, {fmt(z)}")
    for body in (model.lower, model.upper):
        off_n, off_e = model.node_offset(body.name), model.element_offset(body.name)
        lines.append(f"*ELEMENT, TYPE={body.mesh.etype}, ELSET={body.name}")
        for eid in sorted(body.mesh.elements):
            row = [str(off_e + eid)] + [str(off_n + n) for n in body.mesh.elements[eid]]
            chunks = [row[k:k + 16] for k in range(0, len(row), 16)]  # ccx: 16 per line
            lines += [", ".join(ch) + ("," if k < len(chunks) - 1 else "")
                      for k, ch in enumerate(chunks)]
    used_sets = ({(b, s) for b, s, *_ in model.fixed}
                 | {(b, s) for _, fixed in model.later_steps for b, s, *_ in fixed}
                 | {(b, s) for b, s, _ in model.node_prints})
    for body, nset in sorted(used_sets):
        lines.append(f"*NSET, NSET={_set_name(body, nset)}")
        lines += meshgen._id_lines(model.node_set(body, nset))
    for surface, (body, nset) in (("SLAVE", model.slave), ("MASTER", model.master)):
        lines.append(f"*SURFACE, NAME={surface}, TYPE=ELEMENT")
        lines += [f"{e}, S{f}" for e, f in model.faces(body, nset)]
    for body in (model.lower, model.upper):
        lines += [f"*MATERIAL, NAME={body.name}_MATERIAL", "*ELASTIC",
                  f"{fmt(body.young)}, {fmt(body.poisson)}",
                  f"*SOLID SECTION, ELSET={body.name}, MATERIAL={body.name}_MATERIAL"]
    if model.tie:
        lines += [f"*TIE, NAME={model.tie}", "SLAVE, MASTER"]
    else:
        if model.law not in LAWS:
            raise ValueError(f"pressure-overclosure law {model.law!r}: one of {LAWS}")
        if model.law == "TIED" and not model.friction:
            raise ValueError("a TIED law needs friction=(mu, lambda): lambda is its stick slope")
        law_data = [model.penalty] + ([model.tension] if model.law == "LINEAR" else [])
        lines += ["*SURFACE INTERACTION, NAME=CONTACT",
                  f"*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE={model.law}",
                  ", ".join(fmt(v) for v in law_data)]
        if model.friction:
            lines += ["*FRICTION", ", ".join(fmt(v) for v in model.friction)]
        lines += [f"*CONTACT PAIR, INTERACTION=CONTACT, TYPE={model.contact_type}",
                  "SLAVE, MASTER"]
    lines += _step_lines(model, model.increment, model.fixed, model.pressures, model.cloads)
    for increment, fixed in model.later_steps:
        lines += _step_lines(model, increment, fixed, [], [])
    return "\n".join(lines) + "\n"


def _step_lines(model, increment, fixed, pressures, cloads):
    """One *STEP with its supports, loads and output requests."""
    fmt = meshgen._fmt
    lines = [f"*STEP{', NLGEOM' if model.nlgeom else ''}, INC={model.max_increments}",
             "*STATIC", ", ".join(fmt(v) for v in increment)]
    if fixed:
        lines.append("*BOUNDARY")
        for body, nset, first, last, value in fixed:
            lines.append(f"{_set_name(body, nset)}, {first}, {last}, {fmt(value)}")
    if cloads:
        lines.append("*CLOAD")
        for body, nid, dof, force in cloads:
            lines.append(f"{model.node_offset(body) + nid}, {dof}, {fmt(force)}")
    for body, nset, pressure in pressures:
        lines.append("*DLOAD")
        lines += [f"{e}, P{f}, {fmt(pressure)}" for e, f in model.faces(body, nset)]
    for body, nset, variables in model.node_prints:
        lines += [f"*NODE PRINT, NSET={_set_name(body, nset)}", variables]
    for body, variables in model.el_prints:
        lines += [f"*EL PRINT, ELSET={body}", variables]
    if model.contact_print:
        lines += ["*CONTACT PRINT", model.contact_print]
    if model.contact_file:
        lines += ["*NODE FILE", "U", "*CONTACT FILE", "CDIS, CSTR"]
    lines.append("*END STEP")
    return lines
