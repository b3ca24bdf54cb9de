"""Round seven's kinds of the generated maker drawings (issue 114; tests/gen_drawings.py,
``--kinds round7`` of benchmarks/imports/infer_edits.py), their truths from the spec
(docs/import.md, "What an edit means"), not from the inference:

* ``checker``: a lattice of round holes of two sizes, ``nx`` x ``ny`` on ``px`` / ``py``,
  (``py`` None: one pitch both ways), ``d`` and ``d2``, the second where ``(i + j) % 2 == 1`` (``mode`` ``parity``: a
  checkerboard) or at the nodes ``odd`` (``mixed``); centred on the plate (``at`` ``C``: a new
  pitch or count spreads it about the centre) or its first hole ``ix``, ``iy`` in from the lower
  left corner, within one and a half pitches of both edges (``LB``: that end member stays);
  one grid, each hole its own size on its turn (a new column of a checkerboard keeps the
  parity);
* ``edgehole``: one hole ``ox`` from the left or right edge (``sx``) and ``oy`` from the
  bottom or top (``sy``), nearer them than the centre lines: it moves with those edges, and
  each distance is a number a maker edits;
* ``asympair``: two holes of one size in line along ``dir`` on the plate's centre line, ``a``
  from the low edge and ``b`` from the high one (``a != b``: not mirrored), each nearer its
  edge than the centre line: each keeps its distance to its own edge.

Design units (mm or inches, :class:`~gen_drawings.Design`)."""
from __future__ import annotations


def round7_members(f, origin, W: float, H: float) -> list:
    """``[((x, y), diameter)]`` of feature ``f`` on a plate ``W`` x ``H`` drawn from
    ``origin`` (design units)."""
    x0, y0 = origin
    k = f["kind"]
    if k == "checker":
        out = []
        py = f["py"] or f["px"]
        for i in range(f["nx"]):
            for j in range(f["ny"]):
                if f["at"] == "C":
                    x = x0 + W / 2 + (i - (f["nx"] - 1) / 2) * f["px"]
                    y = y0 + H / 2 + (j - (f["ny"] - 1) / 2) * py
                else:
                    x, y = x0 + f["ix"] + i * f["px"], y0 + f["iy"] + j * py
                two = (i + j) % 2 == 1 if f["mode"] == "parity" else [i, j] in \
                    [list(t) for t in f["odd"]]
                out.append(((x, y), f["d2"] if two else f["d"]))
        return out
    if k == "edgehole":
        x = x0 + f["ox"] if f["sx"] == "L" else x0 + W - f["ox"]
        y = y0 + f["oy"] if f["sy"] == "B" else y0 + H - f["oy"]
        return [((x, y), f["d"])]
    # asympair
    if f["dir"] == "x":
        return [((x0 + f["a"], y0 + H / 2), f["d"]), ((x0 + W - f["b"], y0 + H / 2), f["d"])]
    return [((x0 + W / 2, y0 + f["a"]), f["d"]), ((x0 + W / 2, y0 + H - f["b"]), f["d"])]


def _round7_valid(d, f, m: float) -> bool:
    """Whether ``f`` on design ``d`` is what its kind says, and no other reading fits (``m``:
    the least web, design units)."""
    W, H = d.width, d.height
    k = f["kind"]
    if k == "checker":
        if min(f["px"], f["py"] or f["px"]) < max(f["d"], f["d2"]) + m or f["d"] == f["d2"] or \
                max(f["d"], f["d2"]) > 2 * min(f["d"], f["d2"]) or f["nx"] * f["ny"] < 4:
            return False
        if f["mode"] == "mixed" and not f["odd"]:
            return False
        if f["at"] != "C":      # by its end member: within 1.5 pitches of the low edges,
            for size, inset, p, n in ((W, f["ix"], f["px"], f["nx"]),
                                      (H, f["iy"], f["py"] or f["px"], f["ny"])):
                far = size - inset - (n - 1) * p
                if not (0 < inset < 1.5 * p and inset < far - 1e-9):
                    return False    # ...and nearer them than the far ones
        return True
    if k == "edgehole":
        return 0 < f["ox"] * 4 < W - 1e-9 and 0 < f["oy"] * 4 < H - 1e-9
    size = W if f["dir"] == "x" else H
    return abs(f["a"] - f["b"]) > 1e-6 and 0 < f["a"] * 4 < size - 1e-9 and \
        0 < f["b"] * 4 < size - 1e-9


def random_round7(rng, T: dict, kind: str, dia: float) -> dict:
    """A random feature of round seven's ``kind`` (``T``: the unit's table of numbers,
    ``dia``: a hole size drawn from it)."""
    if kind == "checker":
        f = {"kind": kind, "nx": rng.randint(2, 5), "ny": rng.randint(2, 4),
             "px": rng.choice(T["pitch"]), "py": rng.choice([None] + T["pitch"]), "d": dia,
             "mode": rng.choice(["parity", "parity", "mixed"]), "at": rng.choice(["C", "LB"])}
        if f["py"] == f["px"]:
            f["py"] = None          # one pitch both ways (as the grid kind's)
        f["d2"] = round(dia * rng.choice([0.75, 0.8, 1.25, 1.5]), 4)
        f["odd"] = sorted({(rng.randrange(f["nx"]), rng.randrange(f["ny"]))
                           for _ in range(rng.randint(1, 3))})
        if f["at"] != "C":
            f["ix"] = round(f["px"] * rng.choice([0.5, 0.75, 1.0]), 4)
            f["iy"] = round((f["py"] or f["px"]) * rng.choice([0.5, 0.75, 1.0]), 4)
        return f
    if kind == "edgehole":
        return {"kind": kind, "d": rng.choice(T["d"] + T["big"][:2]), "sx": rng.choice("LR"),
                "sy": rng.choice("BT"), "ox": rng.choice(T["off"]) * rng.choice([1, 1.5, 2]),
                "oy": rng.choice(T["off"]) * rng.choice([1, 1.5, 2])}
    a = rng.choice(T["off"]) * rng.choice([1, 1.5, 2])
    b = a + rng.choice([-1, 1]) * rng.choice([T["off"][0] / 100, T["off"][0] / 4, T["off"][0]])
    return {"kind": kind, "d": dia, "dir": rng.choice("xy"), "a": a, "b": round(b, 4)}
