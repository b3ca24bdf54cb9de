"""Issue 61 ("what models and makers reach for, round three"): each finding as the real
program a model or a maker wrote, through the real parser, solver and outputs."""
from __future__ import annotations

import contextlib
import io

import numpy as np

from aidl_lang.api import compile as aidl_compile
from aidl_lang.cli.main import main


def run_cli(*args):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main([str(a) for a in args])
    return rc, out.getvalue(), err.getvalue()


def checked(src: str, path: str = "/tmp/aidl-issue61.aidl"):
    r = aidl_compile(src, path=path)
    r.find_redundant(seconds=None, max_rows=None)
    return r


# ------------------------------------------------------------ the docs' own examples warn
def test_a_point_shape_in_a_constraint_is_seen_from_the_constraints_structure():
    """`Coincident(teeth_ring.axis, hub.center)` (a `Point` of a child beside a point of the
    structure itself) tied the child's frame to nothing: the Point was seen from the model
    frame, the other point from the structure's, so moving the gear and its teeth ring
    oppositely changed no row (W0404 on `spur_gear`'s own teeth_ring).  The row now reads
    the child frame alone."""
    src = """solid part {
    solid p {
        hub = Circle(center=(0, 0), radius=10)
        Fixed(hub.center)
        solid ring {
            axis = Point(0, 0)
            Fixed(axis)
            r = Circle(center=(0, 0), radius=14)
            Fixed(r)
        }
        Coincident(ring.axis, hub.center)
    }
}
"""
    r = checked(src)
    assert not r.sink.items, [d.message for d in r.sink.items]
    m = r.compiled.model
    ring = next(t for t in m.structures if t.path == "part.p.ring")
    p = next(t for t in m.structures if t.path == "part.p")
    rows = [e for c in m.constraints if c.describe().startswith("Coincident")
            for e in c.equations]
    terms = set().union(*(e.expr.terms for e in rows))
    assert ring.fx in terms and ring.fy in terms
    assert p.fx not in terms and p.fy not in terms and 0 not in terms     # no outer frames
    # and the solve keeps the ring on the hub when the gear is moved
    r2 = checked(src.replace("Fixed(hub.center)", "hub.center == (30, 7)"))
    v = {x.name: x.value for x in r2.values}
    assert np.allclose(v["part.p.ring.r.center"], (30, 7), atol=1e-9)


def test_stdlib_locations_read_std_not_the_install_path():
    src = 'import "std/gears.aidl"\nsolid part {\n    p = spur_gear(teeth=12, module=1 mm, bore=30 mm)\n}\n'
    rc, _, err = run_cli("check", _write(src, "bore"))
    assert rc == 1
    assert "std/gears.aidl:32:5: error[E0405]" in err, err
    assert "/stdlib/" not in err and "site-packages" not in err


def _write(src: str, name: str) -> str:
    import tempfile
    import os
    d = tempfile.mkdtemp(prefix="aidl-issue61-")
    p = os.path.join(d, f"{name}.aidl")
    with open(p, "w", encoding="utf-8") as f:
        f.write(src)
    return p


def test_a_redundancy_against_a_templates_own_fixed_blames_the_users_line_only():
    """`CenterInside(h, body)` beside `cross_halving`'s own `Fixed(self)`: one W0401, on the
    user's line, whose hint says the template holds it and names no template line to drop."""
    src = """import "std/joints.aidl"

solid plate {
    body = Rectangle(center=(0, 0), width=120, height=120)
    h = cross_halving()
    Fixed(body)
    CenterInside(h, body)
}
"""
    r = checked(src)
    ws = [d for d in r.sink.items if d.code == "W0401"]
    assert len(ws) == 1, [d.message for d in r.sink.items]
    w = ws[0]
    assert w.span.line == 7 and "1 of the 4 can go" in w.message
    assert w.hint.startswith("drop `CenterInside(h, body)` (line 7): the template holds it")
    assert "std/joints.aidl line 136" in w.hint
    assert "drop `Fixed(self)`" not in w.hint and "drop `Fixed(cut)`" not in w.hint


def test_a_part_placed_by_a_template_names_the_file_that_places_it():
    src = """import "std/gears.aidl"
thickness 3 mm
assembly kit {
    t = gear_train(teeth=[12, 24])
    Place(t.gear[0], position=(0, 0, 10))
}
"""
    r = aidl_compile(src, path="/tmp/aidl-issue61-place.aidl")
    e = next(d for d in r.sink.items if d.code == "E0108")
    assert "already placed, in std/gears.aidl line" in e.message, e.message


# ------------------------------------------------------------ Mirrored of a list
def test_mirrored_of_a_list_is_the_list_of_the_mirror_images():
    """`Mirrored(legs, axis)` (a list a loop made, or written) was E0108 "got list"; now each
    item is mirrored, and the result is their images in order (`m[1]` is item 1's)."""
    src = """solid plate {
    body = Rectangle(center=(0, 0), width=80, height=40)
    axis = Line((0, -20), (0, 20), construction=true)
    Fixed(body)
    hole h {
        a = Circle(center=(-30, 10), radius=2)
        b = Circle(center=(-20, -10), radius=3)
        Fixed(a)
        Fixed(b)
    }
    Fixed(h)
    for i in range(2) {
        hole k { c = Circle(center=(-10 + 3 * i, 0), radius=1) }
        Fixed(k)
    }
    m = Mirrored([h.a, h.b], axis)
    n = Mirrored(k, axis)
    assert m[1].center == (20, -10) and m[0].radius == 2
    assert n[1].c.center == (7, 0)
}
"""
    r = checked(src)
    assert r.ok and not r.sink.items, [d.message for d in r.sink.items]
    got = sorted((o["center"][0], o["center"][1], o["d"])
                 for o in r.description["parts"][0]["openings"])
    assert got == sorted([(-30, 10, 4), (30, 10, 4), (-20, -10, 6), (20, -10, 6),
                          (-10, 0, 2), (10, 0, 2), (-7, 0, 2), (7, 0, 2)])
    bad = aidl_compile(src.replace("Mirrored(k, axis)", "Mirrored([h, 3], axis)"),
                       path="/tmp/aidl-issue61-m.aidl")
    (e,) = [d for d in bad.sink.items if d.is_error][:1]
    assert e.code == "E0108" and "list holds a number" in e.message, e.message
