"""Unit tests of the deck qualification rule (run: /usr/bin/python3 -m unittest)."""
import gzip
import os
import tempfile
import unittest

from select_decks import exclusion_reason, qualifying_decks, records, derived_deck

GOOD = """*HEADING
a cube
** comment *FREQUENCY
*NODE, NSET=NALL
1, 0, 0, 0
*ELEMENT, TYPE=C3D8, ELSET=EALL
1, 1, 2, 3, 4, 5, 6, 7, 8
*MATERIAL, NAME=M
*ELASTIC
210000, 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=M
*BOUNDARY
NALL, 1, 3
*STEP
*STATIC
*CLOAD
1, 3, 1.
*DLOAD
EALL, P2, 1.
*NODE PRINT, NSET=NALL
U, RF
*EL PRINT, ELSET=EALL
S, E
*END STEP
"""


class SelectDecks(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def deck(self, text, name="d"):
        path = os.path.join(self.dir, name + ".inp")
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_good_deck_qualifies(self):
        self.assertIsNone(exclusion_reason(self.deck(GOOD)))

    def test_orthotropic_elastic_and_orientation_qualify(self):
        deck = GOOD.replace("*ELASTIC\n", "*ORIENTATION, NAME=OR\n1., 0., 0., 0., 1., 0.\n"
                            "*ELASTIC, TYPE=ENGINEERING CONSTANTS\n")
        deck = deck.replace("MATERIAL=M\n", "MATERIAL=M, ORIENTATION=OR\n")
        self.assertIn("ORIENTATION=OR", deck)
        self.assertIsNone(exclusion_reason(self.deck(deck)))

    def test_each_check_names_its_reason(self):
        cases = {
            ("TYPE=C3D8,", "TYPE=S8,"): "element S8",
            ("*STEP\n", "*STEP\n*FREQUENCY\n"): "keyword *FREQUENCY",
            ("*ELASTIC\n", "*ELASTIC, TYPE=HYPO\n"): "*ELASTIC, TYPE=HYPO",
            ("*ELASTIC\n", "*EXPANSION, TYPE=ORTHO\n1e-5, 1e-5, 1e-5\n*ELASTIC\n"):
                "*EXPANSION, TYPE=ORTHO",
            ("NALL, 1, 3", "NALL, 1, 6"): "*BOUNDARY dof outside 1-3",
            ("1, 3, 1.", "1, 5, 1."): "*CLOAD dof outside 1-3",
            ("EALL, P2, 1.", "EALL, NEWTON"): "*DLOAD NEWTON (not Pn)",
            ("*STEP\n", "*STEP, NLGEOM\n"): "*STEP, NLGEOM",
            ("*STEP\n", "*STEP, PERTURBATION\n"): "*STEP, PERTURBATION",
            ("U, RF", "U, NT"): "*NODE PRINT of NT",
            ("S, E", "S, SDV"): "*EL PRINT of SDV",
            ("210000, 0.3\n", "210000, 0.3\n*PLASTIC\n800, 0\n"): "keyword *PLASTIC",
            ("*CLOAD\n", "*CLOAD, USER\n"): "*CLOAD, USER",
        }
        for (old, new), reason in cases.items():
            with self.subTest(reason=reason):
                self.assertIn(old, GOOD)
                self.assertEqual(exclusion_reason(self.deck(GOOD.replace(old, new, 1))), reason)

    def test_temperature_tables_qualify(self):
        table = GOOD.replace("210000, 0.3\n", "210000, 0.3, 0\n200000, 0.3, 100\n"
                             "*EXPANSION, ZERO=20\n1.2E-5, 0\n1.4E-5, 100\n")
        self.assertIsNone(exclusion_reason(self.deck(table)))

    def test_nonlinear_set_admits_plasticity_and_c3d8i(self):
        nl = GOOD.replace("*STEP\n", "*STEP, NLGEOM\n").replace("TYPE=C3D8,", "TYPE=C3D8I,")
        plastic = nl.replace("210000, 0.3\n", "210000, 0.3\n*PLASTIC\n800, 0, 20\n900, 0.1, 20\n")
        self.assertIsNone(exclusion_reason(self.deck(plastic), nlgeom=True))
        by_temperature = plastic.replace("900, 0.1, 20\n", "900, 0.1, 20\n700, 0, 500\n")
        self.assertIsNone(exclusion_reason(self.deck(by_temperature), nlgeom=True))
        for rule in ("KINEMATIC", "COMBINED"):
            hardened = plastic.replace("*PLASTIC\n", f"*PLASTIC, HARDENING={rule}\n", 1)
            self.assertIsNone(exclusion_reason(self.deck(hardened), nlgeom=True))
        cases = {
            ("*PLASTIC\n", "*PLASTIC, HARDENING=JOHNSON COOK\n"):
                "*PLASTIC, HARDENING=JOHNSON COOK",
        }
        for (old, new), reason in cases.items():
            with self.subTest(reason=reason):
                self.assertIn(old, plastic)
                text = plastic.replace(old, new, 1)
                self.assertEqual(exclusion_reason(self.deck(text), nlgeom=True), reason)

    def test_nonlinear_set_admits_hyperelasticity_and_hyperfoam_without_pressure(self):
        nl = GOOD.replace("*STEP\n", "*STEP, NLGEOM\n")
        hyper = nl.replace("*ELASTIC\n210000, 0.3\n", "*HYPERELASTIC, NEO HOOKE\n1.9, 0.026\n")
        self.assertEqual(exclusion_reason(self.deck(hyper), nlgeom=True),
                         "*HYPERELASTIC with *DLOAD")
        unloaded = hyper.replace("*DLOAD\nEALL, P2, 1.\n", "")
        self.assertIsNone(exclusion_reason(self.deck(unloaded), nlgeom=True))
        ogden = unloaded.replace("NEO HOOKE\n1.9, 0.026", "OGDEN, N=1\n3.488, 2.163, 0.")
        self.assertIsNone(exclusion_reason(self.deck(ogden), nlgeom=True))
        arruda = unloaded.replace("NEO HOOKE\n1.9, 0.026", "ARRUDA-BOYCE\n1., 7., .1")
        self.assertEqual(exclusion_reason(self.deck(arruda), nlgeom=True),
                         "*HYPERELASTIC, ARRUDA-BOYCE")
        foam = unloaded.replace("*HYPERELASTIC, NEO HOOKE\n1.9, 0.026", "*HYPERFOAM, N=1\n.5, 3., .2")
        self.assertIsNone(exclusion_reason(self.deck(foam), nlgeom=True))
        pressed_foam = hyper.replace("*HYPERELASTIC, NEO HOOKE\n1.9, 0.026",
                                     "*HYPERFOAM, N=1\n.5, 3., .2")
        self.assertEqual(exclusion_reason(self.deck(pressed_foam), nlgeom=True),
                         "*HYPERFOAM with *DLOAD")
        self.assertEqual(exclusion_reason(self.deck(unloaded)), "keyword *HYPERELASTIC")
        self.assertEqual(exclusion_reason(self.deck(foam)), "keyword *HYPERFOAM")

    def test_constraints_and_connectors(self):
        model_end = "*SOLID SECTION, ELSET=EALL, MATERIAL=M\n"
        nl = GOOD.replace("*STEP\n", "*STEP, NLGEOM\n")
        for card, linear, nonlinear in [
                ("*MPC\nMEANROT, 1, 1, 1, 2, 2, 2, 9\n", None, "no NLGEOM step"),
                ("*MPC\nPLANE, 1, 2, 3, 4\n", "*MPC PLANE (ccx switches NLGEOM on)", None),
                ("*MPC\nDIST, 1, 1, 1, 2, 2, 2, 9\n", "*MPC DIST", "*MPC DIST"),
                ("*RIGID BODY, NSET=NALL\n", "*RIGID BODY without REF NODE= and ROT NODE=",
                 "*RIGID BODY without REF NODE= and ROT NODE="),
                ("*RIGID BODY, NSET=NALL, REF NODE=9, ROT NODE=10\n", None, "no NLGEOM step"),
                ("*ELEMENT, TYPE=SPRINGA, ELSET=S\n2, 1, 9\n*SPRING, ELSET=S\n\n10.\n", None,
                 "no NLGEOM step"),
                ("*ELEMENT, TYPE=T3D2, ELSET=T\n2, 1, 9\n*SOLID SECTION, ELSET=T, MATERIAL=M\n"
                 "0.5\n", None, "no NLGEOM step"),
                ("*ELEMENT, TYPE=T3D3, ELSET=T\n2, 1, 9, 10\n", "element T3D3",
                 "element T3D3")]:
            with self.subTest(card=card):
                text = GOOD.replace(model_end, model_end + card)
                self.assertEqual(exclusion_reason(self.deck(text)), linear)
                if nonlinear != "no NLGEOM step":
                    text = nl.replace(model_end, model_end + card)
                    self.assertEqual(exclusion_reason(self.deck(text), nlgeom=True), nonlinear)
        loose = GOOD.replace("*STATIC\n", "*STATIC\n*CONTROLS, PARAMETERS=FIELD\n0.25, 0.25\n")
        self.assertEqual(exclusion_reason(self.deck(loose)),
                         "*CONTROLS, PARAMETERS=FIELD with R_n or C_n above 0.1")
        tight = GOOD.replace("*STATIC\n", "*STATIC\n*CONTROLS, PARAMETERS=FIELD\n1e-8, 1e-8\n")
        self.assertIsNone(exclusion_reason(self.deck(tight)))

    def test_nothing_printed(self):
        text = GOOD.replace("*NODE PRINT, NSET=NALL\nU, RF\n*EL PRINT, ELSET=EALL\nS, E\n", "")
        self.assertEqual(exclusion_reason(self.deck(text)), "no *NODE PRINT / *EL PRINT")

    def test_nonlinear_set_admits_deformation_plasticity_without_energy_prints(self):
        text = GOOD.replace("*ELASTIC\n210000, 0.3\n",
                            "*DEFORMATION PLASTICITY\n190000., .34, 900., 12., .45\n")
        text = text.replace("*STEP\n", "*STEP, NLGEOM\n")
        self.assertIn("DEFORMATION PLASTICITY", text)
        self.assertIsNone(exclusion_reason(self.deck(text), nlgeom=True))
        self.assertEqual(exclusion_reason(self.deck(text.replace("S, E\n", "S, ENER\n")),
                                          nlgeom=True),
                         "*DEFORMATION PLASTICITY with *EL PRINT of ENER or ELSE")
        self.assertEqual(exclusion_reason(self.deck(text)), "keyword *DEFORMATION PLASTICITY")

    def test_pretension_sections_qualify_without_rf_prints(self):
        cut = "*SURFACE, NAME=CUT\n1, S2\n*PRE-TENSION SECTION, SURFACE=CUT, NODE=9\n0, 0, 1\n*BOUNDARY\n"
        text = GOOD.replace("*BOUNDARY\n", cut, 1)
        self.assertEqual(exclusion_reason(self.deck(text)),
                         "*PRE-TENSION SECTION with *NODE PRINT of RF")
        self.assertIsNone(exclusion_reason(self.deck(text.replace("U, RF\n", "U\n"))))
        beam = text.replace("SURFACE=CUT, NODE", "ELEMENT=3, NODE").replace("U, RF\n", "U\n")
        self.assertEqual(exclusion_reason(self.deck(beam)), "*PRE-TENSION SECTION without SURFACE=")

    def test_first_violation_wins(self):
        text = GOOD.replace("TYPE=C3D8,", "TYPE=B32,").replace("*STEP\n", "*STEP, NLGEOM\n")
        self.assertEqual(exclusion_reason(self.deck(text)), "element B32")

    def test_gzipped_include_is_resolved(self):
        with gzip.open(os.path.join(self.dir, "mesh.msh.gz"), "wt") as f:
            f.write("*ELEMENT, TYPE=B32, ELSET=E2\n1, 1, 2, 3, 4, 5, 6, 7, 8\n")
        text = GOOD.replace("*MATERIAL", "*INCLUDE, INPUT=mesh.msh\n*MATERIAL")
        self.assertEqual(exclusion_reason(self.deck(text)), "element B32")

    def test_qualifying_decks_over_a_folder(self):
        self.deck(GOOD, "good")
        with gzip.open(os.path.join(self.dir, "zipped.inp.gz"), "wt") as f:
            f.write(GOOD.replace("TYPE=C3D8,", "TYPE=C3D20R,"))
        self.deck(GOOD.replace("*STEP\n", "*STEP, NLGEOM\n"), "nl")
        good, excluded = qualifying_decks(self.dir)
        self.assertEqual(good, ["good", "zipped"])
        self.assertEqual(excluded, {"nl": "*STEP, NLGEOM"})
        good, _ = qualifying_decks(self.dir, nlgeom=True)
        self.assertEqual(good, ["nl"])

    def test_contact_set(self):
        contact = GOOD.replace("*STEP\n", """*SURFACE, NAME=S1
EALL, S1
*SURFACE, NAME=S2
EALL, S2
*SURFACE INTERACTION, NAME=SI
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR
1e7, 3.
*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE
S1, S2
*STEP, NLGEOM
""", 1).replace("*END STEP", "*CONTACT PRINT\nCSTR, CDISP\n*END STEP")
        self.assertEqual(exclusion_reason(self.deck(contact)), "keyword *SURFACE INTERACTION")
        self.assertIsNone(exclusion_reason(self.deck(contact), contact=True))
        self.assertEqual(exclusion_reason(self.deck(GOOD), contact=True), "no *CONTACT PAIR")
        cases = {
            ("TYPE=SURFACE TO SURFACE", "TYPE=MORTAR"): "*CONTACT PAIR, TYPE=MORTAR",
            ("*CONTACT PAIR", "*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE\nS1, S2\n*CONTACT PAIR"):
                "keyword *MODEL CHANGE",
            ("CSTR, CDISP", "CSTR, CNUM"): "*CONTACT PRINT of CNUM",
            ("TYPE=C3D8,", "TYPE=C3D8I,"): "C3D8I in the contact set",
        }
        admitted = {("=LINEAR", "=TIED"), ("1e7, 3.\n", "1e7, 3.\n*FRICTION\n0.2\n")}
        for old, new in admitted:  # friction and tied contact are solved
            with self.subTest(admitted=new):
                self.assertIsNone(exclusion_reason(self.deck(contact.replace(old, new, 1)),
                                                   contact=True))
        for (old, new), reason in cases.items():
            with self.subTest(reason=reason):
                self.assertIn(old, contact)
                self.assertEqual(exclusion_reason(self.deck(contact.replace(old, new, 1)),
                                                  contact=True), reason)

    def test_tie_set(self):
        tie = GOOD.replace("*STEP\n", """*SURFACE, NAME=S1
EALL, S1
*SURFACE, NAME=S2
EALL, S2
*TIE, NAME=T1, POSITION TOLERANCE=0.01
S1, S2
*SURFACE INTERACTION, NAME=UNUSED
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED
1e7
*FRICTION
1e30, 1e7
*STEP, NLGEOM
""", 1)
        self.assertEqual(exclusion_reason(self.deck(tie)), "keyword *TIE")
        self.assertIsNone(exclusion_reason(self.deck(tie), tie=True))
        self.assertEqual(exclusion_reason(self.deck(GOOD), tie=True), "no *TIE")
        cases = {
            ("NAME=T1,", "NAME=T1, CYCLIC SYMMETRY,"): "*TIE, CYCLIC SYMMETRY",
            ("NAME=T1,", "NAME=T1, MULTISTAGE,"): "*TIE, MULTISTAGE",
            ("*SURFACE INTERACTION", "*CONTACT PAIR, INTERACTION=UNUSED, TYPE=SURFACE TO "
             "SURFACE\nS1, S2\n*SURFACE INTERACTION"): "keyword *CONTACT PAIR",
        }
        for (old, new), reason in cases.items():
            with self.subTest(reason=reason):
                self.assertIn(old, tie)
                self.assertEqual(exclusion_reason(self.deck(tie.replace(old, new, 1)), tie=True),
                                 reason)

    def test_derived_deck_drops_perturbation_steps_and_adds_prints(self):
        silent = GOOD.replace("*NODE PRINT, NSET=NALL\nU, RF\n*EL PRINT, ELSET=EALL\nS, E\n", "")
        silent = silent.replace("*ELEMENT, TYPE=C3D8, ELSET=EALL\n1, 1, 2, 3, 4, 5, 6, 7, 8\n",
                                "*ELEMENT, TYPE=C3D20, ELSET=EALL\n1, 1, 2, 3, 4, 5, 6, 7, 8, 9, "
                                "10, 11, 12, 13, 14, 15, 16,\n17, 18, 19, 20\n2, 1, 2, 3, 4, 5, "
                                "6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16,\n17, 18, 19, 20\n")
        silent += "*STEP, PERTURBATION\n*FREQUENCY\n10\n*END STEP\n"
        derived = derived_deck(self.deck(silent))
        self.assertNotIn("PERTURBATION", derived)
        self.assertNotIn("*FREQUENCY\n10", derived)
        recs = list(records(self.deck(derived, "derived")))
        sets = {p.get("NSET", p.get("ELSET")): data for k, p, data in recs if k in ("NSET", "ELSET")}
        self.assertEqual(sets["PEERNALL"], ["1"])
        self.assertEqual(sets["PEEREALL"], ["1, 2"])  # continuation lines are not labels
        keywords = [k for k, _, _ in recs]
        step = keywords.index("STEP")
        self.assertLess(keywords.index("NSET"), step)  # sets before the first step
        self.assertEqual(keywords[-3:], ["NODE PRINT", "EL PRINT", "END STEP"])
        self.assertEqual(derived_deck(self.deck(GOOD)), GOOD)  # printing decks keep their prints


if __name__ == "__main__":
    unittest.main()
