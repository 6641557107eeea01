#!/usr/bin/python3
"""Contact patch test (thesis §5.4, table 7): every contact scheme of kontakt and ccx's two
pair types on the same decks, with the thesis' requirement.

Model (tests/contact_models/patch.py): two unit cubes, upper coarse C3D10, lower fine C3D20,
nu = 0, unit pressure on top, K = 1e7; exact state sigma_zz = -1 at every integration point,
contact pressure 1. The variants change element types, mesh ratios, the slave side and the
interface regularity (VARIANTS below); --deck adds any deck with the same loading and
output requests (*EL PRINT S of every body, *CONTACT PRINT CSTR).

Measured per run: from the .dat, sigma_zz min / max over every printed integration point of
both bodies and the contact pressure (CSTR press) min / max over every printed contact point
(surface to surface: integration points; node to surface: slave nodes); from the nodal
results (kontakt: HDF5 CPRESS; ccx: .frd CONTACT block) CPRESS min / max over the nodes in
contact -- the thesis' "CPress (max)" is this nodal value.

Requirement (issue 4): lgc3, lgc7 and lgc12 converge with max |sigma_zz + 1| <= 1e-3 and
max |nodal CPRESS - 1| <= 1e-3 on every variant -- or, where ccx's surface to surface on the
same deck is less accurate than that (distorted quadratic faces: 4.2e-4 / 1.03e-3 measured),
no worse than ccx. Every other scheme must converge and is reported: nts and gauss are
expected to fail the test (thesis table 7: sigma_zz from -3.99 to 0.356 and from -2.52 to
1.21), and the table shows by how much. ccx's columns are the reference: its surface to
surface must pass at 1e-3 on the affine (undistorted) variants -- a check that the deck's
exact state is right -- and its node to surface is reported. On faces that have grown before
the last increment (the Poisson variant) ccx's contact pressure is force per area at the start
of that increment (0.997 measured): there its stresses are the deck check and kontakt's
CPRESS is held to 1e-3 regardless.

Without --kontakt only the ccx columns run (what CI can run before contact lands).

--gap G starts every variant's upper body G above the lower one (issue 9: held only by
contact, the load closes the gap first; the exact state is the same). --random N adds N
seeded random variants (element types of both bodies, meshes, distortion, slave side, Young's
moduli up to a factor 10 apart; --seed).

  contact_patch.py [--kontakt EXE] [--schemes lgc7 nts ...] [--variants thesis swapped ...]
                   [--spec upper=C3D4,lower=C3D8,n_upper=3,slave=lower ...]
                   [--deck DECK.inp ...] [--work DIR] [--no-ccx]
                   [--gap 1e-3] [--random 60 --seed 9]
"""
import argparse
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the source tree clean

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "contact_models"))
import contact_fields  # noqa: E402
import datfile  # noqa: E402
import patch  # noqa: E402
import solvers  # noqa: E402
import vutil  # noqa: E402

TOLERANCE = 1e-3
REQUIRED = ("lgc3", "lgc7", "lgc12")
EXPECTED_TO_FAIL = ("nts", "gauss")

# name -> keyword arguments of patch.patch()
VARIANTS = {
    "thesis": {},
    "swapped": dict(slave="lower"),
    "distorted": dict(distortion=0.3),
    "hex8": dict(upper="C3D8", lower="C3D8", n_upper=3, n_lower=4),
    "hex8_fine_slave": dict(upper="C3D8", lower="C3D8", n_upper=7, n_lower=4),
    "tet4_hex20": dict(upper="C3D4", lower="C3D20", n_upper=2, n_lower=3, distortion=0.2),
    "wedge15_wedge6": dict(upper="C3D15", lower="C3D6", n_upper=3, n_lower=4, distortion=0.25),
    "hex20_tet10": dict(upper="C3D20", lower="C3D10", n_upper=3, n_lower=2),
    "hex20r_swapped": dict(upper="C3D10", lower="C3D20R", n_upper=2, n_lower=4, slave="lower"),
    # The faces grow sideways by nu / E = 3e-3 and the second increment starts on faces grown
    # by half of that: a pressure per deformed area would be 0.3 to 0.6 % low.
    "poisson": dict(upper="C3D8", lower="C3D20", n_upper=3, n_lower=4, poisson=0.3,
                    young_upper=100.0, young_lower=100.0, increments=2),
}


def measure(result_dir, name):
    """{szz min, szz max, point CPRESS min, max, nodal CPRESS min, max} of a run; nodal values
    over the nodes in contact (CPRESS != 0), None when the run wrote no nodal results. All of
    the last increment's output (the exact state is the full load's)."""
    blocks = datfile.parse(os.path.join(result_dir, name + ".dat"))
    blocks = [b for b in blocks if b.time == max(b.time for b in blocks)]
    szz = [row[4] for b in blocks if b.kind == "stresses" for row in b.rows]
    contact = datfile.find(blocks, "contact stress")
    first_value = 2 if contact.columns.startswith("slave element+face") else 1
    press = [row[first_value] for row in contact.rows]
    if not szz or not press:
        raise ValueError(f"{name}.dat: no stresses or no contact stress rows")
    nodal_path = contact_fields.result_file(result_dir, name)
    nodal = ([p for _, p in contact_fields.nodal_contact(nodal_path).values() if p != 0]
             if nodal_path else [])
    return {"szz": (min(szz), max(szz)), "points": (min(press), max(press)),
            "nodes": (min(nodal), max(nodal)) if nodal else None}


def errors(figures):
    """(max |szz + 1|, max |nodal CPRESS - 1| or inf without nodal results)."""
    szz = max(abs(v + 1) for v in figures["szz"])
    nodes = max(abs(v - 1) for v in figures["nodes"]) if figures["nodes"] else float("inf")
    return szz, nodes


def runs_of_variant(args, name, model):
    """[(label, scheme or ccx type, Run, deck name)]: kontakt schemes, then ccx."""
    folder = os.path.join(args.work, name)
    decks = {t: solvers.write_deck(model, folder, t, "patch") for t in solvers.CCX_TYPES}
    return [(label, column, solvers.solve(decks, folder, column, args.kontakt), "patch")
            for label, column in solvers.columns(args.schemes, args.kontakt,
                                                 () if args.no_ccx else solvers.CCX_TYPES)]


def evaluate(rep, variant, affine, runs, gap=0.0, grown=False):
    """Checks and prints one variant. With a gap, ccx's columns are reported only (ccx often
    fails to close it); kontakt's must converge. `grown`: the faces grow before the last
    increment, where ccx's pressure per area at its start is not a reference."""
    figures = {}
    for label, what, run, name in runs:
        if gap == 0 or what not in solvers.CCX_TYPES:
            rep.check(f"{variant} {label}: converged", run.converged,
                      f"{run.status} {run.message}".strip())
        if run.converged:
            figures[label] = vutil.guarded(rep, f"{variant} {label}: output", measure,
                                           run.result_dir, name)
    reference = figures.get("ccx surface to surface")
    floor = errors(reference) if reference else (0.0, 0.0)
    if grown:
        floor = (floor[0], 0.0)
    tolerance = tuple(max(TOLERANCE, e) if math.isfinite(e) else TOLERANCE for e in floor)
    rows = []
    for label, what, run, _ in runs:
        limit = None  # (szz, nodal CPRESS) tolerance of a gated row
        if what in REQUIRED:
            limit = tolerance
            requirement = f"<= {limit[0]:.3g} / {limit[1]:.3g}"
        elif what in EXPECTED_TO_FAIL:
            requirement = "expected to fail"
        elif what == "SURFACE TO SURFACE" and affine and gap == 0:
            limit = (TOLERANCE, math.inf if grown else TOLERANCE)
            requirement = f"<= {TOLERANCE:g}{' szz' if grown else ''} (deck check)"
        else:
            requirement = "reported"
        found = figures.get(label)
        if not found:
            rows.append([label, run.status, run.iterations] + ["-"] * 7 + [requirement])
            continue
        stress_error, pressure_error = errors(found)
        if limit:
            rep.check(f"{variant} {label}: max |szz + 1| <= {limit[0]:.3g}",
                      stress_error <= limit[0], f"{stress_error:.3e}")
            if math.isfinite(limit[1]):
                rep.check(f"{variant} {label}: max |nodal CPRESS - 1| <= {limit[1]:.3g}",
                          pressure_error <= limit[1], f"{pressure_error:.3e}")
        nodes = found["nodes"] or ("-", "-")
        rows.append([label, run.status, run.iterations]
                    + [f"{v:.4f}" for v in found["szz"]] + [f"{stress_error:.2e}"]
                    + [f"{v:.4f}" for v in found["points"]]
                    + [v if v == "-" else f"{v:.4f}" for v in nodes] + [requirement])
    rep.table(["formulation", "status", "iter", "szz min", "szz max", "max|szz+1|",
               "CPRESS min", "CPRESS max", "nodal min", "nodal max", "requirement"], rows)


RANDOM_TYPES = ("C3D4", "C3D6", "C3D8", "C3D10", "C3D15", "C3D20", "C3D20R")


def random_variants(count, seed):
    """[(name, patch.patch() arguments)] of `count` seeded random variants."""
    import random
    rng = random.Random(seed)
    out = []
    for k in range(count):
        kwargs = dict(upper=rng.choice(RANDOM_TYPES), lower=rng.choice(RANDOM_TYPES),
                      n_upper=rng.randint(1, 4), n_lower=rng.randint(1, 5),
                      slave=rng.choice(("upper", "lower")),
                      distortion=rng.choice((0.0, 0.0, rng.uniform(0.05, 0.3))),
                      seed=rng.randint(1, 10 ** 6),
                      young_upper=patch.YOUNG * 10 ** rng.uniform(-1, 1),
                      young_lower=patch.YOUNG * 10 ** rng.uniform(-1, 1))
        out.append((f"random{k:03d}", kwargs))
    return out


def parse_spec(spec):
    """patch.patch() keyword arguments of a --spec text (numbers converted)."""
    kwargs = {}
    for item in spec.split(","):
        key, _, value = item.partition("=")
        kwargs[key.strip()] = (float(value) if key.strip() == "distortion"
                               else int(value) if key.strip() in ("n_upper", "n_lower", "seed")
                               else value.strip())
    return kwargs


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    solvers.add_solver_options(p, solvers.SCHEMES)
    p.add_argument("--variants", nargs="+", default=list(VARIANTS), choices=sorted(VARIANTS))
    p.add_argument("--spec", action="append", default=[], metavar="K=V,...",
                   help="a further variant: patch.patch() arguments, e.g. "
                        "upper=C3D4,lower=C3D8,n_upper=3,n_lower=5,slave=lower,distortion=0.1")
    p.add_argument("--deck", action="append", default=[],
                   help="a further patch-test deck, solved as given (its own pair type)")
    p.add_argument("--no-ccx", action="store_true", help="kontakt columns only")
    p.add_argument("--gap", type=float, default=0.0, help="initial gap of every variant")
    p.add_argument("--random", type=int, default=0, metavar="N", help="N random variants")
    p.add_argument("--seed", type=int, default=9, help="of the random variants")
    p.add_argument("--work", default="contact_patch_work")
    args = p.parse_args()
    args.work = os.path.abspath(args.work)
    rep = vutil.Report("contact patch test (thesis 5.4, table 7): exact szz = -1, CPRESS = 1")
    variants = [(name, VARIANTS[name]) for name in args.variants]
    variants += [(spec, parse_spec(spec)) for spec in args.spec]
    variants += random_variants(args.random, args.seed)
    for name, kwargs in variants:
        model = patch.patch(**kwargs, gap=args.gap)
        print(f"-- {name}: {model.notes[0].split(': ', 1)[1]}")
        grown = kwargs.get("poisson", 0) > 0 and kwargs.get("increments", 1) > 1
        evaluate(rep, name, not kwargs.get("distortion"), runs_of_variant(args, name, model),
                 args.gap, grown)
    for deck in args.deck:
        name = os.path.basename(deck)[:-4]
        print(f"-- deck {deck}")
        evaluate(rep, name, False, runs_of_deck(args, name, deck))
    rep.finish()


def runs_of_deck(args, name, deck):
    """As runs_of_variant for a given deck, solved as it is: its own pair type for ccx and
    for every kontakt scheme."""
    folder = os.path.join(args.work, "deck_" + name)
    with open(deck) as f:
        text = f.read()
    contact_type = next((t for t in solvers.CCX_TYPES if t in text.upper()), None)
    staged = os.path.join(folder, "deck", name + ".inp")
    os.makedirs(os.path.dirname(staged), exist_ok=True)
    with open(staged, "w") as f:
        f.write(text)
    decks = {t: staged for t in solvers.CCX_TYPES}
    return [(label, column, solvers.solve(decks, folder, column, args.kontakt), name)
            for label, column in solvers.columns(args.schemes, args.kontakt,
                                                 () if args.no_ccx or not contact_type
                                                 else (contact_type,))]


if __name__ == "__main__":
    main()
