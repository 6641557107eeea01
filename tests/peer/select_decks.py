#!/usr/bin/python3
"""The written, mechanical rule that decides which ccx test decks the peer test runs.

The whole rule is `exclusion_reason()`: a deck qualifies when it returns None. The deck is
read with every *INCLUDE expanded (relative to the including file, gzipped files read
transparently); comment lines (`**`) are ignored; keywords and parameter names are compared
upper-case with runs of blanks collapsed. The checks run record by record in deck order, and
the FIRST check a deck breaks is its exclusion reason:

  (a) every *ELEMENT has TYPE= one of ELEMENT_TYPES
      (C3D4 C3D6 C3D8 C3D8R C3D8I C3D10 C3D15 C3D20 C3D20R, the plane stress, plane strain
      and axisymmetric CPS/CPE/CAX 3, 4, 4R, 6, 8, 8R, the SPRINGA and GAPUNI connectors, the
      T3D2 truss and the DCOUP3D reference element);
  (b) every keyword is in SUPPORTED_KEYWORDS, within these limits:
      - no parameter in FORBIDDEN_PARAMETERS (USER) on any keyword;
      - *ELASTIC: TYPE= absent, ISO, ORTHO, ENGINEERING CONSTANTS or ANISO; *EXPANSION: TYPE=
        absent or ISO (temperature tables admitted);
      - *SOLID SECTION: ORIENTATION= admitted (*ORIENTATION is a supported keyword);
      - *INITIAL CONDITIONS: TYPE=TEMPERATURE only;
      - *PRE-TENSION SECTION: SURFACE= only, and no *NODE PRINT of RF in the deck (ccx prints a
        force of the cut's first node at the reference node);
      - *MPC: PLANE, STRAIGHT or MEANROT (its first data field); PLANE and STRAIGHT only in the
        nonlinear set (ccx switches NLGEOM on for them); *RIGID BODY with REF NODE= and ROT
        NODE=;
      - *CONTROLS, PARAMETERS=FIELD: R_n and C_n (its first two fields) at most 0.1;
      - *BOUNDARY: first and last dof within 1-3; *CLOAD: dof within 1-3;
      - *DLOAD: load label P1-P6 (face pressures), GRAV or CENTRIF (body loads) only;
      - *STEP: no NLGEOM (unless NLGEOM=NO), no PERTURBATION;
      - *NODE PRINT: variables from NODE_PRINT_VARIABLES (U, RF) only;
        *EL PRINT: variables from EL_PRINT_VARIABLES (S, E, EVOL, ENER, ELSE, PEEQ) only
        (a deck printing any other variable is excluded: there is nothing to compare it with);
  (c) the deck has at least one *NODE PRINT or *EL PRINT (else there is nothing to compare).

The nonlinear peer set (`nlgeom=True`, run_peer.py --nlgeom) applies the same rule except
that it requires a *STEP with NLGEOM instead of forbidding it, and admits *PLASTIC with
HARDENING= absent, ISOTROPIC, KINEMATIC or COMBINED (with *CYCLIC HARDENING; curves by
temperature admitted), and
*HYPERELASTIC with a potential of HYPERELASTIC_MODELS and *HYPERFOAM in a deck without *DLOAD,
and *DEFORMATION PLASTICITY in a deck that prints no ENER or ELSE. The linear set keeps *PLASTIC out: ccx
switches NLGEOM on for any deck with a *PLASTIC material, so such a deck is nonlinear there
whatever its *STEP says.

The contact and tie sets judge and run the deck as `derived_deck()` derives it (run_peer.py
runs that derived deck through both solvers; it is written into the work folder, never into
this repository):
  - steps with PERTURBATION are dropped with their procedure (a frequency analysis after the
    static step: the static step is what is compared);
  - a deck that prints nothing (*NODE PRINT / *EL PRINT) gets *NODE PRINT U of every node and
    *EL PRINT S of every element in each step (sets PEERNALL / PEEREALL, defined before the
    first *STEP), so its .frd-only results can be compared as .dat blocks.

The contact peer set (`contact=True`, run_peer.py --contact): penalty contact with friction.
The same rule, with NLGEOM allowed (not required; C3D8I excluded), the keywords of
CONTACT_KEYWORDS admitted, and:
  - *CONTACT PAIR: TYPE= NODE TO SURFACE or SURFACE TO SURFACE (not MORTAR and its kin);
  - *SURFACE BEHAVIOR: PRESSURE-OVERCLOSURE= LINEAR, EXPONENTIAL, TABULAR, TIED or HARD;
  - *CONTACT PRINT / FILE / OUTPUT: variables from CONTACT_VARIABLES (CDIS, CSTR, CELS) only,
    by their first four characters as ccx reads them (CDISP, CSTRESS);
  - *FRICTION, *CHANGE FRICTION and *CHANGE SURFACE BEHAVIOR admitted; *MODEL CHANGE stays
    an unsupported keyword (one fixed set of pairs);
  - the deck has at least one *CONTACT PAIR;
  - no *SURFACE, TYPE=NODE in a deck with plane or axisymmetric elements (Kontakt refuses
    node surfaces on their nodes).

The tie peer set (`tie=True`, run_peer.py --tie): MPC-based tied contact (*TIE). The same
rule on the derived deck, with NLGEOM allowed (not required), and:
  - *TIE admitted without CYCLIC SYMMETRY and MULTISTAGE (other analyses);
  - *SURFACE INTERACTION, *SURFACE BEHAVIOR and *FRICTION admitted: without a *CONTACT PAIR
    (which stays unsupported in this set) they define nothing the analysis uses;
  - the deck has at least one *TIE.

Usable as a module (`exclusion_reason`, `qualifying_decks`, `element_types`, `read_text`,
`included_files`, `derived_deck`) and as a CLI:
    select_decks.py [--suite DIR] [--nlgeom | --contact | --tie]
                                               excluded decks with reasons, grouped counts,
                                               then the qualifying names
    select_decks.py --list                     only the qualifying names, one per line
"""
import argparse
import collections
import gzip
import os
import re
import sys

DEFAULT_SUITE = "/usr/share/doc/calculix-ccx-test/examples/test"

ELEMENT_TYPES = {"C3D4", "C3D6", "C3D8", "C3D8R", "C3D8I", "C3D10", "C3D15", "C3D20", "C3D20R",
                 "SPRINGA", "GAPUNI", "T3D2", "DCOUP3D"} | {
    f"{kind}{shape}" for kind in ("CPS", "CPE", "CAX") for shape in ("3", "4", "4R", "6", "8", "8R")}
SUPPORTED_KEYWORDS = {
    "HEADING", "NODE", "ELEMENT", "NSET", "ELSET", "SURFACE", "MATERIAL", "ELASTIC", "DENSITY",
    "EXPANSION", "SOLID SECTION", "INITIAL CONDITIONS", "TEMPERATURE", "BOUNDARY", "CLOAD",
    "DLOAD", "EQUATION", "AMPLITUDE", "STEP", "STATIC", "END STEP", "NODE PRINT", "EL PRINT",
    "NODE FILE", "EL FILE", "NODE OUTPUT", "ELEMENT OUTPUT", "OUTPUT", "FILE FORMAT", "CONTROLS",
    "TRANSFORM", "ORIENTATION", "PRE-TENSION SECTION", "RIGID BODY", "MPC", "SPRING", "GAP",
    "DISTRIBUTING COUPLING",
}
# *MPC types the peer sets compare; PLANE and STRAIGHT switch NLGEOM on in ccx (not MEANROT).
# Kontakt builds DIST too, but ccx 2.20 lets a DIST go while it still pulls (tests/peer/README.md):
# the coverage report measures the suite's dist deck.
MPC_TYPES = {"PLANE", "STRAIGHT", "MEANROT"}
ELASTIC_TYPES = ("ISO", "ORTHO", "ENGINEERINGCONSTANTS", "ANISO")  # as ccx: by first characters
FORBIDDEN_PARAMETERS = {"USER"}
# *HYPERELASTIC potentials of the nonlinear set (the polynomial family and OGDEN; ARRUDA-BOYCE out).
HYPERELASTIC_MODELS = {"NEO HOOKE", "MOONEY-RIVLIN", "POLYNOMIAL", "REDUCED POLYNOMIAL", "YEOH",
                       "OGDEN"}
CONTACT_KEYWORDS = {"CONTACT PAIR", "SURFACE INTERACTION", "SURFACE BEHAVIOR", "CONTACT PRINT",
                    "CONTACT FILE", "CONTACT OUTPUT", "FRICTION", "CHANGE FRICTION",
                    "CHANGE SURFACE BEHAVIOR"}
CONTACT_TYPES = {"NODE TO SURFACE", "SURFACE TO SURFACE"}
PRESSURE_OVERCLOSURES = {"LINEAR", "EXPONENTIAL", "TABULAR", "TIED", "HARD"}
CONTACT_VARIABLES = {"CDIS", "CSTR", "CELS"}
TIE_KEYWORDS = {"TIE", "SURFACE INTERACTION", "SURFACE BEHAVIOR", "FRICTION"}
TIE_REFUSED_PARAMETERS = {"CYCLIC SYMMETRY", "MULTISTAGE"}
NODE_PRINT_VARIABLES = {"U", "RF"}
EL_PRINT_VARIABLES = {"S", "E", "EVOL", "ENER", "ELSE", "PEEQ"}

_INCLUDE = re.compile(r"(?im)^\s*\*\s*INCLUDE\s*,\s*INPUT\s*=\s*([^\s,]+)")


# ----------------------------------------------------------------------------- reading decks

def read_text(path):
    """Text of a deck or include file, read from `path` or, failing that, `path.gz`."""
    for candidate in (path, path + ".gz"):
        if os.path.exists(candidate):
            opener = gzip.open if candidate.endswith(".gz") else open
            with opener(candidate, "rt", errors="replace") as f:
                return f.read()
    raise FileNotFoundError(path)


def deck_names(folder):
    """Names (without .inp / .inp.gz) of every deck in a folder, sorted."""
    return sorted({f[:-4] if f.endswith(".inp") else f[:-7] for f in os.listdir(folder)
                   if f.endswith(".inp") or f.endswith(".inp.gz")})


def deck_path(folder, name):
    """Path of NAME's deck in folder without any .gz suffix (read_text finds either form)."""
    return os.path.join(folder, name + ".inp")


def included_files(deck_file):
    """Names (as written in *INCLUDE, relative to the deck's folder) of every file the deck
    includes, recursively, without duplicates."""
    out, todo = [], [deck_file]
    while todo:
        text = read_text(todo.pop())
        for m in _INCLUDE.finditer(text):
            name = m.group(1).strip("\"'")
            if name not in out:
                out.append(name)
                todo.append(os.path.join(os.path.dirname(deck_file), name))
    return out


def _normalise(word):
    return re.sub(r"\s+", " ", word.strip().upper())


def records(path, _seen=None, text=None):
    """(KEYWORD, {PARAM: value}, [data lines]) of a deck in order, *INCLUDEs expanded; `text`
    replaces the content of `path` itself (includes are still read relative to it)."""
    _seen = set() if _seen is None else _seen
    base = path[:-3] if path.endswith(".gz") else path
    if base in _seen:
        return
    _seen.add(base)
    current = None
    for raw in (read_text(base) if text is None else text).splitlines():
        line = raw.strip()
        if not line or line.startswith("**"):
            continue
        if line.startswith("*"):
            if current:
                yield current
            parts = line[1:].split(",")
            keyword = _normalise(parts[0])
            params = {}
            for p in parts[1:]:
                if p.strip():
                    k, _, v = p.partition("=")
                    params[_normalise(k)] = v.strip()
            if keyword == "INCLUDE":
                current = None
                inc = params.get("INPUT", "").strip("\"'")
                yield from records(os.path.join(os.path.dirname(base), inc), _seen)
                continue
            current = (keyword, params, [])
        elif current:
            current[2].append(line)
    if current:
        yield current


def element_types(path):
    """Sorted element TYPE= values of a deck (for reports)."""
    return sorted({p.get("TYPE", "?").upper() for k, p, _ in records(path) if k == "ELEMENT"})


# ------------------------------------------------------------------------ derived tie decks

_STEP_LINE = re.compile(r"^\s*\*\s*STEP\b", re.IGNORECASE)
_END_STEP_LINE = re.compile(r"^\s*\*\s*END\s*STEP\b", re.IGNORECASE)


def _id_lines(ids):
    return [", ".join(str(i) for i in ids[k:k + 16]) for k in range(0, len(ids), 16)]


def derived_deck(path):
    """Text of the deck at `path` as the contact and tie sets run it (module docstring):
    PERTURBATION steps dropped, prints added (with_prints). Only the deck's own text changes
    (its *INCLUDE files are used as they are)."""
    kept, dropping = [], False
    for line in read_text(path).splitlines():
        if _STEP_LINE.match(line) and "PERTURBATION" in line.upper().replace(" ", ""):
            dropping = True
        if not dropping:
            kept.append(line)
        elif _END_STEP_LINE.match(line):
            dropping = False
    return with_prints(path, "\n".join(kept) + "\n")


def with_prints(path, text):
    """`text` (the deck at `path` or a form derived from it) as it is compared: a deck that
    prints nothing to the .dat (friction1, fricloop, the tie decks: .frd output only) gets
    prints of U at every node and S at every element at the end of each step, the same for
    ccx and kontakt; a deck that prints keeps its own requests."""
    lines = text.splitlines()
    recs = list(records(path, text=text))
    if any(k in ("NODE PRINT", "EL PRINT") for k, _, _ in recs):
        return text
    nodes, elements = set(), set()
    for keyword, _, data in recs:
        if keyword == "NODE":
            nodes.update(int(line.split(",")[0]) for line in data)
        elif keyword == "ELEMENT":  # a continuation line starts with a node, not a label
            elements.update(int(line.split(",")[0]) for line, previous in zip(data, [""] + data)
                            if not previous.rstrip().endswith(","))
    sets = (["*NSET, NSET=PEERNALL"] + _id_lines(sorted(nodes))
            + ["*ELSET, ELSET=PEEREALL"] + _id_lines(sorted(elements)))
    prints = ["*NODE PRINT, NSET=PEERNALL", "U", "*EL PRINT, ELSET=PEEREALL", "S"]
    out, sets_written = [], False
    for line in lines:
        if _STEP_LINE.match(line) and not sets_written:
            out += sets
            sets_written = True
        if _END_STEP_LINE.match(line):
            out += prints
        out.append(line)
    return "\n".join(out) + "\n"


# ----------------------------------------------------------------------------------- the rule

def _contact_limit(keyword, params, data):
    """The contact set's limit a contact keyword breaks, or None."""
    if keyword == "CONTACT PAIR":
        kind = _normalise(params.get("TYPE", ""))
        if kind not in CONTACT_TYPES:
            return f"*CONTACT PAIR, TYPE={kind or '(none)'}"
    elif keyword == "SURFACE BEHAVIOR":
        law = _normalise(params.get("PRESSURE-OVERCLOSURE", ""))
        if law not in PRESSURE_OVERCLOSURES:
            return f"*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE={law or '(none)'}"
    elif keyword in ("CONTACT PRINT", "CONTACT FILE", "CONTACT OUTPUT"):
        for line in data:
            for var in (_normalise(v) for v in line.split(",")):
                if var and var[:4] not in CONTACT_VARIABLES:  # ccx reads 4 characters (CDISP)
                    return f"*{keyword} of {var}"
    return None


def plastic_exclusion(params):
    """Why a *PLASTIC record is outside the nonlinear set, or None: isotropic, kinematic or
    combined hardening."""
    hardening = params.get("HARDENING", "ISOTROPIC").upper()
    if hardening not in ("ISOTROPIC", "KINEMATIC", "COMBINED"):
        return f"*PLASTIC, HARDENING={hardening}"
    return None


def _tie_limit(keyword, params):
    """The tie set's limit a *TIE breaks, or None."""
    if keyword == "TIE":
        refused = TIE_REFUSED_PARAMETERS.intersection(params)
        if refused:
            return f"*TIE, {sorted(refused)[0]}"
    return None


def exclusion_reason(path, nlgeom=False, contact=False, tie=False):
    """THE qualification rule (see the module docstring): None when the deck at `path`
    qualifies, otherwise a short text naming the first check it breaks."""
    try:
        recs = list(records(path, text=derived_deck(path) if tie or contact else None))
    except (OSError, UnicodeError, ValueError) as e:
        return f"unreadable: {e}"
    prints, has_nlgeom, pairs, ties, planar = 0, False, 0, 0, False
    keywords = (SUPPORTED_KEYWORDS | (CONTACT_KEYWORDS if contact else set())
                | (TIE_KEYWORDS if tie else set()))
    for keyword, params, data in recs:
        if keyword == "ELEMENT":  # (a)
            etype = params.get("TYPE", "").upper()
            if etype not in ELEMENT_TYPES:
                return f"element {etype or '(no TYPE)'}"
            if contact and etype == "C3D8I":
                return "C3D8I in the contact set"
            planar |= etype[:3] in ("CPS", "CPE", "CAX")
            continue
        if (keyword == "SURFACE" and planar
                and params.get("TYPE", "ELEMENT").upper().replace(" ", "") == "NODE"):
            return "node surface in a deck with 2D elements"
        if keyword == "PLASTIC" and nlgeom:  # (b), nonlinear set only
            reason = plastic_exclusion(params)
            if reason:
                return reason
            continue
        if keyword == "CYCLIC HARDENING" and nlgeom:  # (b), nonlinear set only
            continue
        if keyword == "DEFORMATION PLASTICITY" and nlgeom:  # (b), nonlinear set only
            # Kontakt has no energy of this law to print (ccx's ENER of it is not known).
            if any(k == "EL PRINT" and {"ENER", "ELSE"} & {_normalise(v) for line in d
                                                          for v in line.split(",")}
                   for k, _, d in recs):
                return "*DEFORMATION PLASTICITY with *EL PRINT of ENER or ELSE"
            continue
        if keyword in ("HYPERELASTIC", "HYPERFOAM") and nlgeom:  # (b), nonlinear set only
            models = set(params) - {"N"}
            if keyword == "HYPERELASTIC" and not models <= HYPERELASTIC_MODELS:
                return f"*HYPERELASTIC, {sorted(models - HYPERELASTIC_MODELS)[0]}"
            # A pressure on a hyperelastic body: ccx 2.20 stops one Newton iteration earlier
            # than Kontakt (beamnh: 3 against 4, 2.4e-3 apart; an *ELASTIC column alike): open.
            if any(k == "DLOAD" for k, _, _ in recs):
                return f"*{keyword} with *DLOAD"
            continue
        if keyword not in keywords:  # (b)
            return f"keyword *{keyword}"
        if tie and keyword in TIE_KEYWORDS:
            limit = _tie_limit(keyword, params)
            if limit:
                return limit
            ties += keyword == "TIE"
            continue
        if keyword in CONTACT_KEYWORDS:
            limit = _contact_limit(keyword, params, data)
            if limit:
                return limit
            pairs += keyword == "CONTACT PAIR"
            continue
        forbidden = FORBIDDEN_PARAMETERS.intersection(params)
        if forbidden:
            return f"*{keyword}, {sorted(forbidden)[0]}"
        if keyword in ("ELASTIC", "EXPANSION"):
            types = ELASTIC_TYPES if keyword == "ELASTIC" else ("ISO",)
            if not params.get("TYPE", "ISO").upper().replace(" ", "").startswith(types):
                return f"*{keyword}, TYPE={params['TYPE'].upper()}"
        elif keyword == "INITIAL CONDITIONS" and params.get("TYPE", "").upper() != "TEMPERATURE":
            return f"*INITIAL CONDITIONS, TYPE={params.get('TYPE', '?').upper()}"
        elif keyword in ("BOUNDARY", "CLOAD"):
            for line in data:
                fields = [f.strip() for f in line.split(",")]
                dofs = [f for f in (fields[1:3] if keyword == "BOUNDARY" else fields[1:2]) if f]
                if any(not d.isdigit() or not 1 <= int(d) <= 3 for d in dofs):
                    return f"*{keyword} dof outside 1-3"
        elif keyword == "DLOAD":
            for line in data:
                fields = [f.strip().upper() for f in line.split(",")]
                if len(fields) < 2 or not re.fullmatch(r"P[1-6]|GRAV|CENTRIF", fields[1]):
                    label = fields[1] if len(fields) > 1 else "?"
                    return f"*DLOAD {re.sub(r'[0-9]+$', 'n', label)} (not Pn)"
        elif keyword == "STEP":
            flag = params.get("NLGEOM")
            if flag is not None and flag.upper() != "NO":
                if not (nlgeom or contact or tie):
                    return "*STEP, NLGEOM"
                has_nlgeom = True
            if "PERTURBATION" in params:
                return "*STEP, PERTURBATION"
        elif keyword == "PRE-TENSION SECTION":
            if "SURFACE" not in params:
                return "*PRE-TENSION SECTION without SURFACE="
            # ccx 2.20 prints at the reference node the normal force on the cut's first node
            # (pret1: 1.03 of a bolt force of 10), Kontakt its element forces (none) as at
            # every node: the RF blocks of such decks are not comparable.
            if any(k == "NODE PRINT" and "RF" in {_normalise(v) for line in d
                                                  for v in line.split(",")}
                   for k, _, d in recs):
                return "*PRE-TENSION SECTION with *NODE PRINT of RF"
        elif keyword == "MPC":
            mpc = data[0].split(",")[0].strip().upper() if data else ""
            if mpc not in MPC_TYPES:
                return f"*MPC {mpc or '(no type)'}"
            if mpc != "MEANROT" and not nlgeom:
                return f"*MPC {mpc} (ccx switches NLGEOM on)"
        elif keyword == "RIGID BODY":
            if not {"REF NODE", "ROT NODE"} <= set(params):
                return "*RIGID BODY without REF NODE= and ROT NODE="
        elif keyword == "CONTROLS" and params.get("PARAMETERS", "").upper() == "FIELD":
            # Residual or correction criteria looser than a tenth leave both solvers far from
            # equilibrium, each where its own iterations stop (beammrco: 0.25, ccx stops after
            # 7 iterations, Kontakt after 4, 4.7e-2 apart): no common answer to compare.
            first = data[0].split(",") if data else []
            if any(_float(f) > 0.1 for f in first[:2]):
                return "*CONTROLS, PARAMETERS=FIELD with R_n or C_n above 0.1"
        elif keyword in ("NODE PRINT", "EL PRINT"):
            allowed = NODE_PRINT_VARIABLES if keyword == "NODE PRINT" else EL_PRINT_VARIABLES
            for line in data:
                for var in (_normalise(v) for v in line.split(",")):
                    if var and var not in allowed:
                        return f"*{keyword} of {var}"
            prints += 1
    if prints == 0 and not contact:  # (c); the contact set prints U itself (run_peer.py)
        return "no *NODE PRINT / *EL PRINT"
    if nlgeom and not has_nlgeom:
        return "no NLGEOM step"
    if contact and not pairs:
        return "no *CONTACT PAIR"
    if tie and not ties:
        return "no *TIE"
    return None


def _float(text):
    """The number in a data field, 0 for an empty or unreadable one."""
    try:
        return float(text.strip().replace("d", "e").replace("D", "e"))
    except ValueError:
        return 0.0


def has_nlgeom_step(path, text=None):
    """True when a *STEP of the deck (or of `text`, standing for it) has NLGEOM (not =NO)."""
    return any(k == "STEP" and p.get("NLGEOM", "NO").upper() != "NO"
               for k, p, _ in records(path, text=text))


# ccx's procedure keywords (each step has one; *CREEP is a material card, not a procedure).
PROCEDURES = {"STATIC", "FREQUENCY", "BUCKLE", "DYNAMIC", "MODAL DYNAMIC", "STEADY STATE DYNAMICS",
              "COMPLEX FREQUENCY", "HEAT TRANSFER", "COUPLED TEMPERATURE-DISPLACEMENT",
              "UNCOUPLED TEMPERATURE-DISPLACEMENT", "VISCO", "GREEN", "SENSITIVITY",
              "ELECTROMAGNETICS", "CFD", "MASS FLOW", "NO ANALYSIS", "SUBSTRUCTURE GENERATE"}


def is_static_only(path):
    """The coverage report's population (coverage.py): the deck (its *INCLUDEs expanded) has
    at least one procedure and every procedure keyword in it is *STATIC."""
    procedures = {k for k, _, _ in records(path) if k in PROCEDURES}
    return procedures == {"STATIC"}


FILE_REQUESTS = {"NODE FILE", "EL FILE", "CONTACT FILE", "NODE OUTPUT", "ELEMENT OUTPUT",
                 "CONTACT OUTPUT"}


def has_file_requests(path, text=None):
    """True when the deck (or `text`, standing for it) requests .frd output (*NODE FILE,
    *EL FILE, *CONTACT FILE or their OUTPUT synonyms)."""
    return any(k in FILE_REQUESTS for k, _, _ in records(path, text=text))


def qualifying_decks(folder, nlgeom=False, contact=False, tie=False):
    """(qualifying names, {excluded name: reason}) over every deck in the folder."""
    good, excluded = [], {}
    for name in deck_names(folder):
        reason = exclusion_reason(deck_path(folder, name), nlgeom, contact, tie)
        if reason is None:
            good.append(name)
        else:
            excluded[name] = reason
    return good, excluded


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--suite", default=DEFAULT_SUITE, help="deck folder (default: %(default)s)")
    p.add_argument("--nlgeom", action="store_true", help="the nonlinear set instead")
    p.add_argument("--contact", action="store_true", help="the frictionless contact set instead")
    p.add_argument("--tie", action="store_true", help="the *TIE set instead")
    p.add_argument("--list", action="store_true", help="print only the qualifying names")
    a = p.parse_args(argv)
    if not os.path.isdir(a.suite):
        print(f"deck folder not found: {a.suite} (install calculix-ccx-test)", file=sys.stderr)
        return 1
    good, excluded = qualifying_decks(a.suite, a.nlgeom, a.contact, a.tie)
    if a.list:
        print("\n".join(good))
        return 0
    for name, reason in excluded.items():
        print(f"excluded {name:24s} {reason}")
    print(f"\nexclusion reasons ({len(excluded)} decks):")
    for reason, count in collections.Counter(excluded.values()).most_common():
        print(f"  {count:4d}  {reason}")
    print(f"\n{len(good)} qualifying decks:")
    print("\n".join(good))
    return 0


if __name__ == "__main__":
    sys.exit(main())
