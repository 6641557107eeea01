"""Unit tests of the .dat block comparison (run: /usr/bin/python3 -m unittest)."""
import unittest

from compare_dat import compare, parse_blocks

REF = """
 displacements (vx,vy,vz) for set NALL and time  0.1000000E+01

         1  1.000000E+00  0.000000E+00 -2.000000E+00
         2  5.000000E-01  1.000000E-01  0.000000E+00

 stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz) for set EALL and time  0.1000000E+01

         1   1  1.000000E+02  0.000000E+00  0.000000E+00  0.000000E+00  0.000000E+00  0.000000E+00

 total force (fx,fy,fz) for set FIX and time  0.1000000E+01

       -1.000000E+00  0.000000E+00  0.000000E+00
"""


class CompareDat(unittest.TestCase):
    def test_parses_keys_of_each_block_kind(self):
        blocks = parse_blocks(REF)
        self.assertEqual([len(rows) for _, rows in blocks], [2, 1, 1])
        self.assertEqual(blocks[0][1][1][0], (2,))
        self.assertEqual(blocks[1][1][0][0], (1, 1))
        self.assertEqual(blocks[2][1][0], ((), [-1.0, 0.0, 0.0]))

    def test_identical_files_have_zero_error(self):
        self.assertEqual(compare(REF, REF), (0.0, []))

    def test_error_is_relative_to_the_block_maximum(self):
        ours = REF.replace("5.000000E-01  1.000000E-01", "5.000000E-01  1.000400E-01")
        worst, problems = compare(ours, REF)
        self.assertEqual(problems, [])
        self.assertAlmostEqual(worst, 4e-5 / 2.0)

    def test_missing_row_is_a_structural_problem(self):
        ours = REF.replace("         2  5.000000E-01  1.000000E-01  0.000000E+00\n", "")
        worst, problems = compare(ours, REF)
        self.assertEqual(worst, float("inf"))
        self.assertIn("rows differ", problems[0])

    def test_different_time_is_a_header_mismatch(self):
        worst, problems = compare(REF.replace("0.1000000E+01", "0.2000000E+01", 1), REF)
        self.assertEqual(worst, float("inf"))
        self.assertIn("header", problems[0])

    def test_missing_block_is_reported(self):
        ours = REF[: REF.index(" total force")]
        worst, problems = compare(ours, REF)
        self.assertEqual(worst, float("inf"))
        self.assertIn("blocks", problems[0])

    def test_common_times_skip_increments_only_one_side_printed(self):
        half = REF.replace("0.1000000E+01", "0.5000000E+00")
        worst, problems = compare(half + REF, REF, common_times_only=True)
        self.assertEqual((worst, problems), (0.0, []))
        worst, problems = compare(half, REF, common_times_only=True)
        self.assertEqual(worst, float("inf"))
        self.assertIn("last printed time", problems[0])


if __name__ == "__main__":
    unittest.main()
