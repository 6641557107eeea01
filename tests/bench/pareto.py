"""Pareto fronts of (wall time, error) runs and whether one front dominates another: the pure
part of time_vs_error.py (issue 13), unit-tested in test_time_vs_error.py.

A run is a (time, error) pair; smaller is better in both. A run beats another when it is no
worse in both and better in at least one; the front is the runs no other run beats.
"""
from dataclasses import dataclass


def beats(a, b):
    """Whether run a = (time, error) beats run b: no worse in both, better in one."""
    return a[0] <= b[0] and a[1] <= b[1] and (a[0] < b[0] or a[1] < b[1])


def pareto_front(runs):
    """The runs no other run beats, sorted by time (then error). Runs without an error (None:
    not converged or not measured) are not candidates. Identical runs do not beat each other:
    all copies stay."""
    candidates = [r for r in runs if r[1] is not None]
    return sorted(r for r in candidates if not any(beats(o, r) for o in candidates))


@dataclass
class Verdict:
    dominates: bool    # every run of the other front is matched: no slower and no less accurate
    unmatched: list    # the other front's runs that no run of this front matches
    matched: list      # [(other's run, the fastest run of this front matching it)]
    reason: str        # a sentence saying why, with the figures


def dominance(front, other, error_tolerance=0.0):
    """Whether `front` dominates `other`: each run of `other` has a run in `front` that is no
    slower and no less accurate (lower error at equal time, lower time at equal error); errors
    within the relative `error_tolerance` of each other count as equal. An empty `other` (the
    other solver converged nowhere) is dominated by any non-empty front; an empty `front`
    dominates nothing."""
    if not front:
        return Verdict(False, list(other), [], "no converged run on this side")
    matched, unmatched = [], []
    for run in other:
        match = [r for r in front if r[0] <= run[0] and r[1] <= run[1] * (1 + error_tolerance)]
        if match:
            matched.append((run, min(match)))
        else:
            unmatched.append(run)
    if not other:
        return Verdict(True, [], [], "the other side converged nowhere")
    reason = (f"all {len(other)} runs of the other front matched" if not unmatched else
              f"{len(unmatched)} of {len(other)} runs of the other front not matched: "
              + ", ".join(f"{t:.3g} s / {e:.3g}" for t, e in unmatched))
    return Verdict(not unmatched, unmatched, matched, reason)
