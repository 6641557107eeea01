"""Unit tests of the .dat block comparison (run: /usr/bin/python3 -m unittest)."""
import unittest

from compare_dat import compare, compare_blocks, parse_blocks

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

    def test_local_system_mark_is_part_of_the_row_key(self):
        local = REF.replace("-2.000000E+00\n", "-2.000000E+00 L\n")
        self.assertEqual(parse_blocks(local)[0][1][0], ((1, "L"), [1.0, 0.0, -2.0]))
        self.assertEqual(compare(local, local), (0.0, []))
        worst, problems = compare(REF, local)  # global where ccx printed local: a mismatch
        self.assertEqual(worst, float("inf"))
        self.assertTrue(problems)

    def test_orientation_name_is_part_of_the_row_key(self):
        row = "0.000000E+00  0.000000E+00\n\n total"
        local = REF.replace(row, "0.000000E+00  0.000000E+00 OR1                 \n\n total")
        self.assertEqual(parse_blocks(local)[1][1][0][0], (1, 1, "OR1"))
        self.assertEqual(compare(local, local), (0.0, []))
        worst, problems = compare(REF, local)  # global where ccx printed the frame's components
        self.assertEqual(worst, float("inf"))
        self.assertTrue(problems)

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
        self.assertIn("1 rows, reference has 2", problems[0])

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

    def test_final_time_only_compares_the_last_printed_state(self):
        half = REF.replace("0.1000000E+01", "0.5000000E+00")
        worse_half = half.replace("1.000000E+02", "9.000000E+01")
        r = compare_blocks(worse_half + REF, half + half.replace("0.5000000E+00", "0.7500000E+00")
                           + REF, final_time_only=True)
        self.assertEqual((r.worst, r.problems), (0.0, []))
        r = compare_blocks(half, REF, final_time_only=True)
        self.assertFalse(r.passed)
        self.assertIn("last printed time", r.problems[0])

    def test_select_keeps_only_accepted_blocks(self):
        ours = REF.replace("1.000000E+02", "2.000000E+02")
        displacements = compare_blocks(ours, REF, select=lambda h: h.startswith("displacements"))
        self.assertEqual([b.index for b in displacements.blocks], [1])
        self.assertTrue(displacements.passed)
        self.assertFalse(compare_blocks(ours, REF).passed)

    def test_per_block_errors_and_worst(self):
        ours = REF.replace("1.000000E+02", "1.000100E+02").replace("-1.000000E+00", "-1.000010E+00")
        r = compare_blocks(ours, REF)
        self.assertEqual([b.index for b in r.blocks], [1, 2, 3])
        self.assertEqual(r.blocks[0].error, 0.0)
        self.assertAlmostEqual(r.blocks[1].error, 1e-4, places=12)
        self.assertAlmostEqual(r.blocks[2].error, 1e-5, places=12)
        self.assertAlmostEqual(r.worst, 1e-4, places=12)
        self.assertEqual(r.worst_block().index, 2)

    def test_tolerance_decides_pass(self):
        ours = REF.replace("1.000000E+02", "1.000200E+02")
        self.assertFalse(compare_blocks(ours, REF).passed)
        self.assertTrue(compare_blocks(ours, REF, tolerance=1e-3).passed)
        self.assertEqual([b.passed for b in compare_blocks(ours, REF).blocks], [True, False, True])

    def test_zero_reference_block_is_compared_absolutely(self):
        zero = REF.replace("1.000000E+02", "0.000000E+00")
        tiny = zero.replace("1   1  0.000000E+00", "1   1  1.000000E-13")
        self.assertEqual(compare_blocks(tiny, zero).blocks[1].error, 0.0)
        small = zero.replace("1   1  0.000000E+00", "1   1  1.000000E-11")
        r = compare_blocks(small, zero)
        self.assertEqual(r.blocks[1].error, float("inf"))
        self.assertFalse(r.passed)

    def test_different_row_key_is_reported(self):
        ours = REF.replace("         2  5.000000E-01", "         3  5.000000E-01")
        r = compare_blocks(ours, REF)
        self.assertFalse(r.passed)
        self.assertIn("row 2 has key (3,) where the reference has (2,)", r.problems[0])

    def test_extra_block_is_reported(self):
        r = compare_blocks(REF + REF, REF)
        self.assertFalse(r.passed)
        self.assertIn("6 blocks, reference has 3 (first extra block", r.problems[0])

    def test_nan_and_overflow_fail_the_block(self):
        for bad in ("NaN", "************"):
            r = compare_blocks(REF.replace("1.000000E+02", bad), REF)
            self.assertEqual(r.blocks[1].error, float("inf"))
            self.assertFalse(r.passed)

    def test_fortran_three_digit_exponent(self):
        blocks = parse_blocks(REF.replace("1.000000E+02", "0.100000-100"))
        self.assertAlmostEqual(blocks[1][1][0][1][0], 1e-101, delta=1e-110)

    def test_headers_compare_with_blanks_collapsed(self):
        ours = REF.replace("for set NALL and time  0.1", "for set NALL and time 0.1")
        self.assertTrue(compare_blocks(ours, REF).passed)

    def test_unparsable_output_is_a_problem_not_a_crash(self):
        r = compare_blocks("         1  1.0\n" + REF, REF)
        self.assertFalse(r.passed)
        self.assertIn("unparsable", r.problems[0])


if __name__ == "__main__":
    unittest.main()
