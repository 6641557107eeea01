"""Block-by-block comparison of two .dat files in ccx's layout.

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


def compare(ours_text, reference_text):
    """(worst error, [problem strings]); structural mismatches are problems with error inf."""
    ours, ref = parse_blocks(ours_text), parse_blocks(reference_text)
    problems, worst = [], 0.0
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
