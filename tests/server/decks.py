"""Small decks the daemon tests submit (our own, generated here)."""


def beam(nx: int = 1, nlgeom: bool = False, increments: int = 1, load: float = -10.0,
         extra_step_lines: str = "") -> str:
    """A C3D8 beam nx x 1 x 1, clamped at x = 0, tip load `load` in z at x = nx.

    With nlgeom, *STATIC DIRECT with `increments` fixed increments (so a run takes a
    predictable number of Newton iterations)."""
    nodes, elements = [], []
    def nid(i, j, k):
        return 1 + i + (nx + 1) * (j + 2 * k)
    for k in range(2):
        for j in range(2):
            for i in range(nx + 1):
                nodes.append(f"{nid(i, j, k)}, {float(i)}, {float(j)}, {float(k)}")
    for i in range(nx):
        c = [nid(i, 0, 0), nid(i + 1, 0, 0), nid(i + 1, 1, 0), nid(i, 1, 0),
             nid(i, 0, 1), nid(i + 1, 0, 1), nid(i + 1, 1, 1), nid(i, 1, 1)]
        elements.append(f"{i + 1}, " + ", ".join(map(str, c)))
    fixed = [nid(0, j, k) for j in range(2) for k in range(2)]
    tip = [nid(nx, j, k) for j in range(2) for k in range(2)]
    dt = 1.0 / increments
    static = (f"*STATIC, DIRECT\n{dt}, 1.0\n" if nlgeom else "*STATIC\n")
    step = f"*STEP, NLGEOM, INC={increments + 10}\n" if nlgeom else "*STEP\n"
    return ("*HEADING\nkontaktd test beam\n*NODE, NSET=NALL\n" + "\n".join(nodes) +
            "\n*ELEMENT, TYPE=C3D8, ELSET=EALL\n" + "\n".join(elements) +
            "\n*NSET, NSET=FIX\n" + ", ".join(map(str, fixed)) +
            "\n*NSET, NSET=TIP\n" + ", ".join(map(str, tip)) +
            "\n*MATERIAL, NAME=STEEL\n*ELASTIC\n210000, 0.3\n"
            "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n*BOUNDARY\nFIX, 1, 3\n" + step + static +
            f"*CLOAD\nTIP, 3, {load / 4}\n" + extra_step_lines +
            "*NODE PRINT, NSET=TIP\nU\n*NODE FILE\nU\n*EL FILE\nS\n*END STEP\n")


def tiny() -> str:
    """One linear C3D8: solves in milliseconds."""
    return beam(1)


def long_running(increments: int = 400, nx: int = 20) -> str:
    """An NLGEOM beam with many fixed increments: runs for seconds, one iteration at a time."""
    return beam(nx, nlgeom=True, increments=increments, load=-2000.0)


def load_template(deck: str, load: float) -> str:
    """`deck` (a beam above) with its tip load per node (load / 4) as the sweep placeholder
    <load>."""
    text = f"TIP, 3, {load / 4}\n"
    assert deck.count(text) == 1
    return deck.replace(text, "TIP, 3, <load>\n")
