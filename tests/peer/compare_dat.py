"""Block-by-block comparison of two .dat files in ccx's layout.

Layout: every output request writes a blank line, a header line such as
    ` displacements (vx,vy,vz) for set NALL and time  0.1000000E+01`
a blank line, and rows. A row starts with a number; everything else that is not blank is a
header. Row keys: the node or element number (first field); for headers containing
"integ.pnt." the element and integration point (first two fields); "total ..." rows have no
key. The remaining fields are the values.

Matching: blocks are matched in order. A block pair must have the same header text (blanks
collapsed; the time included), the same row count, the same row keys in the same order and the
same number of values per row. Anything else - missing or extra blocks included - is a
structural problem: the comparison fails with a message naming it.

Error of a block (b = the reference, ccx 2.20):
    error = max |a - b| / max |b|        (max over every value of the block)
A block passes when error <= tolerance (default 1e-4). A block whose reference is zero,
max |b| < ZERO_SCALE (1e-30), is compared absolutely instead: it passes when
max |a - b| <= ZERO_BLOCK_ABS (1e-12), and its reported error is then 0, else inf.
A value that is NaN/inf, or a field that is not a number (Fortran's `*****` overflow), makes the
block's error inf.

For nonlinear runs (common_times_only) only the blocks at times both files printed are
compared, and the last printed time must agree. For contact runs (final_time_only) only the
blocks of the last printed time are compared (it must agree); `select` (a predicate on the
header) keeps only some kinds of block, e.g. the displacements.
"""
import math
import re
from dataclasses import dataclass, field

DEFAULT_TOLERANCE = 1e-4
ZERO_SCALE = 1e-30
ZERO_BLOCK_ABS = 1e-12
_ROW = re.compile(r"^\s*[-+]?\.?\d")
_FORTRAN_EXP = re.compile(r"^([-+]?\d*\.?\d+)([-+]\d{3})$")  # 0.1234-100: E dropped by Fortran


def _number(text):
    try:
        return float(text)
    except ValueError:
        m = _FORTRAN_EXP.match(text)
        if m:
            return float(f"{m.group(1)}E{m.group(2)}")
        return float("nan")  # not a number (e.g. *****): makes the block fail


def parse_blocks(text):
    """[(header, [(key tuple, [values])])] of a .dat file's text."""
    blocks = []
    for number, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            continue
        if not _ROW.match(line):
            blocks.append((re.sub(r"\s+", " ", line.strip()), []))
            continue
        if not blocks:
            raise ValueError(f"line {number}: data row before any block header: {line!r}")
        fields = line.split()
        header = blocks[-1][0]
        # ccx marks a vector in a *TRANSFORM node's local system with L, and a tensor in an
        # element's *ORIENTATION frame with the orientation's name after its 6 components; the
        # mark goes into the row's key, so both files must print the same system.
        mark = ()
        if fields[-1] == "L" or ("integ.pnt." in header and len(fields) == 9):
            mark = (fields.pop(),)
        try:
            if header.startswith("total"):
                key, values = (), fields
            elif "integ.pnt." in header:
                key, values = (int(fields[0]), int(fields[1])), fields[2:]
            else:
                key, values = (int(fields[0]),), fields[1:]
        except (ValueError, IndexError):
            raise ValueError(f"line {number}: row without integer key in {header!r}: {line!r}")
        blocks[-1][1].append((key + mark, [_number(v) for v in values]))
    return blocks


_TIME = re.compile(r"time\s+(\S+)\s*$")


def block_time(header):
    m = _TIME.search(header)
    return float(m.group(1)) if m else None


def keep_common_times(ours, ref):
    """Blocks of the times both files printed, and a problem when the last times differ.
    Nonlinear runs may choose other increments than ccx; what both reached is comparable."""
    times_o = {block_time(h) for h, _ in ours}
    times_r = {block_time(h) for h, _ in ref}
    problems = []
    last_o = max((t for t in times_o if t is not None), default=None)
    last_r = max((t for t in times_r if t is not None), default=None)
    if ours and ref and last_o != last_r:
        problems.append(f"last printed time {last_o} where the reference has {last_r}")
    common = times_o & times_r
    return ([b for b in ours if block_time(b[0]) in common],
            [b for b in ref if block_time(b[0]) in common], problems)


def keep_final_time(ours, ref):
    """Blocks of the last printed time of each file, and a problem when those times differ.
    Contact runs may take other increments than ccx; only the final state is comparable."""
    last_o = max((t for t in (block_time(h) for h, _ in ours) if t is not None), default=None)
    last_r = max((t for t in (block_time(h) for h, _ in ref) if t is not None), default=None)
    problems = []
    if ours and ref and last_o != last_r:
        problems.append(f"last printed time {last_o} where the reference has {last_r}")
    return ([b for b in ours if block_time(b[0]) == last_o],
            [b for b in ref if block_time(b[0]) == last_r], problems)


@dataclass
class BlockResult:
    index: int       # 1-based position in the reference
    header: str
    error: float     # relative error (see module docstring); inf when not comparable
    passed: bool


@dataclass
class Comparison:
    blocks: list = field(default_factory=list)     # [BlockResult] of matched blocks
    problems: list = field(default_factory=list)   # structural problems (messages)
    worst: float = 0.0                             # max block error; inf on any problem
    passed: bool = True

    def worst_block(self):
        return max(self.blocks, key=lambda b: b.error, default=None)


def block_error(rows_o, rows_r):
    """Error of one block pair with equal keys (see the module docstring)."""
    scale, diff = 0.0, 0.0
    for (_, va), (_, vb) in zip(rows_o, rows_r):
        for a, b in zip(va, vb):
            if not (math.isfinite(a) and math.isfinite(b)):
                return float("inf")
            scale = max(scale, abs(b))
            diff = max(diff, abs(a - b))
    if scale < ZERO_SCALE:
        return 0.0 if diff <= ZERO_BLOCK_ABS else float("inf")
    return diff / scale


def _first_key_difference(rows_o, rows_r):
    for i, ((ko, _), (kr, _)) in enumerate(zip(rows_o, rows_r)):
        if ko != kr:
            return f"row {i + 1} has key {ko} where the reference has {kr}"
    return None


def compare_blocks(ours_text, reference_text, tolerance=DEFAULT_TOLERANCE,
                   common_times_only=False, final_time_only=False, select=None):
    """Comparison of two .dat texts: per-block errors, structural problems, the worst error.
    `select(header)`, when given, keeps only the blocks it accepts (applied to both files)."""
    result = Comparison()
    try:
        ours = parse_blocks(ours_text)
    except ValueError as e:
        result.problems.append(f"unparsable output: {e}")
        result.worst, result.passed = float("inf"), False
        return result
    ref = parse_blocks(reference_text)
    if common_times_only:
        ours, ref, result.problems = keep_common_times(ours, ref)
    elif final_time_only:
        ours, ref, result.problems = keep_final_time(ours, ref)
    if select:
        ours, ref = [b for b in ours if select(b[0])], [b for b in ref if select(b[0])]
    if len(ours) != len(ref):
        what = "missing" if len(ours) < len(ref) else "extra"
        n = min(len(ours), len(ref))
        first = (ref if len(ours) < len(ref) else ours)[n][0]
        result.problems.append(f"{len(ours)} blocks, reference has {len(ref)} "
                               f"(first {what} block: {first!r})")
    for i, ((h_o, rows_o), (h_r, rows_r)) in enumerate(zip(ours, ref), 1):
        if h_o != h_r:
            result.problems.append(f"block {i}: header {h_o!r} where the reference has {h_r!r}")
            continue
        if len(rows_o) != len(rows_r):
            result.problems.append(f"block {i} ({h_r}): {len(rows_o)} rows, reference has "
                                   f"{len(rows_r)}")
            continue
        key_difference = _first_key_difference(rows_o, rows_r)
        if key_difference:
            result.problems.append(f"block {i} ({h_r}): {key_difference}")
            continue
        if any(len(a) != len(b) for (_, a), (_, b) in zip(rows_o, rows_r)):
            result.problems.append(f"block {i} ({h_r}): different number of values in a row")
            continue
        error = block_error(rows_o, rows_r)
        result.blocks.append(BlockResult(i, h_r, error, error <= tolerance))
    result.worst = max((b.error for b in result.blocks), default=0.0)
    if result.problems:
        result.worst = float("inf")
    result.passed = not result.problems and all(b.passed for b in result.blocks)
    return result


def compare(ours_text, reference_text, common_times_only=False):
    """(worst error, [problem strings]); structural mismatches are problems with error inf.
    With common_times_only, blocks at times only one file printed are left out."""
    r = compare_blocks(ours_text, reference_text, common_times_only=common_times_only)
    return r.worst, r.problems


def _main(argv=None):
    import argparse
    import sys
    p = argparse.ArgumentParser(description="Compare two .dat files block by block.")
    p.add_argument("ours")
    p.add_argument("reference")
    p.add_argument("--tolerance", type=float, default=DEFAULT_TOLERANCE)
    a = p.parse_args(argv)
    with open(a.ours, errors="replace") as f, open(a.reference, errors="replace") as g:
        r = compare_blocks(f.read(), g.read(), a.tolerance)
    for b in r.blocks:
        print(f"{'ok  ' if b.passed else 'FAIL'} {b.error:9.2e}  {b.header}")
    for problem in r.problems:
        print(f"STRUCTURE  {problem}")
    print(f"worst {r.worst:.2e}: {'PASS' if r.passed else 'FAIL'}")
    sys.exit(0 if r.passed else 1)


if __name__ == "__main__":
    _main()
