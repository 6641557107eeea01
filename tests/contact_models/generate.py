#!/usr/bin/python3
"""Writes one generated contact deck (cube, punch, patch, hertz or sphere; see README.md) and checks
its meshes (mesh_checks.check_model) before writing; exit code 1 when a check fails.

  generate.py cube  OUT.inp [--element C3D8] [--n 16] [--x X --y Y --z Z --rotation DEG]
  generate.py punch OUT.inp [same options; z defaults to -0.0002]
  generate.py patch OUT.inp [--upper C3D10 --lower C3D20 --n-upper 2 --n-lower 5
                             --slave upper|lower --distortion D --seed S]
  generate.py hertz OUT.inp [--element C3D8 --level 1|2|3]
  generate.py sphere OUT.inp [--element C3D8 --ratio 20 --increments 6]
common: --type sts|nts (*CONTACT PAIR TYPE=SURFACE TO SURFACE | NODE TO SURFACE, default sts)
"""
import argparse
import sys

sys.dont_write_bytecode = True  # keep the source tree clean

import hertz  # noqa: E402
import hertz_sphere  # noqa: E402
import mesh_checks  # noqa: E402
import patch  # noqa: E402
import thesis_blocks  # noqa: E402

CONTACT_TYPE = {"sts": "SURFACE TO SURFACE", "nts": "NODE TO SURFACE"}


def build(args):
    """The TwoBodyModel the parsed command line describes."""
    contact_type = CONTACT_TYPE[args.type]
    if args.model in ("cube", "punch"):
        placement = dict(x=args.x, y=args.y, rotation=args.rotation)
        if args.z is not None:
            placement["z"] = args.z
        make = thesis_blocks.cube if args.model == "cube" else thesis_blocks.punch
        return make(args.element, n=args.n, n_upper=args.n_upper, contact_type=contact_type,
                    nlgeom=args.nlgeom, **placement)
    if args.model == "patch":
        return patch.patch(args.upper, args.lower, args.n_upper, args.n_lower, args.slave,
                           args.distortion, args.seed, contact_type)
    if args.model == "sphere":
        return hertz_sphere.hertz_sphere(args.element, args.ratio, args.increments, contact_type)
    return hertz.hertz(args.element, args.level, contact_type)


def parser():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    sub = p.add_subparsers(dest="model", required=True)
    for name in ("cube", "punch"):
        s = sub.add_parser(name)
        s.add_argument("--element", default="C3D8")
        s.add_argument("--n", type=int, default=16, help="elements per direction, lower body")
        s.add_argument("--n-upper", type=int, help="upper body (default: --n)")
        s.add_argument("--x", type=float, default=0.0)
        s.add_argument("--y", type=float, default=0.0)
        s.add_argument("--z", type=float, help="cube 0; punch: the thesis' -0.0002")
        s.add_argument("--rotation", type=float, default=0.0, help="degrees about z")
        s.add_argument("--nlgeom", action="store_true")
    s = sub.add_parser("patch")
    s.add_argument("--upper", default="C3D10")
    s.add_argument("--lower", default="C3D20")
    s.add_argument("--n-upper", type=int, default=2)
    s.add_argument("--n-lower", type=int, default=5)
    s.add_argument("--slave", choices=("upper", "lower"), default="upper")
    s.add_argument("--distortion", type=float, default=0.0)
    s.add_argument("--seed", type=int, default=1)
    s = sub.add_parser("hertz")
    s.add_argument("--element", default="C3D8")
    s.add_argument("--level", type=int, choices=(1, 2, 3), default=1)
    s = sub.add_parser("sphere")
    s.add_argument("--element", default="C3D8")
    s.add_argument("--ratio", type=float, default=20, help="a / h at the contact")
    s.add_argument("--increments", type=int, default=6)
    for s in sub.choices.values():
        s.add_argument("out", help="deck to write (NAME.inp)")
        s.add_argument("--type", choices=sorted(CONTACT_TYPE), default="sts")
    return p


def main():
    args = parser().parse_args()
    model = build(args)
    problems = mesh_checks.check_model(model)
    for problem in problems:
        print(f"mesh check: {problem}")
    if problems:
        return 1
    model.write(args.out)
    print(f"{args.out}: {len(model.lower.mesh.elements)} + {len(model.upper.mesh.elements)} "
          f"elements, {len(model.lower.mesh.nodes) + len(model.upper.mesh.nodes)} nodes")
    return 0


if __name__ == "__main__":
    sys.exit(main())
