"""datfile -- parse a CalculiX-layout .dat file (as written by ccx and by
`kontakt solve`) into blocks.

Layout (one block):
    <blank>
     displacements (vx,vy,vz) for set NAME and time  0.1000000E+01
    <blank>
             5  3.584580E-05  8.489796E-06  8.536961E-05      (I10, 1X,E13.6 ...)
stresses rows carry element (I10) and integration point (I4) first;
"total force" rows carry only values.
*CONTACT PRINT blocks (`contact stress (slave element+face,press,tang1,tang2) for all contact
elements and time ...`) have set "contact elements"; their rows carry the slave node, or
(surface to surface) the slave element and face, first.

parse(path) -> list of Block(kind, header, set, time, rows)
  kind : first word(s) of the header before '(' e.g. 'displacements',
         'stresses', 'forces', 'total force'
  rows : list of tuples; integer ids first (node | elem, ip), then floats
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

_HDR = re.compile(r"^\s*(?P<kind>[^()]*?)\s*\((?P<cols>[^)]*)\)\s*"
                  r"for (?:set\s+(?P<set>\S+)|all (?P<contact>contact elements))"
                  r"\s+and time\s+(?P<time>\S+)")

# number of leading integer columns per block kind
_NINT = {"stresses": 2, "strains": 2, "mechanical strains": 2,
         "equivalent plastic strain": 2, "internal energy density": 2}


@dataclass
class Block:
    kind: str
    columns: str
    set: str
    time: float
    header: str
    rows: list = field(default_factory=list)

    def by_id(self):
        """node-keyed blocks: {node: values tuple}"""
        return {r[0]: r[1:] for r in self.rows}

    def by_elem_ip(self):
        """integration-point blocks: {(elem, ip): values tuple}"""
        return {(r[0], r[1]): r[2:] for r in self.rows}


def _float(tok: str) -> float:
    # Fortran may drop the 'E' for 3-digit exponents (1.0-100)
    try:
        return float(tok)
    except ValueError:
        m = re.match(r"^([-+]?\d*\.\d*)([-+]\d+)$", tok)
        if m:
            return float(m.group(1) + "E" + m.group(2))
        raise


def parse(path) -> list[Block]:
    blocks: list[Block] = []
    cur: Block | None = None
    with open(path) as f:
        for line in f:
            s = line.strip()
            if not s:
                continue
            m = _HDR.match(line)
            if m:
                kind = m.group("kind").strip()
                cur = Block(kind=kind, columns=m.group("cols"),
                            set=m.group("set") or m.group("contact"),
                            time=_float(m.group("time")), header=line.rstrip("\n"))
                blocks.append(cur)
                continue
            if cur is None:
                continue  # preamble (e.g. ccx 'STEP 1' lines) is ignored
            toks = s.split()
            try:
                nint = 0 if cur.kind.startswith("total") else _NINT.get(cur.kind, 1)
                if cur.columns.startswith("slave element+face"):
                    nint = 2
                ints = tuple(int(t) for t in toks[:nint])
                vals = tuple(_float(t) for t in toks[nint:])
            except ValueError:
                # unknown text line: ends the current block
                cur = None
                continue
            cur.rows.append(ints + vals)
    return blocks


def find(blocks, kind: str, set_name: str | None = None, last=True):
    """Block of a kind (prefix match, case-insensitive) and set; by default the
    last one (final time)."""
    hits = [b for b in blocks if b.kind.lower().startswith(kind.lower())
            and (set_name is None or b.set.upper() == set_name.upper())]
    if not hits:
        raise KeyError(f"no '{kind}' block for set {set_name}")
    return hits[-1] if last else hits


if __name__ == "__main__":  # quick inspection: python3 datfile.py FILE.dat
    import sys
    for b in parse(sys.argv[1]):
        print(f"{b.kind!r:30} set={b.set:12} time={b.time:g} rows={len(b.rows)}")
