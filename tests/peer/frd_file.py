#!/usr/bin/python3
"""Reader of ASCII .frd result files (ccx 2.20's layout, and Kontakt's): nodes, elements and
result blocks, read by their fixed columns (ccx-behaviour.md §4.3). Pure: no numpy needed.

    frd = frd_file.read("job.frd")
    frd.nodes[label] -> (x, y, z); frd.elements[label] -> Element(type, material, nodes)
    frd.blocks -> [Block(step, increment, time, name, components, values{node: [v, ...]})]

A line that breaks the layout raises FrdError naming the file and line number.
"""
import dataclasses
import sys

# Nodes per frd element type (1 he8, 2 pe6, 3 te4, 4 he20, 5 pe15, 6 te10).
NODES_PER_TYPE = {1: 8, 2: 6, 3: 4, 4: 20, 5: 15, 6: 10}


class FrdError(ValueError):
    pass


@dataclasses.dataclass
class Element:
    type: int
    material: int
    nodes: list


@dataclasses.dataclass
class Block:
    block_number: int
    increment: int
    step: int
    set_number: int
    time: float
    time_field: str        # the 12 columns as written
    name: str
    components: list       # declared names, ALL included
    values: dict           # node -> list of the stored values (ALL is not stored)

    @property
    def stored_components(self):
        return [c for c in self.components if c != "ALL"]


@dataclasses.dataclass
class Frd:
    header: list = dataclasses.field(default_factory=list)   # the 1U lines' text after "1U"
    nodes: dict = dataclasses.field(default_factory=dict)
    elements: dict = dataclasses.field(default_factory=dict)
    blocks: list = dataclasses.field(default_factory=list)
    complete: bool = False                                   # ends with 9999


def _int(text, where, what):
    try:
        return int(text)
    except ValueError:
        raise FrdError(f"{where}: {what} {text!r} is not an integer") from None


def _float(text, where):
    try:
        return float(text)
    except ValueError:
        raise FrdError(f"{where}: value {text!r} is not a number") from None


def _values(line, where):
    """The 12-column values from column 13 on."""
    rest = line[13:].rstrip("\n")
    if len(rest) % 12:
        raise FrdError(f"{where}: values do not fill 12-column fields")
    return [_float(rest[k:k + 12], where) for k in range(0, len(rest), 12)]


def parse(text, name="<frd>"):
    frd = Frd()
    lines = text.splitlines()
    i = 0

    def where(k):
        return f"{name}:{k + 1}"

    pending = None  # (block_number, increment, step) from the last 1PSTEP
    while i < len(lines):
        line = lines[i]
        key = line[:6]
        if line.strip() == "":
            i += 1
        elif key == "    1C":
            i += 1
        elif key == "    1U":
            frd.header.append(line[6:].rstrip())
            i += 1
        elif key in ("    2C", "    3C"):
            count = _int(line[24:36], where(i), "count")
            if line[73:74] != "1":
                raise FrdError(f"{where(i)}: not an ASCII block (column 73 is {line[73:74]!r})")
            i += 1
            if key == "    2C":
                while lines[i].startswith(" -1"):
                    v = _values(lines[i], where(i))
                    if len(v) != 3:
                        raise FrdError(f"{where(i)}: a node line has {len(v)} coordinates")
                    frd.nodes[_int(lines[i][3:13], where(i), "node")] = tuple(v)
                    i += 1
                if len(frd.nodes) != count:
                    raise FrdError(f"{where(i)}: {len(frd.nodes)} nodes, header says {count}")
            else:
                while lines[i].startswith(" -1"):
                    head = lines[i]
                    label = _int(head[3:13], where(i), "element")
                    etype = _int(head[13:18], where(i), "element type")
                    material = _int(head[23:28], where(i), "material")
                    if etype not in NODES_PER_TYPE:
                        raise FrdError(f"{where(i)}: unknown element type {etype}")
                    i += 1
                    nodes = []
                    while len(nodes) < NODES_PER_TYPE[etype]:
                        if not lines[i].startswith(" -2"):
                            raise FrdError(f"{where(i)}: element {label} needs "
                                           f"{NODES_PER_TYPE[etype]} nodes, has {len(nodes)}")
                        row = lines[i][3:].rstrip()
                        if len(row) % 10:
                            raise FrdError(f"{where(i)}: node numbers do not fill 10 columns")
                        nodes += [_int(row[k:k + 10], where(i), "node")
                                  for k in range(0, len(row), 10)]
                        i += 1
                    frd.elements[label] = Element(etype, material, nodes)
                if len(frd.elements) != count:
                    raise FrdError(f"{where(i)}: {len(frd.elements)} elements, header says "
                                   f"{count}")
            if lines[i].rstrip() != " -3":
                raise FrdError(f"{where(i)}: expected ' -3', got {lines[i]!r}")
            i += 1
        elif line.startswith("    1PSTEP"):
            pending = (_int(line[24:36], where(i), "block number"),
                       _int(line[36:48], where(i), "increment"),
                       _int(line[48:60], where(i), "step"))
            i += 1
        elif line.startswith("  100CL"):
            i = _block(frd, lines, i, pending, where)
            pending = None
        elif line.rstrip() == " 9999":
            frd.complete = True
            i += 1
        else:
            raise FrdError(f"{where(i)}: unexpected line {line!r}")
    return frd


def _block(frd, lines, i, pending, where):
    """Reads the block whose 100CL line is lines[i]; returns the index after its -3."""
    cl = lines[i]
    if pending is None:
        raise FrdError(f"{where(i)}: 100CL without a 1PSTEP line before it")
    set_number = _int(cl[7:12], where(i), "result set") - 100
    time_field = cl[12:24]
    time = _float(time_field, where(i))
    count = _int(cl[24:36], where(i), "value count")
    if _int(cl[58:63], where(i), "result set") != set_number or cl[74:75] != "1":
        raise FrdError(f"{where(i)}: 100CL columns 58-62 / 74 do not match the layout")
    i += 1
    head = lines[i]
    if not head.startswith(" -4  "):
        raise FrdError(f"{where(i)}: expected the ' -4' line")
    name = head[5:13].rstrip()
    if not name or name[0] == " ":
        raise FrdError(f"{where(i)}: the block name is not left-justified in columns 5-12")
    ncomp = _int(head[13:18], where(i), "component count")
    i += 1
    components = []
    for _ in range(ncomp):
        if not lines[i].startswith(" -5  "):
            raise FrdError(f"{where(i)}: expected {ncomp} ' -5' lines")
        component = lines[i][5:13].rstrip()
        if not component or component[0] == " ":
            raise FrdError(f"{where(i)}: the component name is not left-justified in columns "
                           "5-12")
        components.append(component)
        i += 1
    stored = len([c for c in components if c != "ALL"])
    values = {}
    while lines[i].startswith(" -1"):
        node = _int(lines[i][3:13], where(i), "node")
        row = _values(lines[i], where(i))
        i += 1
        while lines[i].startswith(" -2"):
            row += _values(lines[i], where(i))
            i += 1
        if len(row) != stored:
            raise FrdError(f"{where(i - 1)}: node {node} has {len(row)} values, the block "
                           f"declares {stored}")
        values[node] = row
    if lines[i].rstrip() != " -3":
        raise FrdError(f"{where(i)}: expected ' -3', got {lines[i]!r}")
    if len(values) != count:
        raise FrdError(f"{where(i)}: block {name} has {len(values)} nodes, 100CL says {count}")
    frd.blocks.append(Block(pending[0], pending[1], pending[2], set_number, time, time_field,
                            name, components, values))
    return i + 1


def read(path):
    with open(path, errors="replace") as f:
        return parse(f.read(), path)


def main(argv):
    """frd_file.py FILE: a summary (nodes, elements, blocks per name, frames)."""
    if len(argv) != 2:
        print("usage: frd_file.py FILE.frd", file=sys.stderr)
        return 2
    frd = read(argv[1])
    names = {}
    for b in frd.blocks:
        names[b.name] = names.get(b.name, 0) + 1
    print(f"{len(frd.nodes)} nodes, {len(frd.elements)} elements, "
          f"{len({b.set_number for b in frd.blocks})} result sets, complete={frd.complete}")
    for n, c in names.items():
        print(f"  {n:8s} {c} blocks")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
