#!/usr/bin/python3
"""Run time against error (issue 13, first slice): kontakt's contact schemes and ccx 2.20's two
pair types on the same decks of problems with a known answer, one after the other (a run under
SHORT_RUN_S is solved REPEATS times and keeps its least wall time, both solvers alike);
wall time, Newton iterations, peak memory and the errors of every run in DIR/time_vs_error.csv,
one PNG per problem (error against wall time, each solver's Pareto front as a step line) and
the per-problem dominance verdict in DIR/verdict.txt.

Problems (`setting` is what varies along a problem's axis):
  patch         seeded random contact patch tests (tests/verification/contact_patch.py's
                random variants: element types, meshes, distortion, slave side, moduli; exact
                sigma_zz = -1, CPRESS = 1); setting = the variant. error = max(error_szz,
                error_cpress): max |sigma_zz + 1| over every printed integration point of
                both bodies, max |nodal CPRESS - 1| over the nodes in contact (contact_patch's
                measure).
  hertz_sphere  3D Hertz: a quarter sphere on a block (tests/contact_models/hertz_sphere.py),
                C3D8 at a/h --ratios (4 6 8 12) and C3D20 at --quadratic-ratios (2 3 4 6: the
                same node spacing), setting = element and a/h at the contact. At the load the run measured (4 x the
                quarter's top reaction): error_p0 = peak nodal CPRESS / p0 - 1 (bench_contact's
                measure), error_p0_fit and error_radius = the fitted p0 and contact radius a of
                p^2 = p0^2 (1 - r^2 / a^2) over the slave nodes (contact_hertz's fit) against
                Hertz. error = the largest of the three magnitudes.
  hertz_penalty the penalty study: the Hertz sphere at one a/h (--penalty-ratio, 6) with the
                penalty K = r E* / a for r = K a / E* in --penalties (1 10 100 1e3 1e4; the
                other problems use 200), setting = that r; errors as hertz_sphere. Besides
                the front plot, hertz_penalty_study.png: error and Newton iterations against
                K a / E* per scheme.
  hertz_increments  the increment study: the Hertz sphere at one a/h (--increment-ratio, 6) with
                K a/E* = 10 (where the penalty study finds surface-to-surface accurate; at 200
                its pressure oscillates and hides the increment's effect) in N equal
                increments for N in --increments (1 2 3 6 12), setting = N; the
                linear variants also with the drift check off (kontakt --drift-check off,
                setting "N increments, drift check off"; ccx and the other schemes are not
                rerun there). Besides the front plot, hertz_increments_study.png.
  sliding_increments  the drift study: a cylinder pressed on a block and slid 3.7 contact
                half-widths across it, frictionless, plane strain, the block's top the slave
                (tests/contact_models/sliding_cylinder.py, level 1, K b/E* = 10), the slide in N
                increments for N in --slides (1 2 4 8 16), setting = N, the linear variants
                also with the drift check off. error_turned = max |p2(x, z) - p1(-x, h - z)| /
                max p1: the nodal pressure after the slide against the pressure before it,
                turned half about the y axis (exact for the discrete problem: what is left is
                the increment path's). Besides the front plot, sliding_increments_study.png.
  punch, cube   the thesis' punch (spherical bottom R 0.5, at the thesis' overlap -2e-4) and
                cube (touching) on the unit cube (tests/contact_models/thesis_blocks.py), C3D8
                n^3 per body for n in --block-levels (4 8), placed off centre and turned
                (x 0.05, y -0.03, 15 degrees); setting = the mesh. No closed form: errors
                against a kontakt lgc7 run at --block-reference (16^3, solved first, into
                runs/PROBLEM/reference): error_u = the upper top's mean settlement, error_vm =
                the largest von Mises difference at nine fixed points of the lower cube over
                the reference's largest there (block_measure.py: element means, points on no
                element boundary); the punch also error_p0 = peak nodal CPRESS / Hertz p0 - 1
                (a sphere of R 0.5 on a half-space under the whole load; the cube's edges make
                its peak pressure singular, so it has none).
  hertz_line    plane-strain Hertz line contact (tests/contact_models/hertz.py), setting =
                element and mesh level; error_p0, error_p0_fit, error_radius (the half-width b)
                as contact_hertz.py measures them; error = the largest magnitude.
  hueeber       Hueeber's two blocks (tests/contact_models/hueeber_blocks.py: the ccx suite's
                hueeber1 figures, plane strain, the upper block's top pressed down by 5e-7,
                non-matching meshes 6 : 7 x 2^(level-1) elements per side), setting = the level
                in --hueeber-levels (2 3 4 5). No closed form: errors against a kontakt lgc7
                run at --hueeber-reference (level 6, 192/224, solved first, into
                runs/hueeber/reference; hueeber_measure.py): error_u = the lower (loaded)
                block's top mean settlement (area-weighted u_y), error_cpress = the largest
                slave CPRESS difference along the interface (interpolated at the reference's
                nodes) over the reference's peak (a reference without pressure is refused:
                every row then is "not measured", and the smoke fails).
A run that does not converge, or whose results cannot be measured, is a row with its status (and
message) and no error; it never enters a front.

Pareto front of a solver: its runs (all schemes and settings of the problem) that no other of
its runs beats in both wall time and error. Fronts: kontakt (all schemes), kontakt lgc7, ccx
node-to-surface, ccx surface-to-surface. Verdict: kontakt's front (all, and lgc7) dominates a
ccx front when every run on the ccx front has a kontakt run on the front that is no slower and
no less accurate (tests/bench/pareto.py).

  time_vs_error.py --kontakt build/solver/app/kontakt --out DIR      # the full study
  time_vs_error.py --kontakt ... --out DIR --smoke                   # CI size, checked

--smoke: patch 2 variants, sphere a/h 4, the penalty study at K a/E* 10 and the increment study
at 1 increment (drift check on and off) on a/h 4, the punch and the cube at 4^3 against 6^3
references (the punch's coarse mesh is a hostile case: ccx's node to surface fails it, kontakt's
nts must converge), line Hertz level 1 (C3D8), Hueeber's blocks level 1 against a
level 3 reference (about 2 s), schemes nts gc7 lgc7 and
ccx's two types (no drift study: verification_contact_sliding runs its model in CI); exit code
1 when the CSV lacks a column or a row per (problem, solver, scheme, setting), or a kontakt run
did not converge with a measured error. Without --smoke only the CSV's completeness is
checked (the drift study's linear variants may stop at the increment limit: a finding).
"""
import argparse
import csv
import dataclasses
import math
import os
import sys
from dataclasses import dataclass

sys.dont_write_bytecode = True  # keep the source tree clean

import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "contact_models"))
sys.path.insert(0, os.path.join(HERE, "..", "verification"))
sys.path.insert(0, os.path.join(HERE, "..", "peer"))
import bench_contact  # noqa: E402
import block_measure  # noqa: E402
import contact_fields  # noqa: E402
import contact_hertz  # noqa: E402
import contact_patch  # noqa: E402
import frd_file  # noqa: E402
import hertz  # noqa: E402
import hertz_sphere  # noqa: E402
import hueeber_blocks  # noqa: E402
import hueeber_measure  # noqa: E402
import pareto  # noqa: E402
import patch  # noqa: E402
import sliding_cylinder  # noqa: E402
import solvers  # noqa: E402
import thesis_blocks  # noqa: E402

COLUMNS = ["problem", "solver", "scheme", "setting", "status", "wall_s", "iterations",
           "increments", "peak_mb", "error", "error_szz", "error_cpress", "error_p0",
           "error_p0_fit", "error_radius", "error_turned", "error_u", "error_vm", "message"]
KEY = ("problem", "solver", "scheme", "setting")
# the error components whose largest magnitude is a problem's headline error
HEADLINE = {"patch": ("error_szz", "error_cpress"),
            "hertz_sphere": ("error_p0", "error_p0_fit", "error_radius"),
            "hertz_penalty": ("error_p0", "error_p0_fit", "error_radius"),
            "hertz_increments": ("error_p0", "error_p0_fit", "error_radius"),
            "sliding_increments": ("error_turned",),
            "punch": ("error_u", "error_vm", "error_p0"),
            "cube": ("error_u", "error_vm"),
            "hertz_line": ("error_p0", "error_p0_fit", "error_radius"),
            "hueeber": ("error_u", "error_cpress")}
CCX_SCHEME = {"NODE TO SURFACE": "node-to-surface", "SURFACE TO SURFACE": "surface-to-surface"}
# C3D20 levels at half the C3D8 a/h: a quadratic edge has a mid-side node, so both have the same
# node spacing (and a C3D20 sphere at a/h 12 would take ccx hours per run).
FULL = dict(patch=6, ratios=[4, 6, 8, 12], quadratic_ratios=[2, 3, 4, 6], sphere_elements=["C3D8", "C3D20"], line_elements=["C3D8", "C3D20"], line_levels=[1, 2, 3],
            penalties=[1, 10, 100, 1000, 10000], penalty_ratio=6, increments=[1, 2, 3, 6, 12],
            increment_ratio=6, slides=[1, 2, 4, 8, 16], blocks=["punch", "cube"],
            block_levels=[4, 8], block_reference=16, hueeber_levels=[2, 3, 4, 5],
            hueeber_reference=6, schemes=list(solvers.SCHEMES))
SMOKE = dict(patch=2, ratios=[4], quadratic_ratios=[2], sphere_elements=["C3D8"], line_elements=["C3D8"], line_levels=[1], penalties=[10],
             penalty_ratio=4, increments=[1], increment_ratio=4, slides=[], blocks=["punch", "cube"],
             block_levels=[4], block_reference=6, hueeber_levels=[1], hueeber_reference=3,
             schemes=["nts", "gc7", "lgc7"])
DRIFT_OFF = ("--drift-check", "off")
# off centre and turned: no mesh line of either body on a plane of symmetry
BLOCK_PLACEMENT = dict(x=0.05, y=-0.03, rotation=15.0)
BLOCK_CENTRE = (0.5 + BLOCK_PLACEMENT["x"], 0.5 + BLOCK_PLACEMENT["y"])
BLOCK_REFERENCE_SCHEME = "lgc7"
INCREMENT_STUDY_PENALTY = 10  # K a / E*
DEFAULT_SEED = 2031  # not one the schemes were tuned on (contact_patch.py's default is 9)
# errors below the resolution of the printed results (ccx's .frd: 6 digits, E12.5) cannot be
# told apart: fronts, verdicts and plots take them as equal to it
ERROR_FLOOR = 1e-5
# a process start alone varies by tens of milliseconds on a shared machine, more than a small
# deck's whole solve: such runs are repeated and keep their least wall time
SHORT_RUN_S = 1.0
REPEATS = 3
# errors within 1 % of each other are equal for the verdict: the measures (six printed digits,
# a fit over a few nodes) do not resolve finer, and a 4th-digit difference is no finding
ERROR_TOLERANCE = 0.01


@dataclass
class Case:
    problem: str
    setting: str
    model: object      # two_body.TwoBodyModel
    name: str          # the deck's name
    measure: object    # (Run) -> {error component: value}
    kontakt_args: tuple = ()     # options of every kontakt run of the case
    linear_variants_only: bool = False  # only kontakt's linear variants run (no ccx)


def case_columns(case, schemes, kontakt, ccx_types):
    """[(solver, scheme, column)] of the runs a case makes."""
    out = []
    for _, column in solvers.columns(schemes, kontakt, () if case.linear_variants_only
                                     else ccx_types):
        if column in solvers.CCX_TYPES:
            out.append(("ccx", CCX_SCHEME[column], column))
        elif not case.linear_variants_only or column.startswith("l"):
            out.append(("kontakt", column, column))
    return out


def patch_errors(run):
    stress, pressure = contact_patch.errors(contact_patch.measure(run.result_dir, "patch"))
    return {"error_szz": stress, "error_cpress": pressure}


def sphere_errors(model, run):
    """error_p0 (peak nodal CPRESS), error_p0_fit, error_radius of a Hertz sphere run, each
    against Hertz at the load the run measured."""
    load = bench_contact.sphere_load(run, "sphere")
    a, p0 = hertz_sphere.closed_form(load)
    nodal = contact_fields.nodal_contact(contact_fields.result_file(run.result_dir, "sphere"))
    offset = model.node_offset("UPPER")
    pairs = [(math.hypot(*model.upper.mesh.nodes[n - offset][:2]), nodal[n][1])
             for n in model.node_set("UPPER", "ZMIN") if n in nodal]
    radii, pressures = zip(*pairs)
    p0_fit, a_fit = contact_hertz.fit(radii, pressures)
    return {"error_p0": max(pressures) / p0 - 1, "error_p0_fit": p0_fit / p0 - 1,
            "error_radius": a_fit / a - 1}


def turned_error(model, run):
    frd = frd_file.read(os.path.join(run.result_dir, "sliding.frd"))
    return {"error_turned": sliding_cylinder.mirror_error(model, frd)}


def line_errors(model, level, run):
    e = contact_hertz.relative_errors(contact_hertz.measure(model, level, run.result_dir, "hertz"))
    return {"error_p0": e["peak"], "error_p0_fit": e["p0_fit"], "error_radius": e["b_fit"]}


def block_model(problem, n):
    make = thesis_blocks.punch if problem == "punch" else thesis_blocks.cube
    return block_measure.with_outputs(make("C3D8", n=n, **BLOCK_PLACEMENT))


def block_errors(problem, model, run, reference):
    """error_u, error_vm against the reference's figures (reference(problem)); the punch's
    error_p0 against Hertz."""
    reference_figures = reference(problem)
    found = block_measure.figures(model, run.result_dir, problem, BLOCK_CENTRE)
    out = block_measure.errors(found, reference_figures)
    if problem == "punch":
        e_star = thesis_blocks.YOUNG / (2 * (1 - thesis_blocks.POISSON ** 2))
        load = thesis_blocks.PRESSURE * thesis_blocks.PUNCH_SIDE ** 2
        _, p0 = hertz_sphere.closed_form(load, thesis_blocks.PUNCH_RADIUS, e_star)
        out["error_p0"] = found["peak_cpress"] / p0 - 1
    return out


class HueeberReference:
    """The fine-mesh reference figures of Hueeber's blocks: one kontakt run at the reference
    level, solved when first asked for."""

    def __init__(self, args, level):
        self.args, self.level, self.found = args, level, None

    def __call__(self):
        if self.found is None:
            model = hueeber_blocks.hueeber(self.level)
            folder = os.path.join(self.args.out, "runs", "hueeber", "reference")
            decks = {"SURFACE TO SURFACE": solvers.write_deck(model, folder, "SURFACE TO SURFACE",
                                                              "hueeber")}
            run = solvers.solve(decks, folder, BLOCK_REFERENCE_SCHEME, self.args.kontakt,
                                self.args.timeout)
            print(f"hueeber       reference level {self.level} kontakt {BLOCK_REFERENCE_SCHEME}: "
                  f"{run.status}, {run.wall:.1f} s", flush=True)
            self.found = (hueeber_measure.figures(model, run.result_dir, "hueeber")
                          if run.converged else False)
        if self.found is False:
            raise ValueError(f"the level {self.level} reference run of the hueeber blocks did "
                             "not converge")
        return self.found


def hueeber_errors(model, run, reference):
    """error_u, error_cpress against the reference's figures (reference())."""
    reference_figures = reference()
    return hueeber_measure.errors(hueeber_measure.figures(model, run.result_dir, "hueeber"),
                                  reference_figures)


class BlockReference:
    """The fine-mesh reference figures of the punch and the cube: one kontakt run each, solved
    when first asked for."""

    def __init__(self, args, n):
        self.args, self.n, self.found = args, n, {}

    def __call__(self, problem):
        if problem not in self.found:
            model = block_model(problem, self.n)
            folder = os.path.join(self.args.out, "runs", problem, "reference")
            decks = {"SURFACE TO SURFACE": solvers.write_deck(model, folder, "SURFACE TO SURFACE",
                                                              problem)}
            run = solvers.solve(decks, folder, BLOCK_REFERENCE_SCHEME, self.args.kontakt,
                                self.args.timeout)
            print(f"{problem:13s} reference {self.n}^3 kontakt {BLOCK_REFERENCE_SCHEME}: "
                  f"{run.status}, {run.wall:.1f} s", flush=True)
            self.found[problem] = (block_measure.figures(model, run.result_dir, problem,
                                                         BLOCK_CENTRE)
                                   if run.converged else None)
        if self.found[problem] is None:
            raise ValueError(f"the {self.n}^3 reference run of the {problem} did not converge")
        return self.found[problem]


def cases(size, seed, reference=None, hueeber_reference=None):
    """Every Case of a study size (FULL or SMOKE, possibly overridden); `reference(problem)`
    gives the punch's and cube's reference figures (BlockReference), `hueeber_reference()`
    those of Hueeber's blocks (HueeberReference)."""
    out = []
    for name, kwargs in contact_patch.random_variants(size["patch"], seed):
        out.append(Case("patch", name, patch.patch(**kwargs), "patch", patch_errors))
    for element in size["sphere_elements"]:
        for ratio in size["ratios" if element == "C3D8" else "quadratic_ratios"]:
            model = hertz_sphere.hertz_sphere(element, ratio=ratio)
            out.append(Case("hertz_sphere", f"{element} a/h {ratio:g}", model, "sphere",
                            lambda run, m=model: sphere_errors(m, run)))
    for r in size["penalties"]:
        model = dataclasses.replace(hertz_sphere.hertz_sphere(ratio=size["penalty_ratio"]),
                                    penalty=r * hertz_sphere.E_STAR / hertz_sphere.TARGET_RADIUS)
        out.append(Case("hertz_penalty", f"K a/E* {r:g}", model, "sphere",
                        lambda run, m=model: sphere_errors(m, run)))
    for n in size["increments"]:
        model = dataclasses.replace(
            hertz_sphere.hertz_sphere(ratio=size["increment_ratio"], increments=n),
            penalty=INCREMENT_STUDY_PENALTY * hertz_sphere.E_STAR / hertz_sphere.TARGET_RADIUS)
        measure = (lambda run, m=model: sphere_errors(m, run))
        out.append(Case("hertz_increments", f"{n} increments", model, "sphere", measure))
        out.append(Case("hertz_increments", f"{n} increments, drift check off", model, "sphere",
                        measure, kontakt_args=DRIFT_OFF, linear_variants_only=True))
    for n in size["slides"]:
        model = sliding_cylinder.sliding_cylinder(level=1, increments=n)
        measure = (lambda run, m=model: turned_error(m, run))
        out.append(Case("sliding_increments", f"{n} increments", model, "sliding", measure))
        out.append(Case("sliding_increments", f"{n} increments, drift check off", model,
                        "sliding", measure, kontakt_args=DRIFT_OFF, linear_variants_only=True))
    for problem in size["blocks"]:
        for n in size["block_levels"]:
            model = block_model(problem, n)
            out.append(Case(problem, f"C3D8 {n}^3", model, problem,
                            lambda run, p=problem, m=model: block_errors(p, m, run, reference)))
    for element in size["line_elements"]:
        for level in size["line_levels"]:
            model = hertz.hertz(element, level)
            out.append(Case("hertz_line", f"{element} level {level}", model, "hertz",
                            lambda run, m=model, k=level: line_errors(m, k, run)))
    for level in size["hueeber_levels"]:
        model = hueeber_blocks.hueeber(level)
        lower, upper = hueeber_blocks.elements_per_side(level)
        out.append(Case("hueeber", f"level {level} ({lower}/{upper})", model, "hueeber",
                        lambda run, m=model: hueeber_errors(m, run, hueeber_reference)))
    return out


def headline(problem, components):
    """The problem's headline error: the largest magnitude of its components (None when one is
    not finite, e.g. a run without nodal results)."""
    values = [abs(components[k]) for k in HEADLINE[problem]]
    return max(values) if all(math.isfinite(v) for v in values) else None


def row_of(case, solver, scheme, run):
    """The CSV row of one run: measured when it converged."""
    row = dict(problem=case.problem, solver=solver, scheme=scheme, setting=case.setting,
               status=run.status, wall_s=f"{run.wall:.3f}", iterations=run.iterations,
               increments=run.increments, peak_mb=f"{run.peak_mib:.1f}", message=run.message)
    if run.converged:
        try:
            components = case.measure(run)
        except (OSError, KeyError, ValueError, TypeError) as e:
            row.update(status="not measured", message=str(e))
            return row
        row.update({k: f"{v:.6g}" for k, v in components.items()})
        error = headline(case.problem, components)
        if error is None:
            row.update(status="not measured", message="an error component is not finite")
        else:
            row["error"] = f"{error:.6g}"
    return row


def least_wall_time(solve_once):
    """The Run of solve_once(); a converged run under SHORT_RUN_S is solved again up to REPEATS
    times in all and carries the least wall and CPU time of its solves."""
    run = solve_once()
    for _ in range(REPEATS - 1):
        if not run.converged or run.wall >= SHORT_RUN_S:
            break
        again = solve_once()
        run = dataclasses.replace(again, wall=min(run.wall, again.wall), cpu=min(run.cpu, again.cpu))
    return run


def run_all(all_cases, args, csv_path):
    """Solves every case with every column, writing each row as soon as it is measured."""
    ccx_types = () if args.no_ccx else solvers.CCX_TYPES
    with open(csv_path, "w", newline="") as f:
        writer = csv.DictWriter(f, COLUMNS)
        writer.writeheader()
        for case in all_cases:
            folder = os.path.join(args.out, "runs", case.problem, case.setting.replace(" ", "_")
                                  .replace("/", "").replace(",", ""))
            decks = {t: solvers.write_deck(case.model, folder, t, case.name)
                     for t in solvers.CCX_TYPES}
            for solver, scheme, column in case_columns(case, args.schemes, args.kontakt, ccx_types):
                run = least_wall_time(lambda: solvers.solve(
                    decks, folder, column, args.kontakt, args.timeout, case.kontakt_args))
                row = row_of(case, solver, scheme, run)
                writer.writerow(row)
                f.flush()
                print(f"{case.problem:13s} {case.setting:16s} {solver:8s} {scheme:19s} "
                      f"{row['status']:14s} {run.wall:8.2f} s {run.iterations:4d} it "
                      f"{run.peak_mib:7.1f} MiB  error {row.get('error', '-')}", flush=True)


def expected_keys(all_cases, schemes, kontakt, ccx):
    """The (problem, solver, scheme, setting) of every run the study makes."""
    ccx_types = solvers.CCX_TYPES if ccx else ()
    out = []
    return [(case.problem, solver, scheme, case.setting) for case in all_cases
            for solver, scheme, _ in case_columns(case, schemes, kontakt, ccx_types)]


def completeness(header, rows, expected):
    """Problems of a written CSV: missing columns, missing or repeated rows (a list of
    sentences, empty when complete)."""
    problems = [f"column {c} missing" for c in COLUMNS if c not in header]
    if problems:
        return problems
    found = [tuple(r[k] for k in KEY) for r in rows]
    problems += [f"no row for {k}" for k in expected if k not in found]
    problems += [f"{found.count(k)} rows for {k}" for k in set(found) if found.count(k) > 1]
    problems += [f"unexpected row {k}" for k in set(found) if k not in expected]
    return problems


def smoke_failures(rows):
    """Kontakt rows of a smoke run that did not converge with a measured error."""
    return [f"{r['problem']} {r['setting']} kontakt {r['scheme']}: {r['status']} "
            f"{r['message']}".strip()
            for r in rows if r["solver"] == "kontakt" and (r["status"] != "converged"
                                                         or not r["error"])]


def point(row):
    """(wall time, error raised to ERROR_FLOOR, or None without an error) of a CSV row."""
    return (float(row["wall_s"]), max(float(row["error"]), ERROR_FLOOR) if row["error"] else None)


def front_rows(rows):
    """{front name: its rows} of one problem (fronts without rows left out)."""
    ours = [r for r in rows if r["solver"] == "kontakt"]
    groups = {"kontakt (all schemes)": ours,
              "kontakt lgc7": [r for r in ours if r["scheme"] == "lgc7"]}
    groups.update({f"ccx {s}": [r for r in rows if r["solver"] == "ccx" and r["scheme"] == s]
                   for s in CCX_SCHEME.values()})
    return {name: group for name, group in groups.items() if group}


def front_groups(rows):
    """{front name: its rows' (time, error) points} of one problem."""
    return {name: [point(r) for r in group] for name, group in front_rows(rows).items()}


def verdict_lines(problem, rows):
    """The dominance verdict of one problem and the fronts behind it, as text lines."""
    fronts = {name: pareto.pareto_front(points) for name, points in front_groups(rows).items()}
    label = {point(r): f"{r['scheme']} {r['setting']}" for r in rows}
    lines = [f"{problem}:"]
    for name, front in fronts.items():
        failed = sum(1 for r in front_rows(rows)[name] if not r["error"])
        runs = "; ".join(f"{label[p]} {p[0]:.3g} s {p[1]:.3g}" for p in front) or "empty"
        lines.append(f"  front {name}: {runs}" + (f" ({failed} runs without an error)"
                                                  if failed else ""))
    for ours in ("kontakt (all schemes)", "kontakt lgc7"):
        for theirs in (f"ccx {s}" for s in CCX_SCHEME.values()):
            if ours in fronts and theirs in fronts:
                v = pareto.dominance(fronts[ours], fronts[theirs], ERROR_TOLERANCE)
                lines.append(f"  {ours} dominates {theirs}: {'yes' if v.dominates else 'NO'} "
                             f"({v.reason})")
    return lines


def plot(problem, rows, path):
    """Error (log) against wall time (log): a marker per solver and scheme, each front a step
    line. Returns the time axis' limits."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 6))
    series = sorted({(r["solver"], r["scheme"]) for r in rows}, key=lambda s: (s[0] == "ccx", s))
    markers = "os^vD<>pP*Xhd"
    colours = plt.cm.tab20(np.linspace(0, 1, max(len(series), 2)))
    for k, (solver, scheme) in enumerate(series):
        points = [point(r) for r in rows if (r["solver"], r["scheme"]) == (solver, scheme)]
        done = [(t, e) for t, e in points if e is not None]
        failed = len(points) - len(done)
        tag = f"{solver} {scheme}" + (f" ({failed} without error)" if failed else "")
        colour = "black" if solver == "ccx" else colours[k]
        if done:
            ax.scatter(*zip(*done), marker=markers[k % len(markers)], color=colour, label=tag,
                       zorder=3)
        else:
            ax.scatter([], [], marker=markers[k % len(markers)], color=colour, label=tag)
    styles = {"kontakt (all schemes)": ("tab:blue", "-", 3.0),
              "kontakt lgc7": ("tab:green", ":", 2.0),
              "ccx node-to-surface": ("tab:red", "--", 1.2),
              "ccx surface-to-surface": ("tab:red", "-", 1.2)}  # kontakt's wider: visible under
    right = 1.2 * max(float(r["wall_s"]) for r in rows)
    for name, points in front_groups(rows).items():
        front = pareto.pareto_front(points)
        if front:  # the last run's error holds to the right edge: a lone run is a line too
            colour, style, width = styles[name]
            ax.step(*zip(*front, (right, front[-1][1])), where="post", color=colour,
                    linestyle=style, linewidth=width, label=f"front: {name}")
    # Log scale first: a linear autoscale's left limit is negative for runs from 2 s to 1000 s.
    ax.set_xscale("log")
    ax.set_xlim(0.8 * min(float(r["wall_s"]) for r in rows), right)
    ax.set_yscale("log")
    ax.set_xlabel("wall time [s]")
    ax.set_ylabel(f"{problem} error ({' / '.join(HEADLINE[problem])}, largest magnitude)")
    ax.set_title(f"{problem}: error against wall time (errors below {ERROR_FLOOR:g} taken as it)",
                 fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="best")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return ax.get_xlim()


# problem: (x of a row's setting, x label, plot title, error label). The plots read the CSV
# (--replot re-plots a finished run), which holds the setting, so x comes from the setting.
HERTZ_ERROR = "error (p0, fitted p0, radius: largest magnitude)"
STUDIES = {
    "hertz_penalty": (lambda setting: float(setting.split()[-1]), "penalty K a / E*",
                      "Hertz sphere: the penalty study", HERTZ_ERROR),
    "hertz_increments": (lambda setting: float(setting.split()[0]), "equal increments per step",
                         "Hertz sphere: the increment study", HERTZ_ERROR),
    "sliding_increments": (lambda setting: float(setting.split()[0]), "increments of the slide",
                           "Sliding cylinder: the drift study",
                           "error: pressure after the slide against before it, turned"),
}


def study_series(row):
    """The line of a study plot a row belongs to."""
    off = ", drift check off" if "drift check off" in row["setting"] else ""
    return f"{row['solver']} {row['scheme']}{off}"


def plot_study(problem, rows, path):
    """Error and Newton iterations (all attempts) against the study's parameter, a line per
    solver and scheme (dashed: ccx; dotted: kontakt without the drift check)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    x_of, x_label, title, error_label = STUDIES[problem]
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 8), sharex=True)
    for series in sorted({study_series(r) for r in rows}, key=lambda s: (s.startswith("ccx"), s)):
        mine = sorted(((x_of(r["setting"]), r) for r in rows if study_series(r) == series),
                      key=lambda pair: pair[0])
        style = dict(marker="o", label=series,
                     linestyle="--" if series.startswith("ccx") else ":" if "off" in series
                     else "-")
        measured = [(x, max(float(r["error"]), ERROR_FLOOR)) for x, r in mine if r["error"]]
        if measured:
            top.plot(*zip(*measured), **style)
        converged = [(x, int(r["iterations"])) for x, r in mine if r["status"] == "converged"]
        if converged:
            bottom.plot(*zip(*converged), **style)
    top.set_xscale("log")
    top.set_yscale("log")
    top.set_ylabel(error_label)
    bottom.set_ylabel("Newton iterations (converged runs, all attempts)")
    bottom.set_xlabel(x_label)
    top.set_title(title, fontsize=9)
    for ax in (top, bottom):
        ax.grid(True, which="both", alpha=0.3)
    top.legend(fontsize=6, loc="best", ncol=2)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    solvers.add_solver_options(p, FULL["schemes"])
    p.add_argument("--out", required=True, help="folder of the CSV, PNGs, verdict and runs")
    p.add_argument("--smoke", action="store_true", help="CI size, checked (see above)")
    p.add_argument("--problems", nargs="+", choices=tuple(HEADLINE), default=list(HEADLINE))
    p.add_argument("--patch", type=int, help="patch: number of random variants (6)")
    p.add_argument("--seed", type=int, default=DEFAULT_SEED, help="of the patch variants")
    p.add_argument("--ratios", nargs="+", type=float, help="sphere: C3D8 a/h levels (4 6 8 12)")
    p.add_argument("--quadratic-ratios", nargs="+", type=float,
                   help="sphere: C3D20 a/h levels (2 3 4 6: the C3D8 levels' node spacing)")
    p.add_argument("--sphere-elements", nargs="+", choices=("C3D8", "C3D20"),
                   help="sphere: element types (C3D8 C3D20)")
    p.add_argument("--penalties", nargs="+", type=float,
                   help="penalty study: K a / E* values (1 10 100 1000 10000)")
    p.add_argument("--penalty-ratio", type=float, help="penalty study: the sphere's a/h (6)")
    p.add_argument("--increments", nargs="+", type=int,
                   help="increment study: numbers of equal increments (1 2 3 6 12)")
    p.add_argument("--increment-ratio", type=float, help="increment study: the sphere's a/h (6)")
    p.add_argument("--slides", nargs="+", type=int,
                   help="drift study: increments of the slide (1 2 4 8 16)")
    p.add_argument("--block-levels", nargs="+", type=int,
                   help="punch, cube: elements per edge of each body (4 8)")
    p.add_argument("--block-reference", type=int,
                   help="punch, cube: elements per edge of the reference run (16)")
    p.add_argument("--line-elements", nargs="+", choices=("C3D8", "C3D20"),
                   help="line Hertz: element types (C3D8 C3D20)")
    p.add_argument("--line-levels", nargs="+", type=int, choices=(1, 2, 3),
                   help="line Hertz: mesh levels (1 2 3)")
    p.add_argument("--hueeber-levels", nargs="+", type=int,
                   help="Hueeber's blocks: mesh levels (2 3 4 5)")
    p.add_argument("--hueeber-reference", type=int,
                   help="Hueeber's blocks: mesh level of the reference run (6)")
    p.add_argument("--no-ccx", action="store_true", help="kontakt's schemes only")
    p.add_argument("--timeout", type=int, default=solvers.DEFAULT_TIMEOUT, help="per run, s")
    p.add_argument("--replot", action="store_true",
                   help="solve nothing: checks, plots and verdict of OUT's CSV (same options)")
    args = p.parse_args()
    size = dict(SMOKE if args.smoke else FULL)
    for key in ("patch", "ratios", "quadratic_ratios", "sphere_elements", "line_elements", "line_levels", "penalties", "penalty_ratio",
                "increments", "increment_ratio", "slides", "block_levels", "block_reference",
                "hueeber_levels", "hueeber_reference"):
        if getattr(args, key) is not None:
            size[key] = getattr(args, key)
    if args.smoke and "--schemes" not in sys.argv:
        args.schemes = SMOKE["schemes"]
    args.out = os.path.abspath(args.out)
    os.makedirs(args.out, exist_ok=True)
    size["blocks"] = [b for b in size["blocks"] if b in args.problems]
    if "hueeber" not in args.problems:
        size["hueeber_levels"] = []
    all_cases = [c for c in cases(size, args.seed, BlockReference(args, size["block_reference"]),
                                  HueeberReference(args, size["hueeber_reference"]))
                 if c.problem in args.problems]
    csv_path = os.path.join(args.out, "time_vs_error.csv")
    print(f"one run at a time, 1 thread each, nice {solvers.NICENESS}; patch seed {args.seed}")
    for c in all_cases:
        if c.problem == "patch":
            print(f"  {c.setting}: {c.model.notes[0].split(': ', 1)[1]}")
    if not args.replot:
        run_all(all_cases, args, csv_path)

    with open(csv_path, newline="") as f:
        reader = csv.DictReader(f)
        rows = list(reader)
        header = reader.fieldnames or []
    failures = completeness(header, rows, expected_keys(all_cases, args.schemes, args.kontakt,
                                                        not args.no_ccx))
    if args.smoke and not failures:
        failures = smoke_failures(rows)
    lines = []
    for problem in args.problems if all(c in header for c in COLUMNS) else ():
        mine = [r for r in rows if r["problem"] == problem]
        if mine:
            lines += verdict_lines(problem, mine)
            plot(problem, mine, os.path.join(args.out, f"{problem}.png"))
            if problem in STUDIES:
                plot_study(problem, mine, os.path.join(args.out, f"{problem}_study.png"))
    with open(os.path.join(args.out, "verdict.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    for failure in failures:
        print(f"FAIL: {failure}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
