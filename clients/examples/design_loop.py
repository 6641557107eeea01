#!/usr/bin/python3
"""Design loop: a parameter sweep over a deck template, submitted to kontaktd concurrently,
summarised into a CSV (one row per variant: parameter, status, iterations, wall time,
max |U|, max von Mises, max contact pressure, total contact force).

    design_loop.py --server http://127.0.0.1:8080 --values=-100,-200,-400 --csv sweep.csv

The template's {{LOAD_PER_NODE}} is replaced by value/4 (the tip has four nodes); any other
template and placeholder work the same way (--template, --placeholder, --scale).
"""
import argparse
import concurrent.futures
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from kontakt_client import ApiError, Client  # noqa: E402

FIELDS = ["value", "job", "status", "reason", "iterations", "wall_time", "max_displacement",
          "max_mises", "max_contact_pressure", "total_contact_force"]


def run_variant(client, template, placeholder, scale, value, sweep, timeout):
    """Submits one variant, waits for it, returns its CSV row."""
    deck = template.replace(placeholder, repr(value * scale))
    try:
        job = client.submit(deck, name=f"{sweep} value={value}", labels={"sweep": sweep, "value": str(value)},
                            main="variant.inp")
    except ApiError as e:  # a bad variant is a result too
        return {"value": value, "status": "rejected", "reason": e.code}
    final = job.wait(timeout=timeout)
    s = job.summary()
    row = {"value": value, "job": job.id, "status": final["status"],
           "reason": (final["reason"] or {}).get("code", "")}
    row.update({k: s[k] for k in FIELDS[4:]})
    return row


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--server", default=os.environ.get("KONTAKT_SERVER", "http://127.0.0.1:8080"))
    p.add_argument("--token", default=os.environ.get("KONTAKT_TOKEN"))
    p.add_argument("--template", default=os.path.join(here, "beam_template.inp"))
    p.add_argument("--placeholder", default="{{LOAD_PER_NODE}}")
    p.add_argument("--scale", type=float, default=0.25, help="placeholder = value * scale")
    p.add_argument("--values", default="-100,-200,-400,-800", help="comma-separated parameter values")
    p.add_argument("--parallel", type=int, default=8, help="submissions in flight at once")
    p.add_argument("--sweep", default="load-sweep", help="label of the jobs")
    p.add_argument("--timeout", type=float, default=600)
    p.add_argument("--csv", default="sweep.csv")
    args = p.parse_args()
    with open(args.template, encoding="utf-8") as f:
        template = f.read()
    if args.placeholder not in template:
        p.error(f"the template has no {args.placeholder}")
    values = [float(v) for v in args.values.split(",") if v.strip()]
    client = Client(args.server, token=args.token)
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.parallel) as pool:
        rows = list(pool.map(lambda v: run_variant(client, template, args.placeholder, args.scale, v,
                                                   args.sweep, args.timeout), values))
    with open(args.csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS)
        writer.writeheader()
        writer.writerows(rows)
    for row in rows:
        print(f"{row['value']:>10g}  {row['status']:<10} max|U| = {row.get('max_displacement')}")
    print(f"wrote {args.csv}")
    return 0 if all(r["status"] == "succeeded" for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
