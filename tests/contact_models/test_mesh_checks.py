"""Unit tests of mesh_checks: valid generated models pass, and each kind of broken mesh is
caught (inverted element, face shared by three elements, hanging node, wrong contact face).
Run: /usr/bin/python3 -m unittest test_mesh_checks   (in this folder)"""
import sys
import unittest

sys.dont_write_bytecode = True  # keep the source tree clean

import numpy as np  # noqa: E402

import mesh_checks  # noqa: E402
import patch  # noqa: E402
import thesis_blocks  # noqa: E402
from two_body import meshgen  # noqa: E402


class ValidModels(unittest.TestCase):
    def test_every_element_family_passes(self):
        for upper, lower in (("C3D10", "C3D20"), ("C3D4", "C3D8"), ("C3D15", "C3D6")):
            model = patch.patch(upper, lower, 2, 3, distortion=0.3)
            self.assertEqual(mesh_checks.check_model(model), [], (upper, lower))

    def test_rotated_punch_passes(self):
        model = thesis_blocks.punch("C3D20", n=2, x=0.1, rotation=35)
        self.assertEqual(mesh_checks.check_model(model), [])


class BrokenMeshes(unittest.TestCase):
    def test_inverted_element(self):
        mesh = meshgen.box_mesh("C3D8", n=(2, 2, 2))
        conn = mesh.elements[1]
        mesh.elements[1] = conn[4:] + conn[:4]  # top and bottom swapped: det J < 0
        self.assertTrue(mesh_checks.element_jacobians(mesh))
        self.assertTrue(mesh_checks.outward_boundary(mesh))

    def test_face_shared_by_three_elements(self):
        mesh = meshgen.box_mesh("C3D8", n=(2, 1, 1))
        mesh.elements[3] = list(mesh.elements[1])
        self.assertTrue(mesh_checks.conformity(mesh))

    def test_hanging_node(self):
        mesh = meshgen.box_mesh("C3D8", n=(2, 2, 2))
        centre = next(n for n, x in mesh.nodes.items() if np.allclose(x, 0.5))
        new = max(mesh.nodes) + 1
        mesh.nodes[new] = mesh.nodes[centre] + 0.01
        mesh.elements[1] = [new if n == centre else n for n in mesh.elements[1]]
        self.assertTrue(mesh_checks.conformity(mesh))

    def test_midside_mismatch(self):
        mesh = meshgen.box_mesh("C3D20", n=(2, 1, 1))
        new = max(mesh.nodes) + 1
        shared = set(mesh.elements[1]) & set(mesh.elements[2])
        mid = max(shared)  # a midside node on the shared face
        mesh.nodes[new] = mesh.nodes[mid].copy()
        mesh.elements[2] = [new if n == mid else n for n in mesh.elements[2]]
        self.assertTrue(mesh_checks.conformity(mesh))

    def test_contact_surface_on_the_wrong_side(self):
        model = thesis_blocks.cube("C3D8", n=2)
        model.slave = ("UPPER", "ZMAX")
        self.assertTrue(mesh_checks.contact_surfaces(model))


if __name__ == "__main__":
    unittest.main()
