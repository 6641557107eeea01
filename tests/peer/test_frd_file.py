"""Unit tests of frd_file.py (the .frd reader), compare_frd.py and the file-request rule."""
import os
import tempfile
import unittest

import compare_frd
import frd_file
import select_decks


def node_line(n, *xyz):
    return " -1" + f"{n:10d}" + "".join(f"{v:12.5E}" for v in xyz)


def block(counter, name, comps, rows, time="1.000000000", step=1, inc=1, set_no=1):
    """Text of one result block; comps = [(name, type, i, j)], rows = {node: [values]}."""
    lines = [f"    1PSTEP{counter:26d}{inc:12d}{step:12d}          ",
             f"  100CL{100 + set_no:5d}{time:>12s}{len(rows):12d}{0:22d}{set_no:5d}{1:12d}",
             f" -4  {name:8s}{len(comps):5d}    1"]
    for c, t, i, j in comps:
        lines.append(f" -5  {c:8s}{1:5d}{t:5d}{i:5d}{j:5d}" + ("    1ALL" if c == "ALL" else ""))
    for n, values in rows.items():
        for k in range(0, len(values), 6):
            head = " -1" + f"{n:10d}" if k == 0 else " -2" + " " * 10
            lines.append(head + "".join(f"{v:12.5E}" for v in values[k:k + 6]))
    lines.append(" -3")
    return lines


DISP = [("D1", 2, 1, 0), ("D2", 2, 2, 0), ("D3", 2, 3, 0), ("ALL", 2, 0, 0)]
CONTACT = [(c, 4, i, j) for c, (i, j) in zip(
    ["COPEN", "CSLIP1", "CSLIP2", "CPRESS", "CSHEAR1", "CSHEAR2"],
    [(1, 1), (2, 2), (3, 3), (1, 2), (2, 3), (3, 1)])]


def frd_text(disp=None, extra=(), nodes=(1, 2, 3, 4), end=True):
    disp = disp or {n: [0.1 * n, 0.0, -0.2 * n] for n in nodes}
    lines = ["    1C", "    1UUSER" + " " * 62, "    1UMAT    1STEEL" + " " * 53,
             f"    2C{'':18s}{len(nodes):12d}{1:38d}"]
    lines += [node_line(n, float(n), 0.0, 0.0) for n in nodes] + [" -3"]
    lines += [f"    3C{'':18s}{1:12d}{1:38d}", " -1" + f"{7:10d}{3:5d}{0:5d}{1:5d}",
              " -2" + "".join(f"{n:10d}" for n in nodes[:4]), " -3"]
    lines += block(1, "DISP", DISP, disp)
    for extra_lines in extra:
        lines += extra_lines
    if end:
        lines.append(" 9999")
    return "\n".join(lines) + "\n"


class ReaderTest(unittest.TestCase):
    def test_reads_nodes_elements_and_blocks(self):
        frd = frd_file.parse(frd_text())
        self.assertEqual(frd.nodes[3], (3.0, 0.0, 0.0))
        self.assertEqual(frd.elements[7], frd_file.Element(3, 1, [1, 2, 3, 4]))
        (b,) = frd.blocks
        self.assertEqual((b.name, b.step, b.increment, b.set_number, b.time), ("DISP", 1, 1, 1, 1))
        self.assertEqual(b.components, ["D1", "D2", "D3", "ALL"])
        self.assertEqual(b.values[2], [0.2, 0.0, -0.4])
        self.assertTrue(frd.complete)

    def test_continuation_lines_join_one_node(self):
        rows = {n: [float(k + n) for k in range(8)] for n in (1, 2, 3, 4)}
        comps = [(f"C{k}", 1, 0, 0) for k in range(8)]
        frd = frd_file.parse(frd_text(extra=[block(2, "MANY", comps, rows)]))
        self.assertEqual(frd.blocks[1].values[3], [3.0, 4, 5, 6, 7, 8, 9, 10])

    def test_a_file_cut_short_is_incomplete(self):
        self.assertFalse(frd_file.parse(frd_text(end=False)).complete)

    def test_a_moved_column_is_an_error_naming_the_line(self):
        text = frd_text().replace(" -1         2 2.00000E+00", " -1          2 2.00000E+00")
        with self.assertRaisesRegex(frd_file.FrdError, r"x\.frd:\d+"):
            frd_file.parse(text, "x.frd")

    def test_a_shifted_block_name_is_an_error(self):
        text = frd_text().replace(" -4  DISP        4", " -4   DISP       4")
        with self.assertRaisesRegex(frd_file.FrdError, "left-justified"):
            frd_file.parse(text)

    def test_a_wrong_value_count_is_an_error(self):
        text = frd_text().replace("    4    1\n -5  D1", "    3    1\n -5  D1")
        with self.assertRaises(frd_file.FrdError):
            frd_file.parse(text)


class CompareTest(unittest.TestCase):
    def compare(self, ours, ref, **kw):
        return compare_frd.compare(frd_file.parse(ours), frd_file.parse(ref), **kw)

    def test_identical_files_pass_with_zero_error(self):
        r = self.compare(frd_text(), frd_text())
        self.assertTrue(r.passed())
        self.assertEqual((r.worst(), len(r.blocks), r.values()), (0.0, 1, 12))

    def test_error_is_relative_to_the_block_maximum(self):
        ours = {1: [0.1, 0, -0.2], 2: [0.2, 0, -0.4], 3: [0.3, 0, -0.6], 4: [0.4, 0, -0.8 * 1.001]}
        r = self.compare(frd_text(disp=ours), frd_text())
        self.assertAlmostEqual(r.worst(), 1e-3, places=5)
        self.assertFalse(r.passed())
        self.assertTrue(self.compare(frd_text(disp=ours), frd_text(), tolerance=2e-3).passed())

    def test_different_node_sets_fail(self):
        r = self.compare(frd_text(nodes=(1, 2, 3, 5)), frd_text())
        self.assertFalse(r.passed())
        self.assertIn("node sets differ", r.problems[0])

    def test_blocks_kontakt_does_not_write_are_skipped_and_counted(self):
        error = block(2, "ERROR", [("STR(%)", 1, 0, 0)], {n: [1.0] for n in (1, 2, 3, 4)})
        r = self.compare(frd_text(), frd_text(extra=[error]))
        self.assertTrue(r.passed())
        self.assertEqual(r.skipped, {"ERROR": 1})

    def test_a_missing_block_fails(self):
        forc = block(2, "FORC", DISP, {n: [1.0, 0, 0] for n in (1, 2, 3, 4)})
        self.assertFalse(self.compare(frd_text(), frd_text(extra=[forc])).passed())

    def test_contact_nodes_missing_on_one_side_count_as_zeros(self):
        ccx = block(2, "CONTACT", CONTACT, {3: [-1e-5, 0, 0, 100.0, 0, 0]})
        ours = block(2, "CONTACT", CONTACT, {n: ([-1e-5, 0, 0, 100.0, 0, 0] if n == 3 else
                                                 [0.0] * 6) for n in (1, 2, 3, 4)})
        self.assertTrue(self.compare(frd_text(extra=[ours]), frd_text(extra=[ccx])).passed())
        wrong = block(2, "CONTACT", CONTACT, {n: [0.0, 0, 0, 100.0, 0, 0] for n in (1, 2, 3, 4)})
        self.assertFalse(self.compare(frd_text(extra=[wrong]), frd_text(extra=[ccx])).passed())

    def test_frames_are_paired_by_time(self):
        second = block(2, "DISP", DISP, {n: [0.1 * n, 0.0, -0.2 * n] for n in (1, 2, 3, 4)},
                       time="2.000000000", set_no=2)
        one_frame, two_frames = frd_text(), frd_text(extra=[second])
        self.assertFalse(self.compare(one_frame, two_frames).passed())
        self.assertTrue(self.compare(two_frames, two_frames, frames="common").passed())
        # Frames at common times, but one run stopped early: the last times must agree.
        self.assertFalse(self.compare(one_frame, two_frames, frames="common").passed())
        self.assertFalse(self.compare(one_frame, two_frames, frames="final").passed())
        self.assertTrue(self.compare(two_frames, two_frames, frames="final").passed())

    def test_an_all_zero_block_is_compared_absolutely(self):
        zeros = {n: [0.0, 0.0, 0.0] for n in (1, 2, 3, 4)}
        tiny = {n: [1e-11, 0.0, 0.0] for n in (1, 2, 3, 4)}
        self.assertTrue(self.compare(frd_text(disp=zeros), frd_text(disp=zeros)).passed())
        self.assertFalse(self.compare(frd_text(disp=tiny), frd_text(disp=zeros)).passed())


class FileRequestRuleTest(unittest.TestCase):
    def test_file_requests_and_their_output_synonyms(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "x.inp")
            for card, expected in (("*NODE FILE\nU", True), ("*node output\nU", True),
                                   ("*CONTACT FILE\nCDIS", True), ("*EL FILE\nS", True),
                                   ("*NODE PRINT,NSET=A\nU", False)):
                with open(path, "w") as f:
                    f.write("*STEP\n*STATIC\n" + card + "\n*END STEP\n")
                self.assertEqual(select_decks.has_file_requests(path), expected, card)


if __name__ == "__main__":
    unittest.main()
