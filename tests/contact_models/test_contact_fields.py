"""Unit tests of contact_fields: the last CONTACT block of an ASCII .frd and the last frame of
a kontakt HDF5 file give {node: (COPEN, CPRESS)}.
Run: /usr/bin/python3 -m unittest test_contact_fields   (in this folder)"""
import os
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True  # keep the source tree clean

import h5py  # noqa: E402
import numpy as np  # noqa: E402

import contact_fields  # noqa: E402


def frd_block(name, rows):
    lines = ["    1PSTEP                         2           1           1",
             f" -4  {name:8s}    6    1"]
    lines += [f" -1{node:10d}" + "".join(f"{v:12.5E}" for v in values) for node, values in rows]
    return "\n".join(lines + [" -3"]) + "\n"


class ContactFields(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def test_frd_last_contact_block(self):
        text = (frd_block("DISP", [(1, [9.0] * 6)])
                + frd_block("CONTACT", [(1, [-1e-7, 0, 0, 0.5, 0, 0])])
                + frd_block("CONTACT", [(1, [-2e-7, 0, 0, 1.0, 0, 0]),
                                        (7, [0, 0, 0, 0, 0, 0])]) + " 9999\n")
        path = os.path.join(self.dir, "m.frd")
        with open(path, "w") as f:
            f.write(text)
        self.assertEqual(contact_fields.nodal_contact(path), {1: (-2e-7, 1.0), 7: (0.0, 0.0)})

    def test_frd_without_contact_block_is_an_error(self):
        path = os.path.join(self.dir, "m.frd")
        with open(path, "w") as f:
            f.write(frd_block("DISP", [(1, [0.0] * 6)]))
        with self.assertRaises(ValueError):
            contact_fields.frd_contact(path)

    def test_hdf5_last_frame_by_node_label(self):
        path = os.path.join(self.dir, "m.hdf")
        with h5py.File(path, "w") as f:
            f["mesh/node_ids"] = np.array([10, 20])
            f["frames/000001/CPRESS"] = np.array([5.0, 5.0])
            f["frames/000001/COPEN"] = np.array([0.0, 0.0])
            f["frames/000002/CPRESS"] = np.array([1.5, 0.0])
            f["frames/000002/COPEN"] = np.array([-1e-7, 0.0])
        self.assertEqual(contact_fields.nodal_contact(path), {10: (-1e-7, 1.5), 20: (0.0, 0.0)})

    def test_result_file_prefers_kontakt_hdf5(self):
        self.assertIsNone(contact_fields.result_file(self.dir, "m"))
        for ext in (".frd", ".hdf"):
            open(os.path.join(self.dir, "m" + ext), "w").close()
        self.assertTrue(contact_fields.result_file(self.dir, "m").endswith(".hdf"))


if __name__ == "__main__":
    unittest.main()
