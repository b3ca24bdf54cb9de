"""W0508 on a design exactly as meant (issue 111, the second fresh-model run's mirror frame):
a round frame cut as two halves, each half made by a rectangle hole that trims the ring along
its diameter, locked by two `dovetail` joints whose cuts span the ring's width.  Eight W0508s
("overlap ... so they cut one opening, not two"): two for the ring's opening halved by the
trim, six for the joints' 1 mm overruns meeting the opening or the trim.  A model accepted
them with `AllowOverlap`; their hints' moves would have left each half three quarters of a
ring.  Now a trim of the outline (a hole at least half off the part that cuts at least a
quarter of it) and an overlap that lies wholly in a template's `overrun=true` shapes are the
design, and what W0508 is for stays: a notch mostly on the part that bites a screw hole, a
joint's own cut (not its overrun) across a hole."""
from __future__ import annotations

import aidl_lang

FRAME = """import "std/joints.aidl"
units mm
thickness 6 mm
param outer_d = 200 mm
param inner_d = 150 mm
param dt_depth = 8 mm
assembly frame {
    solid top {
        disc = Circle(center=(0, 0), diameter=outer_d)
        hole opening { c = Circle(center=(0, 0), diameter=inner_d) }
        hole lower { r = Rectangle(bottom_left=(-outer_d, -outer_d - dt_depth), width=2 * outer_d, height=outer_d) }
        left_tail = dovetail(part="tail", length=(outer_d - inner_d) / 2, depth=dt_depth, tails=1,
                             angle=10 deg, clearance=0.1 mm, rotation=180 deg,
                             cx=-(outer_d + inner_d) / 4, cy=0 mm)
        right_tail = dovetail(part="tail", length=(outer_d - inner_d) / 2, depth=dt_depth, tails=1,
                              angle=10 deg, clearance=0.1 mm, rotation=180 deg,
                              cx=(outer_d + inner_d) / 4, cy=0 mm)
    }
    solid bottom {
        disc = Circle(center=(0, 0), diameter=outer_d)
        hole opening { c = Circle(center=(0, 0), diameter=inner_d) }
        hole upper { r = Rectangle(bottom_left=(-outer_d, 0), width=2 * outer_d, height=outer_d) }
        left_socket = dovetail(part="socket", length=(outer_d - inner_d) / 2, depth=dt_depth, tails=1,
                               angle=10 deg, clearance=0.1 mm, rotation=180 deg,
                               cx=-(outer_d + inner_d) / 4, cy=0 mm)
        right_socket = dovetail(part="socket", length=(outer_d - inner_d) / 2, depth=dt_depth, tails=1,
                                angle=10 deg, clearance=0.1 mm, rotation=180 deg,
                                cx=(outer_d + inner_d) / 4, cy=0 mm)
    }
    top.disc.center.y - bottom.disc.center.y == dt_depth + 10 mm
    AlignCenterX(bottom.disc, top.disc)
}
"""


def _codes(src):
    r = aidl_lang.compile(source=src)
    assert r.ok, [d.message for d in r.diagnostics]
    return r, [(d.code, d.message) for d in r.diagnostics if d.severity == "warning"]


def test_the_mirror_frame_is_as_meant():
    r, warned = _codes(FRAME)
    assert warned == []
    # the halves are what was drawn: a half ring 200/150 mm (6,872.234 mm^2) with its two
    # tails (each 25 mm wide at half its 8 mm depth: 100 mm^2) on top, less its two sockets
    # (0.1 mm wider: 100.8 mm^2) below
    half = 3.141592653589793 * (100 ** 2 - 75 ** 2) / 2
    areas = {p.name: p.area for p in r.output.parts}
    assert abs(areas["frame.top"] - (half + 200)) < 1e-3, areas
    assert abs(areas["frame.bottom"] - (half - 201.6)) < 1e-3, areas


def test_a_notch_that_bites_a_screw_hole_is_still_W0508():
    src = """units mm
solid plate {
    body = Rectangle(center=(0, 0), width=100, height=60)
    hole notch { r = Rectangle(center=(0, 27), width=20, height=10) }
    hole screw { c = Circle(center=(8, 20), radius=3) }
}
"""
    _, warned = _codes(src)
    assert [c for c, _ in warned].count("W0508") == 1, warned


def test_a_joints_own_cut_across_a_hole_is_still_W0508():
    # the socket's cut (not its overrun) runs over a 6 mm hole placed at its middle
    src = """import "std/joints.aidl"
units mm
solid plate {
    body = Rectangle(center=(0, 0), width=100, height=60)
    hole pin { c = Circle(center=(12, 22), radius=3) }
    j = dovetail(part="socket", length=40 mm, depth=10 mm, tails=1, rotation=180 deg, cx=0 mm, cy=30 mm)
}
"""
    _, warned = _codes(src)
    assert [c for c, _ in warned].count("W0508") == 1, warned


def test_a_trim_that_covers_only_an_edge_bite_is_no_trim():
    # a 20 mm circle hole mostly off the plate bites 2 mm into its edge and a screw hole:
    # it cuts far less than a quarter of the plate, so it is no trim: W0508 as before
    src = """units mm
solid plate {
    body = Rectangle(center=(0, 0), width=100, height=60)
    hole bite { c = Circle(center=(0, 38), radius=10) }
    hole screw { c = Circle(center=(0, 27), radius=2) }
}
"""
    _, warned = _codes(src)
    assert [c for c, _ in warned].count("W0508") == 1, warned


def test_W0504_says_how_far_two_pieces_are_and_where():
    """Issue 111's third run: a star 0.3 mm clear of a tree's top tier (their boxes overlap,
    so no side relation could be named) got only "for example `Above(a, b, gap=-1 mm)`".  The
    hint now says how far apart the two pieces are at their nearest and where: a circle of
    radius 4 at (23, 14) is 1 mm from a 40 x 20 plate's corner (20, 10), the middle of that
    span at (20.3, 10.4), to the circle's chords (within 0.01 mm)."""
    import re
    src = """units mm
solid plate {
    body = Rectangle(center=(0, 0), width=40, height=20)
    knob = Circle(center=(23, 14), radius=4)
}
"""
    r = aidl_lang.compile(source=src)
    (d,) = [d for d in r.diagnostics if d.code == "W0504"]
    m = re.match(r"the two pieces are ([\d.]+) mm apart at their nearest, near "
                 r"\(([-\d.]+), ([-\d.]+)\): make the pieces overlap", d.hint)
    assert m, d.hint
    gap, x, y = map(float, m.groups())
    assert abs(gap - 1.0) <= 0.01 and abs(x - 20.3) <= 0.01 and abs(y - 10.4) <= 0.01
