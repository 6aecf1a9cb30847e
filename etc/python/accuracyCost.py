"""Accuracy against cost: the Pareto front of measured runs and the budget
answer "the cheapest configuration whose error is <= X" (used by
bin/mpmAccuracyCost and benchmarks/accuracyCost).

Also a small reader of OpenFOAM dictionaries (the sweep dictionary) and the
results CSV of mpmAccuracyCost: '#' header lines (machine, sweep), then one
row per run with the parameter values, the entries each run set
(columns "file:entry/path", what the solver's end-of-run log matches against
the case), error, cost and status.
"""
import csv
import math
import re

# ---------------------------------------------------------------------------
# OpenFOAM dictionary (subset: keyword value; sub { }; lists ( ); strings)


def _tokens(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    pos, out = 0, []
    pat = re.compile(r'\s+|//[^\n]*|"((?:[^"\\]|\\.)*)"|([{}();])|([^\s{}();"]+)')
    while pos < len(text):
        m = pat.match(text, pos)
        if m is None:
            raise ValueError(f"cannot read dictionary near {text[pos:pos + 30]!r}")
        pos = m.end()
        if m.group(1) is not None:
            out.append(("str", m.group(1).replace('\\"', '"')))
        elif m.group(2):
            out.append(("punct", m.group(2)))
        elif m.group(3):
            out.append(("word", m.group(3)))
    return out


def _value(toks, i):
    """One value token or a ( ) list starting at i -> (value, next i)."""
    kind, t = toks[i]
    if kind == "punct" and t == "(":
        items, i = [], i + 1
        while not (toks[i][0] == "punct" and toks[i][1] == ")"):
            if toks[i][0] == "punct" and toks[i][1] == "{":
                d, i = _dict(toks, i + 1)
                items.append(d)
                continue
            v, i = _value(toks, i)
            items.append(v)
        return items, i + 1
    if kind == "punct":
        raise ValueError(f"unexpected '{t}'")
    return t, i + 1


def _dict(toks, i):
    d = {}
    while i < len(toks) and not (toks[i][0] == "punct" and toks[i][1] == "}"):
        key = toks[i][1]
        i += 1
        if toks[i] == ("punct", "{"):
            d[key], i = _dict(toks, i + 1)
            continue
        vals = []
        while toks[i] != ("punct", ";"):
            v, i = _value(toks, i)
            vals.append(v)
        d[key] = vals[0] if len(vals) == 1 else vals
        i += 1
    return d, i + 1


def read_dictionary(path):
    """An OpenFOAM dictionary file as nested dicts; values are strings or
    lists; FoamFile is dropped."""
    with open(path) as f:
        toks = _tokens(f.read())
    d, _ = _dict(toks + [("punct", "}")], 0)
    d.pop("FoamFile", None)
    return d


# ---------------------------------------------------------------------------
# Front and budget


def number(x):
    try:
        return float(x)
    except (TypeError, ValueError):
        return math.nan


def pareto(rows, err_key, time_key):
    """Non-dominated rows (no other row is both cheaper-or-equal and more
    accurate-or-equal, with one strict), sorted by time ascending."""
    pts = sorted((r for r in rows
                  if math.isfinite(number(r[err_key])) and math.isfinite(number(r[time_key]))),
                 key=lambda r: (number(r[time_key]), number(r[err_key])))
    front, best = [], math.inf
    for r in pts:
        if number(r[err_key]) < best:
            front.append(r)
            best = number(r[err_key])
    return front


def budget(front, err_key, target):
    """The cheapest front row with error <= target, or None."""
    for r in front:
        if number(r[err_key]) <= target:
            return r
    return None


# ---------------------------------------------------------------------------
# Results CSV of mpmAccuracyCost


def write_results(path, header, columns, rows):
    with open(path, "w", newline="") as f:
        for line in header:
            f.write(f"# {line}\n")
        w = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})


def read_results(path):
    """(header lines without '# ', rows as dicts of strings)."""
    header, lines = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                header.append(line[1:].strip())
            else:
                lines.append(line)
    return header, list(csv.DictReader(lines))


def header_value(header, key, default=""):
    for h in header:
        if h.startswith(key + ":"):
            return h.split(":", 1)[1].strip()
    return default
