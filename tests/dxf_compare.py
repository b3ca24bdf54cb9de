"""An independent reader for round-trip tests: a DXF file's curves as canonical tuples,
read with ezdxf alone (polylines exploded into their lines and arcs), and a matcher to 1e-9 mm."""
from __future__ import annotations

import math

import ezdxf

TOL = 1e-9


def _pt(v):
    return (float(v[0]), float(v[1]))


def _order(pts):
    """Points in an order that a 1e-9 mm change cannot flip."""
    return sorted(pts, key=lambda p: (round(p[0], 6), round(p[1], 6)))


def _key(kind, pts, extra=()):
    return (kind, tuple(pts), tuple(extra))


def curves(path) -> list[tuple]:
    """``(kind, points, numbers)`` of every curve of the DXF at ``path``: a LINE's two ends
    (sorted), an ARC's centre, its two ends (sorted) and radius, a CIRCLE's centre and radius,
    a SPLINE's control points (in the direction that sorts first; a chain of cubic Béziers,
    as AIDL writes them, one item per segment); polylines are exploded."""
    doc = ezdxf.readfile(str(path))
    out = []
    todo = list(doc.modelspace())
    while todo:
        e = todo.pop()
        t = e.dxftype()
        if t in ("LWPOLYLINE", "POLYLINE"):
            todo += list(e.virtual_entities())
        elif t == "LINE":
            out.append(_key("L", _order([_pt(e.dxf.start), _pt(e.dxf.end)])))
        elif t == "ARC":
            c, r = _pt(e.dxf.center), float(e.dxf.radius)
            ends = []
            for a in (e.dxf.start_angle, e.dxf.end_angle):
                a = math.radians(a)
                ends.append((c[0] + r * math.cos(a), c[1] + r * math.sin(a)))
            out.append(_key("A", [c] + _order(ends), [r]))
        elif t == "CIRCLE":
            out.append(_key("C", [_pt(e.dxf.center)], [float(e.dxf.radius)]))
        elif t == "ELLIPSE":
            # centre, the ends of the major axis (sorted: either sign is the same ellipse),
            # the arc's ends (sorted) and its middle (which way round), and the ratio
            c = _pt(e.dxf.center)
            m = _pt(e.dxf.major_axis)
            s0, s1 = float(e.dxf.start_param), float(e.dxf.end_param)
            span = (s1 - s0) % (2 * math.pi) or 2 * math.pi
            ct = e.construction_tool()
            ends = [_pt(v) for v in ct.vertices([s0, s1])]
            mid = _pt(next(iter(ct.vertices([s0 + span / 2]))))
            out.append(_key("E", [c] + _order([(c[0] + m[0], c[1] + m[1]),
                                               (c[0] - m[0], c[1] - m[1])])
                            + _order(ends) + [mid], [float(e.dxf.ratio)]))
        elif t == "SPLINE":
            cp = [_pt(p) for p in e.control_points]
            for piece in _bezier_pieces(e, cp):
                out.append(_key("S", piece if _order([piece[0], piece[-1]])[0] == piece[0]
                                else piece[::-1]))
    return out


def _bezier_pieces(e, cp: list) -> list[list]:
    """A degree-3 clamped SPLINE whose interior knots are each tripled is a chain of cubic
    Béziers (one per knot span, control points ``cp[3 i : 3 i + 4]``): its segments, so that
    the same curve written as one entity or as several compares equal; any other SPLINE
    whole."""
    knots = [float(k) for k in e.knots]
    if int(e.dxf.degree) != 3 or len(cp) < 4 or (len(cp) - 1) % 3 or \
            len(knots) != len(cp) + 4:
        return [cp]
    inner = knots[4:-4]
    if knots[:4] != [knots[0]] * 4 or knots[-4:] != [knots[-1]] * 4 or \
            any(inner[i] != inner[i + 1] or inner[i] != inner[i + 2]
                for i in range(0, len(inner), 3)):
        return [cp]
    return [cp[i:i + 4] for i in range(0, len(cp) - 1, 3)]


def merge_arcs(items: list) -> list:
    """The arcs of ``items`` on one circle that meet end to end joined into one (a writer may
    cut an arc over 180 degrees in two at any point): ends rounded to 1e-7 mm to pair them."""
    arcs = [x for x in items if x[0] == "A"]
    rest = [x for x in items if x[0] != "A"]
    changed = True
    while changed:
        changed = False
        for i, a in enumerate(arcs):
            for j, b in enumerate(arcs):
                if i == j or math.dist(a[1][0], b[1][0]) > TOL or abs(a[2][0] - b[2][0]) > TOL:
                    continue
                ea, eb = list(a[1][1:]), list(b[1][1:])
                for p in ea:
                    for q in eb:
                        if math.dist(p, q) <= TOL:
                            o1 = ea[1] if p is ea[0] else ea[0]
                            o2 = eb[1] if q is eb[0] else eb[0]
                            if math.dist(o1, o2) <= TOL:
                                continue          # two halves of a circle: leave them
                            arcs[i] = ("A", tuple([a[1][0]] + _order([o1, o2])), a[2])
                            arcs.pop(j)
                            changed = True
                            break
                    if changed:
                        break
                if changed:
                    break
            if changed:
                break
    return rest + arcs


def _close(a, b) -> bool:
    if a[0] != b[0] or len(a[1]) != len(b[1]) or len(a[2]) != len(b[2]):
        return False
    return (all(math.dist(p, q) <= TOL for p, q in zip(a[1], b[1]))
            and all(abs(x - y) <= TOL for x, y in zip(a[2], b[2])))


def unmatched(a: list, b: list) -> tuple[list, list]:
    """The curves of ``a`` with no partner in ``b`` within 1e-9 mm, and those of ``b`` left."""
    rest = sorted(merge_arcs(b))
    left = []
    for x in sorted(merge_arcs(a)):
        for i, y in enumerate(rest):
            if _close(x, y):
                rest.pop(i)
                break
        else:
            left.append(x)
    return left, rest
