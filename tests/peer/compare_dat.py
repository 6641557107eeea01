"""Block-by-block comparison of two .dat files in ccx's layout.

For nonlinear runs (common_times_only) only the blocks at times both files printed are
compared, and the last printed time must agree.

A block is a header line (` <what> for set <SET> and time <t>`) and the rows after it. Blocks
are matched in order and must agree in header text (the time included), row count and row keys
(node, or element and integration point). The error of a block is
    max |ours - reference| over its values / max |reference| over its values,
and a block whose reference is all zero is compared absolutely against ZERO_BLOCK_ABS.
"""
import re

ZERO_BLOCK_ABS = 1e-12
_ROW = re.compile(r"^\s*-?\d")


def parse_blocks(text):
    """[(header, [(key tuple, [values])])] of a .dat file's text."""
    blocks = []
    for line in text.splitlines():
        if not line.strip():
            continue
        if not _ROW.match(line):
            blocks.append((re.sub(r"\s+", " ", line.strip()), []))
            continue
        if not blocks:
            raise ValueError(f"data row before any block header: {line!r}")
        fields = line.split()
        header = blocks[-1][0]
        # Integration-point rows carry (element, point); total rows carry no key at all.
        if header.startswith("total"):
            key, values = (), fields
        elif "integ.pnt." in header:
            key, values = (int(fields[0]), int(fields[1])), fields[2:]
        else:
            key, values = (int(fields[0]),), fields[1:]
        blocks[-1][1].append((key, [float(v) for v in values]))
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
    if ours and ref and max(times_o) != max(times_r):
        problems.append(f"last printed time {max(times_o)} where the reference has {max(times_r)}")
    common = times_o & times_r
    return ([b for b in ours if block_time(b[0]) in common],
            [b for b in ref if block_time(b[0]) in common], problems)


def compare(ours_text, reference_text, common_times_only=False):
    """(worst error, [problem strings]); structural mismatches are problems with error inf.
    With common_times_only, blocks at times only one file printed are left out."""
    ours, ref = parse_blocks(ours_text), parse_blocks(reference_text)
    problems, worst = [], 0.0
    if common_times_only:
        ours, ref, problems = keep_common_times(ours, ref)
    if len(ours) != len(ref):
        problems.append(f"{len(ours)} blocks, reference has {len(ref)}")
    for (h_o, rows_o), (h_r, rows_r) in zip(ours, ref):
        if h_o != h_r:
            problems.append(f"header {h_o!r} where the reference has {h_r!r}")
            continue
        if [k for k, _ in rows_o] != [k for k, _ in rows_r]:
            problems.append(f"{h_r}: rows differ ({len(rows_o)} vs {len(rows_r)} or other keys)")
            continue
        if any(len(a) != len(b) for (_, a), (_, b) in zip(rows_o, rows_r)):
            problems.append(f"{h_r}: different number of values in a row")
            continue
        scale = max((abs(v) for _, vals in rows_r for v in vals), default=0.0)
        diff = max((abs(a - b) for (_, va), (_, vb) in zip(rows_o, rows_r)
                    for a, b in zip(va, vb)), default=0.0)
        error = diff / scale if scale > 0 else (0.0 if diff <= ZERO_BLOCK_ABS else float("inf"))
        worst = max(worst, error)
    if problems:
        worst = float("inf")
    return worst, problems
