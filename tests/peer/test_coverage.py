"""Unit tests of the coverage report's pure parts (run: /usr/bin/python3 -m unittest)."""
import os
import tempfile
import unittest

from coverage import (OTHER_GROUP, baseline_verdict, comparison_mode, markdown, read_baseline,
                      refusal_group, refusal_text)
from select_decks import is_static_only

DECK = """*NODE
1, 0, 0, 0
*MATERIAL, NAME=M
*ELASTIC
210000, 0.3
{extra}*STEP{step}
*STATIC
*END STEP
"""


class Coverage(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def deck(self, extra="", step="", second_step=""):
        path = os.path.join(self.tmp.name, "d.inp")
        with open(path, "w") as f:
            f.write(DECK.format(extra=extra, step=step) + second_step)
        return path

    def test_population_is_decks_whose_only_procedure_is_static(self):
        self.assertTrue(is_static_only(self.deck()))
        self.assertTrue(is_static_only(self.deck(extra="*CREEP\n1e-10, 3\n")))  # a material card
        self.assertFalse(is_static_only(self.deck(
            second_step="*STEP\n*FREQUENCY\n10\n*END STEP\n")))
        self.assertFalse(is_static_only(self.deck(
            second_step="*STEP\n*HEAT TRANSFER\n*END STEP\n")))
        no_step = os.path.join(self.tmp.name, "n.inp")
        with open(no_step, "w") as f:
            f.write("*NODE\n1, 0, 0, 0\n")
        self.assertFalse(is_static_only(no_step))

    def test_refusal_text_drops_the_location_and_skips_warnings(self):
        stderr = ("kontakt: warning: d.inp:3: *NODE: something\n"
                  "kontakt: error: sub/d.inp:28: *ELEMENT: element type S8R is not supported\n")
        self.assertEqual(refusal_text(stderr), "*ELEMENT: element type S8R is not supported")
        self.assertEqual(refusal_text("kontakt: error: d.inp: *STEP: the deck defines no step"),
                         "*STEP: the deck defines no step")
        self.assertEqual(refusal_text(""), "(no message)")

    def test_refusal_groups_follow_the_issue_table(self):
        cases = {
            "*ELEMENT: element type B32R is not supported": "beam elements B31/B32(R)",
            "*ELEMENT: element type S8 is not supported": "shell and membrane elements S*, M3D*",
            "*ELEMENT: element type CAX8 is not supported":
                "plane/axisymmetric elements CPE*, CPS*, CAX*",
            "*TRANSFORM: keyword not supported": "*TRANSFORM",
            "*MPC: keyword not supported": "*MPC",
            "*NODE: expected at least 2 field(s), got 1":
                "*NODE lines with an extra or empty field",
            "*NODE FILE: no output variables given": OTHER_GROUP,
            "*ELASTIC: temperature-dependent material data is not supported":
                "temperature-dependent *ELASTIC",
            "*DLOAD: load type GRAV is not supported (only P1..P6)":
                "*DLOAD CENTRIF / GRAV, *PRE-TENSION SECTION, *MODEL CHANGE",
            "*DLOAD: load type P2NP is not supported (only P1..P6)": OTHER_GROUP,
            "*TIME POINTS: keyword not supported": OTHER_GROUP,
        }
        for reason, group in cases.items():
            with self.subTest(reason=reason):
                self.assertEqual(refusal_group(reason), group)

    def test_comparison_mode_per_deck(self):
        self.assertEqual(comparison_mode(self.deck(), None), "linear")
        self.assertEqual(comparison_mode(self.deck(step=", NLGEOM"), None), "nonlinear")
        self.assertEqual(comparison_mode(self.deck(step=", NLGEOM=NO"), None), "linear")
        self.assertEqual(comparison_mode(self.deck(extra="*PLASTIC\n800, 0\n"), None), "nonlinear")
        self.assertEqual(comparison_mode(self.deck(extra="*CONTACT PAIR, INTERACTION=I, "
                                                        "TYPE=SURFACE TO SURFACE\nA, B\n"), None),
                         "contact")

    def test_baseline_regressions_and_gains(self):
        rows = [{"deck": "a", "outcome": "matches"}, {"deck": "b", "outcome": "refused"},
                {"deck": "c", "outcome": "matches"}, {"deck": "d", "outcome": "differs"}]
        lost, gained = baseline_verdict(rows, {"a", "b", "d", "gone"})
        self.assertEqual(lost, [("b", "refused"), ("d", "differs"),
                                ("gone", "not in the population")])
        self.assertEqual(gained, ["c"])
        path = os.path.join(self.tmp.name, "base.txt")
        with open(path, "w") as f:
            f.write("# header\na\n\nc  # why\n")
        self.assertEqual(read_baseline(path), {"a", "c"})

    def test_markdown_counts_outcomes_and_groups(self):
        rows = [dict(deck="a", elements="C3D8", outcome="matches", group="", mode="linear",
                     worst="1e-9", detail=""),
                dict(deck="b", elements="B32", outcome="refused", group="beams", mode="linear",
                     worst="", detail="*ELEMENT: a|b")]
        text = markdown(rows, "/suite")
        self.assertIn("| matches | 1 | 50 % |", text)
        self.assertIn("| beams | 1 |", text)
        self.assertIn("a\\|b", text)


if __name__ == "__main__":
    unittest.main()
