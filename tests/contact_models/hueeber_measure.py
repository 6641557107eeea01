"""What a run of Hüeber's two blocks (hueeber_blocks.py) is measured by, against a fine-mesh
reference run: the lower block's top settlement and the contact pressure along the interface.

The settlement is the area-weighted mean u_y over the lower block's top (the loaded block's
contact face; consistent face weights, so nodes at the ends count half). The pressure profile
is the nodal CPRESS of the slave face (the lower block's top) against x, averaged over the two
node rows through the thickness; a run's profile is interpolated linearly at the reference's
nodes (the meshes differ). Pressure differences are scaled by the reference's peak pressure;
a reference without pressure is refused, as a model whose blocks do not press is no contact
benchmark.
"""
import os

import numpy as np

import contact_fields
import datfile


def settlement(model, displacements):
    """Area-weighted mean u_y over the lower block's top; `displacements` {node: (ux, uy, uz)}
    with the deck's node ids."""
    weights = model.lower.mesh.consistent_face_weights("YMAX")
    total = sum(weights.values())
    return sum(w * displacements[n][1] for n, w in weights.items()) / total


def pressure_profile(model, nodal):
    """(x, CPRESS) of the slave nodes sorted by x, the thickness' node rows averaged; `nodal`
    {deck node id: (COPEN, CPRESS)} (nodes without a value count as 0)."""
    body, nset = model.slave
    mesh, offset = model.body(body).mesh, model.node_offset(body)
    by_x = {}
    for n in mesh.nsets[nset]:
        x = round(float(mesh.nodes[n][0]), 12)
        by_x.setdefault(x, []).append(nodal.get(offset + n, (0.0, 0.0))[1])
    xs = sorted(by_x)
    return np.array(xs), np.array([np.mean(by_x[x]) for x in xs])


def figures(model, result_dir, name):
    """{settlement, profile} of a converged run."""
    blocks = datfile.parse(os.path.join(result_dir, name + ".dat"))
    top = datfile.find(blocks, "displacements", f"{model.lower.name}_YMAX").by_id()
    nodal = contact_fields.nodal_contact(contact_fields.result_file(result_dir, name))
    return {"settlement": settlement(model, top), "profile": pressure_profile(model, nodal)}


def errors(run_figures, reference):
    """error_u: the settlement's relative error; error_cpress: the largest pressure difference
    at the reference's slave nodes over the reference's peak pressure (ValueError without one)."""
    xs_ref, p_ref = reference["profile"]
    if not np.max(p_ref) > 0:
        raise ValueError("the reference's blocks do not press: no contact pressure to measure")
    xs, p = run_figures["profile"]
    difference = np.interp(xs_ref, xs, p) - p_ref
    return {"error_u": run_figures["settlement"] / reference["settlement"] - 1,
            "error_cpress": float(np.max(np.abs(difference)) / np.max(p_ref))}
