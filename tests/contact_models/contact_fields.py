"""Nodal contact results of a finished run, {node: (COPEN, CPRESS)}, from ccx's ASCII .frd
(`-4  CONTACT` block: COPEN, CSLIP1, CSLIP2, CPRESS, CSHEAR1, CSHEAR2) or from kontakt's HDF5
(/frames/NNNNNN/CPRESS and COPEN, indexed like /mesh/node_ids; proto/results_layout.md).
Both read the last frame / the last CONTACT block. Nodes without contact are reported as 0
by both solvers."""
import os


def _frd_values(line):
    """Node and values of an frd data line (` -1` + I10 + 12-character fields)."""
    node = int(line[3:13])
    values = [float(line[k:k + 12]) for k in range(13, len(line.rstrip()), 12)]
    return node, values


def frd_contact(path):
    """{node: (COPEN, CPRESS)} of the last CONTACT block of an ASCII .frd."""
    blocks, current = [], None
    with open(path, errors="replace") as f:
        for line in f:
            if line.startswith(" -4"):
                current = {} if line.split()[1] == "CONTACT" else None
                if current is not None:
                    blocks.append(current)
            elif current is not None and line.startswith(" -1"):
                node, values = _frd_values(line)
                current[node] = (values[0], values[3])
            elif line.startswith(" -3"):
                current = None
    if not blocks:
        raise ValueError(f"{path}: no CONTACT block (is *CONTACT FILE requested?)")
    return blocks[-1]


def hdf5_contact(path):
    """{node: (COPEN, CPRESS)} of the last frame of a kontakt HDF5 results file."""
    import h5py  # only the kontakt side needs it
    with h5py.File(path, "r") as f:
        frames = sorted(f["frames"])
        last = f["frames"][frames[-1]]
        ids = f["mesh/node_ids"][()]
        return dict(zip((int(i) for i in ids), zip(last["COPEN"][()], last["CPRESS"][()])))


def result_file(result_dir, name):
    """Path of a run's nodal results: kontakt's NAME.hdf, else an NAME.frd (ccx, or the ccx
    stand-in), else None."""
    for ext in (".hdf", ".frd"):
        if os.path.exists(os.path.join(result_dir, name + ext)):
            return os.path.join(result_dir, name + ext)
    return None


def nodal_contact(result_path):
    """frd_contact or hdf5_contact by the file's extension (.frd / .hdf)."""
    return frd_contact(result_path) if result_path.endswith(".frd") else hdf5_contact(result_path)
