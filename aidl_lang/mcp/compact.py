"""The MCP tools' results made short for agents (issue 73): one line of text beside the
structured content (never the structured content repeated as text), long lists of alike
items summarised with their count (``93 alike: through-cut ... 15 mm``) unless the call asks
for ``detail``, and one error shape for every failure: ``{"ok": false, "error": {"code",
"message", "argument"?}}`` (docs/mcp.md, "Results" and "Errors").

Error codes (``error.code``): a program's own first error code (``E0103``, ...) when the
program has errors, else one of :data:`CODES`.
"""
from __future__ import annotations

import json
import re

# the codes of a refused call, each with what it means (docs/mcp.md lists them)
CODES = {
    "unknown_argument": "an argument the tool does not take",
    "bad_argument": "an argument of the wrong type, out of its range, or a missing one",
    "program_choice": "both or neither of `source` and `path`",
    "outside_root": "a path outside the allowed folder (also through a symbolic link)",
    "symlink": "an output or program file written through a symbolic link",
    "not_found": "a file that does not exist, or is not a regular file",
    "wrong_kind": "a file of the wrong kind (a drawing where a program is taken, ...)",
    "no_match": "`values` names that match no value; `write_program` text not found",
    "not_unique": "`write_program`'s `old` text found more than once",
    "output_failed": "an output that could not be made or written",
    "timed_out": "a call stopped past 10 times its budget's CPU seconds of wall time",
    "worker_died": "the compile ended its worker process",
    "internal_error": "a fault of aidl itself (please report it)",
}

GROUP_AT = 12      # a list longer than this is summarised by alike items, unless `detail`
_PLACE = ("center", "from", "to", "box", "value", "mm")
_INDEX = re.compile(r"\[\d+\]")


def error(code: str, message: str, argument: str | None = None) -> dict:
    """``{"ok": false, "error": {...}}``: the structured content of a refused call."""
    e = {"code": code, "message": message}
    if argument:
        e["argument"] = argument
    return {"ok": False, "error": e}


def _points(v) -> list[tuple[float, float]]:
    """The (x, y) points of a place value: a point, a box [x0, y0, x1, y1] or a number."""
    if isinstance(v, (list, tuple)):
        if len(v) == 2 and all(isinstance(c, (int, float)) for c in v):
            return [(float(v[0]), float(v[1]))]
        if len(v) == 4 and all(isinstance(c, (int, float)) for c in v):
            return [(float(v[0]), float(v[1])), (float(v[2]), float(v[3]))]
    return []


def group(items: list, detail: bool = False) -> list:
    """``items`` (dicts) with alike ones (equal but for their places: ``center``, ``from``,
    ``to``, ``box``, the index in their name) summarised as one ``{"count", "alike": the
    first, "within": [x0, y0, x1, y1] of their places}`` each, when the list is longer than
    :data:`GROUP_AT` and not ``detail``; else ``items`` as they are."""
    if detail or len(items) <= GROUP_AT or not all(isinstance(i, dict) for i in items):
        return items
    groups: dict[str, list] = {}
    for it in items:
        key = {k: (_INDEX.sub("[*]", v) if k == "name" and isinstance(v, str) else v)
               for k, v in it.items() if k not in _PLACE}
        groups.setdefault(json.dumps(key, sort_keys=True, default=str), []).append(it)
    out = []
    for members in groups.values():
        if len(members) == 1:
            out.append(members[0])
            continue
        pts = [p for m in members for k in _PLACE[:4] for p in _points(m.get(k))]
        g = {"count": len(members), "alike": members[0]}
        if pts:
            xs, ys = [p[0] for p in pts], [p[1] for p in pts]
            g["within"] = [min(xs), min(ys), max(xs), max(ys)]
        out.append(g)
    return out


_COORD = re.compile(r"\((-?[\d.]+(?:e[-+]?\d+)?), (-?[\d.]+(?:e[-+]?\d+)?)\)")


def _n(v: float) -> str:
    return f"{round(v, 6):g}"


def text_lines(text: str, detail: bool = False) -> str:
    """``text`` (one feature a line) with more than :data:`GROUP_AT` lines alike but for
    their coordinates and indices said once: ``93 alike, within x -20..20, y -34.5..34.5:
    through-cut: Line `flex.cut_a` from (x, y) to (x, y), 15 mm``."""
    lines = text.splitlines()
    if detail or len(lines) <= GROUP_AT:
        return text
    keys = [_INDEX.sub("[*]", _COORD.sub("(x, y)", ln)) for ln in lines]
    count: dict[str, int] = {}
    for k in keys:
        count[k] = count.get(k, 0) + 1
    out, said = [], set()
    for ln, k in zip(lines, keys):
        if count[k] <= 2:
            out.append(ln)
            continue
        if k in said:
            continue
        said.add(k)
        pts = [(float(a), float(b)) for ln2, k2 in zip(lines, keys) if k2 == k
               for a, b in _COORD.findall(ln2)]
        where = ""
        if pts:
            xs, ys = [p[0] for p in pts], [p[1] for p in pts]
            where = f", within x {_n(min(xs))}..{_n(max(xs))}, y {_n(min(ys))}..{_n(max(ys))}"
        indent = k[:len(k) - len(k.lstrip())]
        out.append(f"{indent}{count[k]} alike{where}: {k.strip()}")
    return "\n".join(out)


def diagnostics(diags: list[dict], detail: bool = False) -> list[dict]:
    """The diagnostics without their ``rendered`` text (the message, span, hint and fix say
    it) unless ``detail``."""
    if detail:
        return diags
    return [{k: v for k, v in d.items() if k != "rendered"} for d in diags]


def no_repeats(doc: dict, detail: bool = False) -> dict:
    """A compiling tool's result without what it says twice or says nothing with, unless
    ``detail``: the job's ``text`` (the one line of text says it), ``solve`` when it
    converged (its statistics matter when it did not), ``fit`` when nothing was checked (no
    ``Place``: the line says so), and parts' boxes to 1e-6 mm and areas to 1e-3 mm²."""
    if detail:
        return doc
    doc = dict(doc)
    if isinstance(doc.get("job"), dict):
        doc["job"] = {k: v for k, v in doc["job"].items() if k != "text"}
    if isinstance(doc.get("solve"), dict) and doc["solve"].get("converged"):
        doc.pop("solve")
    if isinstance(doc.get("fit"), dict) and doc["fit"].get("checked") is False:
        doc.pop("fit")
    if isinstance(doc.get("parts"), list):
        doc["parts"] = [dict(p, bbox=[round(v, 6) for v in p["bbox"]], area=round(p["area"], 3))
                        if isinstance(p, dict) and "bbox" in p and "area" in p else p
                        for p in doc["parts"]]
    return doc


def describe(doc: dict, detail: bool = False) -> dict:
    """A ``describe`` result's data with each part's openings, through-cuts, notches and
    copies grouped (:func:`group`) and its text's alike lines said once (:func:`text_lines`),
    unless ``detail``."""
    if detail or "describe" not in doc:
        return doc
    d = dict(doc["describe"])
    parts = []
    for p in d.get("parts", []):
        p = dict(p)
        for k in ("openings", "through_cuts", "notches", "copies", "sinks"):
            if isinstance(p.get(k), list):
                p[k] = group(p[k])
        parts.append(p)
    d["parts"] = parts
    out = dict(doc, describe=d)
    if "text" in doc:
        out["text"] = text_lines(doc["text"])
    return out


def values(vals: list[dict], units: str, detail: bool = False) -> list[dict]:
    """``values`` entries compact unless ``detail``: ``mm`` left out where it equals
    ``value`` (a file in mm), and the copies of a pattern or loop (``cut_a[0].start``,
    ``cut_a[1].start``, ... more than :data:`GROUP_AT`) as one ``{"name":
    "cut_a[*].start", "kind": "group", "count", "value": the one value they share or the
    [x0, y0, x1, y1] their points span, "unit"}``."""
    if detail:
        return vals
    slim = [{k: v for k, v in x.items() if not (k == "mm" and x["value"] == v)} for x in vals]
    by: dict[str, list] = {}
    for x in slim:
        by.setdefault(_INDEX.sub("[*]", x["name"]), []).append(x)
    out, done = [], set()
    for x in slim:
        key = _INDEX.sub("[*]", x["name"])
        members = by[key]
        if len(members) <= GROUP_AT:
            out.append(x)
            continue
        if key in done:
            continue
        done.add(key)
        vs = [m["value"] for m in members]
        if all(v == vs[0] for v in vs):
            value = vs[0]
        else:
            pts = [p for v in vs for p in _points(v)]
            if pts:
                value = [min(p[0] for p in pts), min(p[1] for p in pts),
                         max(p[0] for p in pts), max(p[1] for p in pts)]
            else:
                nums = [v for v in vs if isinstance(v, (int, float))]
                value = [min(nums), max(nums)] if nums else vs[0]
        out.append({"name": key, "kind": "group", "count": len(members), "value": value,
                    "unit": members[0]["unit"], "of": members[0]["kind"]})
    return out


def _plural(n: int, word: str) -> str:
    return f"{n} {word}{'' if n == 1 else 's'}"


def _warnings(doc: dict) -> str:
    ws = [d["code"] for d in doc.get("diagnostics", []) if d.get("severity") == "warning"]
    if not ws:
        return "no warnings"
    codes = sorted(set(ws))
    return _plural(len(ws), "warning") + " (" + ", ".join(codes) + ")"


def _parts(doc: dict) -> str:
    ps = doc.get("parts") or []
    if not ps:
        return "no parts"
    shown = []
    for p in ps[:3]:
        x0, y0, x1, y1 = p["bbox"]
        shown.append(f"{p['name']} {_n(x1 - x0)} x {_n(y1 - y0)} mm, "
                     + _plural(p["holes"], "hole"))
    more = f", +{len(ps) - 3} more" if len(ps) > 3 else ""
    return _plural(len(ps), "part") + " (" + "; ".join(shown) + more + ")"


def _num(v) -> str:
    """A number to 1e-6 (``12.5``, ``-0.000001``, ``1234.567891``)."""
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        return str(v)
    v = round(float(v), 6)
    return f"{0.0 if v == 0 else v:.12g}"


def _val(v) -> str:
    if isinstance(v, (list, tuple)):
        return "(" + ", ".join(_num(c) for c in v) + ")"
    return _num(v)


def _span(s: dict | None) -> str:
    if not s:
        return ""
    return f"{s.get('file') or ''}:{s['line']}:{s['column']}"


def _diagnostic(d: dict) -> str:
    """One diagnostic in one line: ``error E0103 at plate.aidl:3:15: message; hint: ...; fix:
    replace 3:15-3:21 (offsets 47..53) with `Circle```."""
    said = f"{d.get('severity', 'error')} {d['code']}"
    if d.get("span"):
        said += f" at {_span(d['span'])}"
    elif d.get("line"):
        said += f" at line {d['line']}"
    said += f": {d['message']}"
    for lab in d.get("labels") or []:
        if not lab.get("primary") and lab.get("message"):
            at = "" if ", at " in lab["message"] else f" at {_span(lab.get('span'))}"
            said += f" [{lab['message']}{at}]"
    if d.get("hint"):
        said += f"; hint: {d['hint']}"
    fix = d.get("fix")
    if fix:
        sp = fix["span"]
        said += (f"; fix: replace {sp['line']}:{sp['column']}-{sp['end_line']}:"
                 f"{sp['end_column']} (offsets {sp['start']}..{sp['end']}) with "
                 f"`{fix['replacement']}`")
    return " ".join(said.split("\n"))


def body(tool: str, doc: dict) -> list[str]:
    """The lines of text after a result's first line: what its structured content holds,
    compact (issue 95: a host may show the model the text only): each diagnostic, each
    value, the description, the freedom left, each collision, the import's notes."""
    out: list[str] = [_diagnostic(d) for d in doc.get("diagnostics") or []
                      if isinstance(d, dict) and "code" in d]
    if tool == "values":
        for v in doc.get("values") or []:
            unit = f" {v['unit']}" if v.get("unit") else ""
            if v.get("kind") == "group":
                out.append(f"{v['name']} = {_val(v['value'])}{unit} ({v['count']} "
                           f"{v.get('of', 'value')}s: " + ("all equal)" if not isinstance(
                               v["value"], list) else "the range they span)"))
            else:
                out.append(f"{v['name']} = {_val(v['value'])}{unit}")
    if tool == "describe" and doc.get("text"):
        out += doc["text"].splitlines()
    f = doc.get("freedom") or {}
    if f.get("text") and f.get("dof"):
        out.append(f["text"])
    for s in f.get("structures") or []:
        out.append(f"{s['structure']}: {s['dof']} of {s['unknowns']} free"
                   + (f" ({', '.join(s['floating'])})" if s.get("floating") else ""))
    fit = doc.get("fit") or {}
    for c in fit.get("collisions") or []:
        out.append(f"collision {c['a']} / {c['b']}: {_num(c['volume'])} mm³, "
                   f"{_num(c['depth'])} mm deep")
    for c in fit.get("floating") or []:
        out.append(f"floating {c['part']}: {_num(c['gap'])} mm from {c['nearest']}")
    for c in doc.get("overlaps") or []:          # 2D, as cut (render)
        out.append(f"overlap {c['a']} / {c['b']}: {_num(c['area'])} mm²"
                   + (f" on sheet {c['sheet']}" if "sheet" in c else "") + " at "
                   + _val(c["box"]))
    for n in doc.get("notes") or []:
        out.append(f"{n['code']}: {n['message']}")
    c = doc.get("check") or {}
    out += c.get("warnings") or []
    return out


def line(tool: str, doc: dict) -> str:
    """The first line of text of a result (its :func:`body` follows it)."""
    diags = [d for d in doc.get("diagnostics") or [] if isinstance(d, dict) and "code" in d]
    if not doc.get("ok") and diags and tool != "import_drawing":     # each one follows
        n = sum(d.get("severity") == "error" for d in diags)
        return f"not ok: {_plural(n, 'error')}; {_warnings(doc)}"
    if "error" in doc and not doc.get("ok"):
        e = doc["error"]
        return f"error {e['code']}: {e['message']}"
    if not doc.get("ok", True):
        return "not ok: " + doc.get("summary", "see diagnostics")
    said = ["ok"]
    if tool in ("write_program", "set_params"):
        said = [f"wrote {doc.get('written')}", "ok" if doc.get("ok") else "not ok"]
    if tool in ("check", "render", "write_program", "set_params"):
        said.append(_parts(doc))
    if tool in ("check", "write_program", "set_params"):
        f = doc.get("freedom") or {}
        if f.get("dof") is not None:
            said.append(f"{f['dof']} degrees of freedom left")
        if "fit" in doc:
            fit = doc["fit"]
            said.append("fit: " + (f"{len(fit['collisions'])} collisions, "
                                   f"{len(fit['floating'])} floating" if fit["checked"]
                                   else "not checked (no Place)"))
    if tool == "render":
        if doc.get("written"):
            said.append(f"wrote {doc['written']}")
        if doc.get("job") and doc["job"].get("text"):
            said.append(doc["job"]["text"])
        if doc.get("layout"):
            said.append(doc["layout"]["text"])
        if "overlaps" in doc:
            n = len(doc["overlaps"])
            said.append("2D: " + (f"{_plural(n, 'pair')} of parts overlap" if n
                                  else "no parts overlap"))
    if doc.get("superseded"):
        said.append(doc["superseded"])
    if tool == "values":
        vs = doc.get("values", [])
        g = [v for v in vs if v.get("kind") == "group"]
        said.append(_plural(len(vs), "value") + (f" ({len(g)} groups of copies; "
                                                 "detail=true lists each)" if g else ""))
    if tool == "measure" and doc.get("measure"):
        m = doc["measure"]
        said.append(f"{m['a']['name']} ({m['a']['kind']}) to {m['b']['name']} "
                    f"({m['b']['kind']}): "
                    + ", ".join(f"{k} {_num(m[k])}" + (" deg" if k == "angle" else " mm")
                                for k in ("distance", "center_distance", "angle", "clearance")
                                if k in m) + (f" ({m['contact']})" if "contact" in m else "")
                    + (f", overlap_area {_num(m['overlap_area'])}" + (
                        f" +- {_num(m['overlap_area_within'])}" if "overlap_area_within" in m
                        else "") + " mm²" if "overlap_area" in m else "")
                    + ", nearest points " + " and ".join(_val(p) for p in m["points"])
                    + (", centres " + " and ".join(_val(p) for p in m["centers"])
                       if m.get("centers") else ""))
    if tool == "import_drawing" and doc.get("check"):
        c = doc["check"]
        said.append(("checked ok" if c.get("ok") else "check: " + c.get("summary", "not ok"))
                    + ("; " + _parts(c) if c.get("parts") else ""))
    if tool == "values":
        said += doc.get("unmatched") or []
    said.append(_warnings(doc))
    return "; ".join(said)
