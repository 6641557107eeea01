#!/usr/bin/python3
"""Validate the layout of a kontakt results file (proto/results_layout.md).

Usage: /usr/bin/python3 check_results_layout.py FILE.hdf [...]
Needs h5py (Debian: python3-h5py, for /usr/bin/python3). Exit status 0 when every file is valid.
"""
import re
import sys

import h5py
import numpy as np

VTK_TYPES = {10: 4, 24: 10, 12: 8, 25: 20, 13: 6, 26: 15}
XDMF_NODES = {6: 4, 38: 10, 9: 8, 48: 20, 8: 6, 40: 15}
NODAL = {"U": 3, "RF": 3, "S": 6, "E": 6, "S_Mises": 1, "CPRESS": 1, "COPEN": 1, "CSHEAR1": 1,
         "CSHEAR2": 1, "CSLIP1": 1, "CSLIP2": 1, "CSTATUS": 1}
# /frames/NNNNNN/contact_points: columns of the contact point table (P rows).
CONTACT_TABLE = {"pair": (np.int64, 1), "slave_element": (np.int64, 1),
                 "slave_face": (np.int64, 1), "slave_node": (np.int64, 1),
                 "status": (np.int64, 1), "xi": (np.float64, 2), "x": (np.float64, 3),
                 "clearance": (np.float64, 1), "pressure": (np.float64, 1),
                 "slip": (np.float64, 2), "shear": (np.float64, 2), "area": (np.float64, 1),
                 "energy": (np.float64, 1)}
IP = {"S_ip": 6, "E_ip": 6, "ENER_ip": 1, "PEEQ_ip": 1}
CELL = {"EVOL": 1}


class Checker:
    def __init__(self, path):
        self.path = path
        self.errors = []

    def check(self, cond, msg):
        if not cond:
            self.errors.append(msg)
        return cond

    def fixed_string_attr(self, obj, name, expected=None, size=None, pad=None):
        if not self.check(name in obj.attrs, f"{obj.name}: missing attribute {name}"):
            return None
        tid = obj.attrs.get_id(name).get_type()
        self.check(isinstance(tid, h5py.h5t.TypeStringID), f"{obj.name}@{name}: not a string")
        if not isinstance(tid, h5py.h5t.TypeStringID):
            return None
        self.check(not tid.is_variable_str(), f"{obj.name}@{name}: variable-length string")
        self.check(tid.get_cset() == h5py.h5t.CSET_ASCII, f"{obj.name}@{name}: not ASCII")
        if size is not None:
            self.check(tid.get_size() == size, f"{obj.name}@{name}: size {tid.get_size()} != {size}")
        if pad is not None:
            self.check(tid.get_strpad() == pad, f"{obj.name}@{name}: wrong padding")
        value = obj.attrs[name]
        value = value.decode("ascii") if isinstance(value, bytes) else str(value)
        if expected is not None:
            self.check(value == expected, f"{obj.name}@{name}: {value!r} != {expected!r}")
        return value

    def dataset(self, f, path, dtype, shape=None):
        if not self.check(path in f and isinstance(f[path], h5py.Dataset), f"missing dataset {path}"):
            return None
        d = f[path]
        self.check(d.dtype == np.dtype(dtype), f"{path}: dtype {d.dtype} != {np.dtype(dtype)}")
        if shape is not None:
            self.check(d.shape == tuple(shape), f"{path}: shape {d.shape} != {tuple(shape)}")
        if d.size > 0 and d.chunks is not None:
            filters = set(d.id.get_create_plist().get_filter(i)[0]
                          for i in range(d.id.get_create_plist().get_nfilters()))
            self.check(filters <= {h5py.h5z.FILTER_DEFLATE}, f"{path}: filters other than deflate")
        return d

    def run(self):
        with h5py.File(self.path, "r") as f:
            self.fixed_string_attr(f, "format", "kontakt-results")
            self.fixed_string_attr(f, "format_version", "1.0")
            self.fixed_string_attr(f, "solver", "kontakt")
            self.fixed_string_attr(f, "solver_version")
            created = self.fixed_string_attr(f, "created")
            if created is not None:
                self.check(re.fullmatch(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d(\.\d+)?(Z|[+-]\d\d:\d\d)",
                                        created), f"created {created!r} is not RFC 3339")
            self.check_vtkhdf(f)
            self.check_mesh(f)
            self.check_frames(f)
            self.check_history(f)
        return not self.errors

    def check_vtkhdf(self, f):
        if not self.check("VTKHDF" in f, "missing /VTKHDF"):
            return
        v = f["VTKHDF"]
        if self.check("Version" in v.attrs, "/VTKHDF: missing Version"):
            ver = v.attrs["Version"]
            self.check(ver.dtype == np.int64 and list(ver) == [1, 0], f"/VTKHDF@Version {ver!r}")
        self.fixed_string_attr(v, "Type", "UnstructuredGrid", size=16, pad=h5py.h5t.STR_NULLPAD)
        npts = self.dataset(f, "VTKHDF/NumberOfPoints", np.int64, (1,))
        ncell = self.dataset(f, "VTKHDF/NumberOfCells", np.int64, (1,))
        nconn = self.dataset(f, "VTKHDF/NumberOfConnectivityIds", np.int64, (1,))
        if npts is None or ncell is None or nconn is None:
            return
        self.N, self.M = int(npts[0]), int(ncell[0])
        K = int(nconn[0])
        self.dataset(f, "VTKHDF/Points", np.float64, (self.N, 3))
        types = self.dataset(f, "VTKHDF/Types", np.uint8, (self.M,))
        offs = self.dataset(f, "VTKHDF/Offsets", np.int64, (self.M + 1,))
        conn = self.dataset(f, "VTKHDF/Connectivity", np.int64, (K,))
        if types is not None and offs is not None and conn is not None:
            t, o, c = types[()], offs[()], conn[()]
            self.check(o[0] == 0 and o[-1] == K, "Offsets do not span Connectivity")
            for i, ty in enumerate(t):
                if not self.check(int(ty) in VTK_TYPES, f"cell {i}: unknown VTK type {ty}"):
                    break
                if not self.check(o[i + 1] - o[i] == VTK_TYPES[int(ty)], f"cell {i}: node count"):
                    break
            if K:
                self.check(c.min() >= 0 and c.max() < self.N, "Connectivity out of range")
        for group, rows in (("PointData", self.N), ("CellData", self.M)):
            if not self.check(group in v, f"/VTKHDF: missing {group}"):
                continue
            for name, ds in v[group].items():
                self.check(ds.shape[0] == rows, f"/VTKHDF/{group}/{name}: {ds.shape[0]} rows")
                link = v[group].get(name, getlink=True)
                self.check(isinstance(link, h5py.HardLink), f"/VTKHDF/{group}/{name}: not a hard link")
        if "frames" in f and len(f["frames"]) and "PointData" in v:
            last = f["frames"][sorted(f["frames"])[-1]]
            for name in v["PointData"]:
                self.check(name in last and last[name] == v["PointData"][name],
                           f"/VTKHDF/PointData/{name} is not the final frame's array")

    def check_mesh(self, f):
        if not self.check("mesh" in f, "missing /mesh"):
            return
        N, M = getattr(self, "N", None), getattr(self, "M", None)
        self.dataset(f, "mesh/node_ids", np.int64, (N,) if N is not None else None)
        self.dataset(f, "mesh/element_ids", np.int64, (M,) if M is not None else None)
        if self.check("mesh/element_type" in f, "missing /mesh/element_type"):
            et = f["mesh/element_type"]
            self.check(et.dtype.kind == "S" and et.shape == (M,), "/mesh/element_type: fixed strings [M]")
        for kind in ("nsets", "elsets"):
            if self.check(f"mesh/sets/{kind}" in f, f"missing /mesh/sets/{kind}"):
                for name, ds in f[f"mesh/sets/{kind}"].items():
                    self.check(ds.dtype == np.int64 and ds.ndim == 1, f"set {kind}/{name}: int64[n]")
        topo = self.dataset(f, "mesh/xdmf_topology", np.int64)
        if topo is not None and M:
            if topo.ndim == 2:
                self.check(topo.shape[0] == M, "/mesh/xdmf_topology rows != M")
            else:
                t, i, cells = topo[()], 0, 0
                while i < len(t) and t[i] in XDMF_NODES:
                    i += 1 + XDMF_NODES[int(t[i])]
                    cells += 1
                self.check(i == len(t) and cells == M, "/mesh/xdmf_topology is not a valid Mixed array")
        if "mesh/ip_offset" in f and M is not None:
            self.dataset(f, "mesh/ip_offset", np.int64, (M + 1,))

    def check_frames(self, f):
        if not self.check("frames" in f, "missing /frames"):
            return
        names = sorted(f["frames"])
        self.check(names == [f"{i:06d}" for i in range(1, len(names) + 1)], "frames not numbered 000001..")
        n_ip = int(f["mesh/ip_offset"][-1]) if "mesh/ip_offset" in f else None
        for n in names:
            g = f["frames"][n]
            for a, kind in (("step", "i"), ("increment", "i"), ("step_time", "f"),
                            ("total_time", "f"), ("converged", "i")):
                self.check(a in g.attrs and np.asarray(g.attrs[a]).dtype.kind == kind,
                           f"/frames/{n}@{a} missing or wrong type")
            for name, ds in g.items():
                if name == "contact_points":
                    self.check_contact_points(f, f"frames/{n}/contact_points")
                    continue
                if name in NODAL:
                    shape = (self.N,) if NODAL[name] == 1 else (self.N, NODAL[name])
                elif name in IP:
                    shape = (n_ip,) if IP[name] == 1 else (n_ip, IP[name])
                elif name in CELL:
                    shape = (self.M,)
                else:
                    self.check(False, f"/frames/{n}/{name}: unknown array")
                    continue
                self.dataset(f, f"frames/{n}/{name}", np.float64, shape)

    def check_contact_points(self, f, path):
        g = f[path]
        if not self.check(isinstance(g, h5py.Group), f"/{path}: not a group"):
            return
        self.check(set(g) == set(CONTACT_TABLE), f"/{path}: columns {sorted(g)}")
        rows = g["pressure"].shape[0] if "pressure" in g else None
        for name, (dtype, width) in CONTACT_TABLE.items():
            if name in g and rows is not None:
                self.dataset(f, f"{path}/{name}", dtype, (rows,) if width == 1 else (rows, width))
        if "status" in g and g["status"].size:
            self.check(set(np.unique(g["status"][()])) <= {0, 1, 2}, f"/{path}/status not 0/1/2")

    def check_history(self, f):
        if "history" not in f:
            return  # unfinished files have no history yet
        h = self.dataset(f, "history/increments", None) if False else f.get("history/increments")
        if self.check(h is not None, "missing /history/increments"):
            want = {"step", "increment", "attempts", "iterations", "total_time", "step_time", "dt",
                    "converged", "stabilisation_energy", "strain_energy"}
            self.check(set(h.dtype.names or ()) == want, f"/history/increments fields {h.dtype.names}")


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    ok = True
    for path in argv[1:]:
        c = Checker(path)
        try:
            good = c.run()
        except Exception as e:  # noqa: BLE001 - report anything as a failure
            c.errors.append(f"exception: {e!r}")
            good = False
        print(f"{path}: {'OK' if good else 'INVALID'}")
        for e in c.errors:
            print(f"  - {e}")
        ok = ok and good
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
