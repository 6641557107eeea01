"""What the thesis' punch and cube runs are measured by when no closed form exists: figures of a
run (the upper top's mean settlement, von Mises stresses at fixed points of the lower cube, the
peak nodal contact pressure) and their errors against the figures of a fine-mesh reference run.

The fixed points lie below the upper body's centre and 0.15 to either side in x, at depths 0.1,
0.3 and 0.55 under the lower top: on no element boundary of the n = 4, 8, 16 meshes, so each
lies inside exactly one element of every mesh. The stress at a point is its element's mean
over the integration points (what a mesh of that size resolves), so a coarse mesh's error
contains its averaging: that is what the comparison measures.
"""
import math
import os

import numpy as np

import contact_fields
import datfile

DEPTHS = (0.1, 0.3, 0.55)
SIDE_OFFSETS = (-0.15, 0.0, 0.15)


def with_outputs(model):
    """The model printing what the figures need: U of the upper top, S of the lower body, and
    nodal contact results (frd / HDF5)."""
    model.node_prints = [(model.upper.name, "ZMAX", "U")]
    model.el_prints = [(model.lower.name, "S")]
    model.contact_file = True
    return model


def fixed_points(centre):
    """The points (x, y, z) below `centre` (x, y of the upper body's centre line)."""
    return [(centre[0] + dx, centre[1], 1.0 - d) for d in DEPTHS for dx in SIDE_OFFSETS]


def von_mises(s):
    sxx, syy, szz, sxy, sxz, syz = s
    return math.sqrt(0.5 * ((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2)
                     + 3 * (sxy ** 2 + sxz ** 2 + syz ** 2))


def element_at(mesh, point):
    """The element of an axis-aligned box mesh whose bounding box holds the point."""
    for eid, conn in mesh.elements.items():
        xyz = np.array([mesh.nodes[n] for n in conn])
        if np.all(xyz.min(axis=0) <= point) and np.all(point <= xyz.max(axis=0)):
            return eid
    raise ValueError(f"no element of the lower body holds the point {point}")


def figures(model, result_dir, name, centre):
    """{settlement, von_mises (per fixed point), peak_cpress} of a converged run."""
    blocks = datfile.parse(os.path.join(result_dir, name + ".dat"))
    top = datfile.find(blocks, "displacements", f"{model.upper.name}_ZMAX").by_id()
    settlement = float(np.mean([u[2] for u in top.values()]))
    stresses = datfile.find(blocks, "stresses", model.lower.name).rows
    per_element = {}
    for row in stresses:
        per_element.setdefault(row[0], []).append(row[2:8])
    vm = [von_mises(np.mean(per_element[element_at(model.lower.mesh, np.array(p))], axis=0))
          for p in fixed_points(centre)]
    nodal = contact_fields.nodal_contact(contact_fields.result_file(result_dir, name))
    return {"settlement": settlement, "von_mises": vm,
            "peak_cpress": max(p for _, p in nodal.values())}


def errors(run_figures, reference):
    """error_u: the settlement's relative error; error_vm: the largest von Mises difference at
    the fixed points over the reference's largest value there."""
    vm, vm_ref = np.array(run_figures["von_mises"]), np.array(reference["von_mises"])
    return {"error_u": run_figures["settlement"] / reference["settlement"] - 1,
            "error_vm": float(np.max(np.abs(vm - vm_ref)) / np.max(np.abs(vm_ref)))}
