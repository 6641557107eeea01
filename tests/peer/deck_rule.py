"""The written, mechanical rule that decides which ccx decks the linear peer test runs.

A deck qualifies when, after resolving *INCLUDE (the nonlinear set, `nlgeom=True`, instead
requires a *STEP with NLGEOM and compares at the times both solvers printed):
  1. every *ELEMENT TYPE is one of our solid types (C3D4 C3D6 C3D8 C3D8R C3D8I C3D10 C3D15
     C3D20 C3D20R);
  2. every keyword is in SUPPORTED, with the parameter limits below: *STEP without NLGEOM or
     PERTURBATION, *STATIC (any SOLVER=), *ELASTIC isotropic with one data line, *EXPANSION
     isotropic with one data line, *SOLID SECTION without ORIENTATION, *INITIAL CONDITIONS of
     TYPE=TEMPERATURE, *BOUNDARY and *CLOAD on dofs 1-3 only, *DLOAD of face-pressure type Pn;
     no TIME DELAY or USER options anywhere, and in the nonlinear set no C3D8I;
  3. it prints something to compare: a *NODE PRINT of U/RF or an *EL PRINT of
     S/E/EVOL/ENER/ELSE, and nothing else.
The first rule a deck breaks is its exclusion reason.
"""
import gzip
import os
import re

OUR_ELEMENTS = {"C3D4", "C3D6", "C3D8", "C3D8R", "C3D8I", "C3D10", "C3D15", "C3D20", "C3D20R"}
SUPPORTED = {
    "HEADING", "NODE", "ELEMENT", "NSET", "ELSET", "SURFACE", "MATERIAL", "ELASTIC", "DENSITY",
    "EXPANSION", "SOLID SECTION", "INITIAL CONDITIONS", "TEMPERATURE", "BOUNDARY", "CLOAD",
    "DLOAD", "EQUATION", "AMPLITUDE", "STEP", "STATIC", "END STEP", "NODE PRINT", "EL PRINT",
    "NODE FILE", "EL FILE", "NODE OUTPUT", "ELEMENT OUTPUT", "OUTPUT", "FILE FORMAT", "CONTROLS",
}
# Options the solver rejects wherever they appear (time-delayed loads, user subroutines).
UNSUPPORTED_PARAMETERS = {"TIME DELAY", "TIMEDELAY", "USER"}
NODE_PRINT_VARS = {"U", "RF"}
EL_PRINT_VARS = {"S", "E", "EVOL", "ENER", "ELSE"}


def read_text(path):
    """Text of a deck or include, transparently gunzipping `path` or `path.gz`."""
    for candidate in (path, path + ".gz"):
        if os.path.exists(candidate):
            opener = gzip.open if candidate.endswith(".gz") else open
            with opener(candidate, "rt", errors="replace") as f:
                return f.read()
    raise FileNotFoundError(path)


def deck_path(suite, name):
    for candidate in (os.path.join(suite, name + ".inp"), os.path.join(suite, name + ".inp.gz")):
        if os.path.exists(candidate):
            return candidate
    return None


def records(path, seen=None):
    """(keyword, params dict, data lines) of a deck, *INCLUDEs expanded (relative to the file)."""
    seen = seen or set()
    base = path[:-3] if path.endswith(".gz") else path
    if base in seen:
        return
    seen.add(base)
    current = None
    for raw in read_text(base).splitlines():
        line = raw.strip()
        if not line or line.startswith("**"):
            continue
        if line.startswith("*"):
            if current:
                yield current
            parts = [p.strip() for p in line[1:].split(",")]
            keyword = re.sub(r"\s+", " ", parts[0].upper())
            params = {}
            for p in parts[1:]:
                if not p:
                    continue
                k, _, v = p.partition("=")
                params[re.sub(r"\s+", " ", k.strip().upper())] = v.strip()
            if keyword == "INCLUDE":
                current = None
                inc = params.get("INPUT", "")
                yield from records(os.path.join(os.path.dirname(base), inc), seen)
                continue
            current = (keyword, params, [])
        elif current:
            current[2].append(line)
    if current:
        yield current


def first_violation(path, nlgeom=False):
    """None when the deck qualifies, otherwise the first rule it breaks (a short reason).
    With nlgeom, the deck must have a NLGEOM step (the nonlinear peer set) instead of none."""
    prints, has_nlgeom = 0, False
    try:
        recs = list(records(path))
    except (OSError, UnicodeError) as e:
        return f"unreadable: {e}"
    for keyword, params, data in recs:
        if keyword not in SUPPORTED:
            return f"keyword *{keyword}"
        unsupported = UNSUPPORTED_PARAMETERS.intersection(params)
        if unsupported:
            return f"*{keyword} {sorted(unsupported)[0]}"
        if keyword == "ELEMENT":
            etype = params.get("TYPE", "").upper()
            if etype not in OUR_ELEMENTS:
                return f"element {etype or '?'}"
            if nlgeom and etype == "C3D8I":
                return "C3D8I under NLGEOM"
        elif keyword == "STEP":
            flag = params.get("NLGEOM")
            if flag is not None and flag.upper() != "NO":
                if not nlgeom:
                    return "NLGEOM"
                has_nlgeom = True
            if "PERTURBATION" in params:
                return "PERTURBATION"
        elif keyword in ("ELASTIC", "EXPANSION"):
            if params.get("TYPE", "ISO").upper() not in ("ISO", "ISOTROPIC"):
                return f"*{keyword} TYPE={params['TYPE']}"
            if len(data) != 1:
                return f"*{keyword} temperature table"
        elif keyword == "SOLID SECTION" and "ORIENTATION" in params:
            return "*SOLID SECTION ORIENTATION"
        elif keyword == "INITIAL CONDITIONS" and params.get("TYPE", "").upper() != "TEMPERATURE":
            return f"*INITIAL CONDITIONS TYPE={params.get('TYPE', '?')}"
        elif keyword in ("BOUNDARY", "CLOAD"):
            for line in data:
                fields = [f.strip() for f in line.split(",")]
                dof_fields = fields[1:3] if keyword == "BOUNDARY" else fields[1:2]
                dofs = [f for f in dof_fields if f]
                if any(not d.isdigit() or not 1 <= int(d) <= 3 for d in dofs):
                    return f"*{keyword} dof outside 1-3"
        elif keyword == "DLOAD":
            for line in data:
                fields = [f.strip().upper() for f in line.split(",")]
                if len(fields) < 2 or not re.fullmatch(r"P[1-6]", fields[1]):
                    return "*DLOAD other than Pn"
        elif keyword in ("NODE PRINT", "EL PRINT"):
            allowed = NODE_PRINT_VARS if keyword == "NODE PRINT" else EL_PRINT_VARS
            for line in data:
                for var in (v.strip().upper() for v in line.split(",")):
                    if var and var not in allowed:
                        return f"*{keyword} {var}"
            prints += 1
    if prints == 0:
        return "nothing printed"
    if nlgeom and not has_nlgeom:
        return "no NLGEOM step"
    return None


def qualifying_decks(suite, nlgeom=False):
    """(qualifying names, {name: reason}) for every deck in the suite folder."""
    names = sorted({f[:-4] if f.endswith(".inp") else f[:-7]
                    for f in os.listdir(suite) if f.endswith(".inp") or f.endswith(".inp.gz")})
    good, excluded = [], {}
    for name in names:
        reason = first_violation(deck_path(suite, name), nlgeom)
        if reason is None:
            good.append(name)
        else:
            excluded[name] = reason
    return good, excluded
