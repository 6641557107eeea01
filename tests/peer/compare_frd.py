#!/usr/bin/python3
"""Comparison of two .frd files (ours against ccx 2.20's), module and CLI
(`compare_frd.py OURS REF [--tolerance T] [--final-only|--common-times]`).

Structure must agree: the same nodes (labels and coordinates), the same elements (frd type,
material number, node list), and per compared output frame (frames paired by time) the same
result blocks in the same order with the same components and nodes. Values are measured per
block as compare_dat.py measures .dat blocks: error = max|ours - ccx| / max|ccx| over the
block's values, a block whose ccx values are all below 1e-30 absolutely (max|ours - ccx| <=
1e-12). A CONTACT block counts a node missing on one side as zeros: ccx lists only the slave
nodes of its node-to-surface contact elements, Kontakt every node.

Blocks Kontakt does not write (NOT_WRITTEN: ccx's ERROR estimate that S adds, MESTRAIN,
ENER, CELS, ...) are skipped on both sides and counted, never compared.
"""
import argparse
import dataclasses
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import frd_file  # noqa: E402

# ccx blocks Kontakt does not write (solver/output/README.md says why).
NOT_WRITTEN = {"ERROR", "MESTRAIN", "ENER", "CELS", "SDV", "ZZSTR"}
ABSOLUTE_FLOOR = 1e-30
ABSOLUTE_TOLERANCE = 1e-12
COORDINATE_TOLERANCE = 1e-5  # relative: both sides round to 6 significant digits


@dataclasses.dataclass
class BlockResult:
    time: float
    name: str
    error: float
    values: int


@dataclasses.dataclass
class Comparison:
    problems: list = dataclasses.field(default_factory=list)
    blocks: list = dataclasses.field(default_factory=list)   # BlockResult per compared block
    skipped: dict = dataclasses.field(default_factory=dict)  # name -> ccx blocks not written
    frames: int = 0                 # frames compared
    frame_counts: tuple = (0, 0)    # frames in ours, in ccx's
    tolerance: float = 1e-4

    def decided(self, decide=None):
        return [b for b in self.blocks if decide is None or decide(b.name)]

    def worst(self, decide=None):
        errors = [b.error for b in self.decided(decide)]
        return max(errors) if errors else 0.0

    def passed(self, decide=None):
        return not self.problems and self.worst(decide) <= self.tolerance

    def worst_per_field(self):
        out = {}
        for b in self.blocks:
            out[b.name] = max(out.get(b.name, 0.0), b.error)
        return out

    def values(self):
        return sum(b.values for b in self.blocks)


def _frames(frd):
    """[(time, [blocks])] in file order, one entry per result set."""
    frames, index = [], {}
    for b in frd.blocks:
        if b.set_number not in index:
            index[b.set_number] = len(frames)
            frames.append((b.time, []))
        frames[index[b.set_number]][1].append(b)
    return frames


def _same_time(a, b):
    return abs(a - b) <= 1e-6 * max(1.0, abs(a), abs(b))


def compare_mesh(ours, ref, result):
    if set(ours.nodes) != set(ref.nodes):
        only_ours = sorted(set(ours.nodes) - set(ref.nodes))[:5]
        only_ref = sorted(set(ref.nodes) - set(ours.nodes))[:5]
        result.problems.append(f"node sets differ (only ours {only_ours}, only ccx {only_ref})")
    else:
        for n, x in ref.nodes.items():
            y = ours.nodes[n]
            scale = max(1.0, *map(abs, x))
            if max(abs(a - b) for a, b in zip(x, y)) > COORDINATE_TOLERANCE * scale:
                result.problems.append(f"node {n}: coordinates {y} against ccx {x}")
                break
    if set(ours.elements) != set(ref.elements):
        result.problems.append("element sets differ")
        return
    for e, r in ref.elements.items():
        o = ours.elements[e]
        if (o.type, o.material, o.nodes) != (r.type, r.material, r.nodes):
            result.problems.append(f"element {e}: type/material/nodes {o.type}/{o.material}/"
                                   f"{o.nodes} against ccx {r.type}/{r.material}/{r.nodes}")
            return


def block_error(ours, ref):
    """(error, values compared, problem or None) of two blocks with the same name."""
    if ours.components != ref.components:
        return None, 0, f"{ref.name}: components {ours.components} against ccx {ref.components}"
    nodes = set(ref.values)
    if ref.name == "CONTACT":
        nodes |= set(ours.values)
    elif set(ours.values) != nodes:
        return None, 0, (f"{ref.name}: {len(ours.values)} nodes against ccx's {len(nodes)} "
                         "(different node sets)")
    zero = [0.0] * len(ref.stored_components)
    diff = scale = 0.0
    count = 0
    for n in nodes:
        for a, b in zip(ours.values.get(n, zero), ref.values.get(n, zero)):
            if a != a or b != b or abs(a) == float("inf"):
                return None, 0, f"{ref.name}: node {n} has a non-finite value"
            diff = max(diff, abs(a - b))
            scale = max(scale, abs(b))
            count += 1
    if scale < ABSOLUTE_FLOOR:
        return (0.0 if diff <= ABSOLUTE_TOLERANCE else float("inf")), count, None
    return diff / scale, count, None


def compare(ours, ref, tolerance=1e-4, frames="all"):
    """Comparison of two parsed .frd files. frames: "all" (every frame, paired in order, times
    equal), "final" (the last frame of each, times equal) or "common" (the frames at times
    both wrote; the last frames' times must agree)."""
    result = Comparison(tolerance=tolerance)
    compare_mesh(ours, ref, result)
    ours_frames, ref_frames = _frames(ours), _frames(ref)
    result.frame_counts = (len(ours_frames), len(ref_frames))
    if frames == "all":
        if len(ours_frames) != len(ref_frames):
            result.problems.append(f"{len(ours_frames)} frames against ccx's {len(ref_frames)}")
        pairs = list(zip(ours_frames, ref_frames))
    elif frames == "final":
        pairs = [(ours_frames[-1], ref_frames[-1])] if ours_frames and ref_frames else []
        if not pairs:
            result.problems.append("no result frame")
    else:
        pairs = [(o, r) for o in ours_frames for r in ref_frames if _same_time(o[0], r[0])]
        if not pairs:
            result.problems.append("no frame at a common time")
        elif not _same_time(ours_frames[-1][0], ref_frames[-1][0]):
            result.problems.append(f"last frame at time {ours_frames[-1][0]:g} against ccx's "
                                   f"{ref_frames[-1][0]:g}")
    for (t_ours, ours_blocks), (t_ref, ref_blocks) in pairs:
        if not _same_time(t_ours, t_ref):
            result.problems.append(f"frame at time {t_ours:g} against ccx's {t_ref:g}")
            continue
        result.frames += 1
        # Blocks Kontakt does not write are left out on both sides (ccx's own file in the
        # harness self-test has them on both).
        wanted = [b for b in ref_blocks if b.name not in NOT_WRITTEN]
        ours_blocks = [b for b in ours_blocks if b.name not in NOT_WRITTEN]
        for b in ref_blocks:
            if b.name in NOT_WRITTEN:
                result.skipped[b.name] = result.skipped.get(b.name, 0) + 1
        if [b.name for b in ours_blocks] != [b.name for b in wanted]:
            result.problems.append(f"time {t_ref:g}: blocks {[b.name for b in ours_blocks]} "
                                   f"against ccx's {[b.name for b in wanted]}")
            continue
        for o, r in zip(ours_blocks, wanted):
            error, count, problem = block_error(o, r)
            if problem:
                result.problems.append(f"time {t_ref:g}: {problem}")
            else:
                result.blocks.append(BlockResult(t_ref, r.name, error, count))
    return result


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("ours")
    p.add_argument("ref")
    p.add_argument("--tolerance", type=float, default=1e-4)
    g = p.add_mutually_exclusive_group()
    g.add_argument("--final-only", action="store_true", help="compare the last frames only")
    g.add_argument("--common-times", action="store_true",
                   help="compare the frames at times both files have (the last must agree)")
    args = p.parse_args()
    frames = "final" if args.final_only else "common" if args.common_times else "all"
    result = compare(frd_file.read(args.ours), frd_file.read(args.ref), args.tolerance, frames)
    for problem in result.problems:
        print("problem:", problem)
    for name, worst in result.worst_per_field().items():
        print(f"{name:8s} worst {worst:.2e}")
    print(f"{result.frames} frames, {len(result.blocks)} blocks, {result.values()} values, "
          f"skipped (not written) {result.skipped or 'none'}")
    print("PASS" if result.passed() else "FAIL")
    return 0 if result.passed() else 1


if __name__ == "__main__":
    sys.exit(main())
