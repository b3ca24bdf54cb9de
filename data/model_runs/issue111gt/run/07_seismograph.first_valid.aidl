# Request (science): a classroom seismograph, 6 mm ply.
# - Base 300 x 160 mm, 6 mm corners. Two uprights 60 mm wide standing 250 mm above the base,
#   200 mm apart centre to centre, each on one 24 mm glued tenon into the base.
# - A beam 260 x 40 mm standing on edge across the uprights' tops, held by cross halvings
#   (20 mm into each), its top flush with theirs; a 3 mm hole for the pendulum's string in
#   its middle 10 mm below its top, and "SEISMOGRAPH" engraved (10 mm letters) under it.
# - The bob: three 80 mm discs glued up, a 12.5 mm hole in the middle for a marker pen and
#   three 3 mm holes on a 30 mm radius for the string's bridle.
# - Two paper guides 8 x 160 mm glued on the base either side of a 57 mm till roll strip,
#   1 mm clear of it each side, the strip running front to back under the pen.

import "std/joints.aidl"

t = 6 mm
thickness t

# drawn with the base's top face at y = 0: the tenon reaches down to y = -6
def upright() -> solid {
    body = Rectangle(center=(0, 122), width=60, height=256)
    tenon = tab_and_slot(part="tab", length=60 mm, thickness=t, tabs=1, tab=24 mm, screw=0,
                         rotation=180 deg, cx=0 mm, cy=-6 mm)
    half = cross_halving(depth=20 mm, thickness=t, cx=0 mm, cy=250 mm)
}

def bob_disc() -> solid {
    disc = Circle(center=(0, 0), diameter=80)
    hole pen { c = Circle(center=(0, 0), diameter=12.5) }
    hole bridle {
        for k in range(3) {
            c = Circle(center=(30 * cos(90 deg + k * 120 deg), 30 * sin(90 deg + k * 120 deg)),
                       diameter=3)
        }
    }
}

assembly seismograph {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=300, height=160, corner_radius=6)
        for i in range(2) {
            m = tab_and_slot(part="slot", length=60 mm, thickness=t, tabs=1, tab=24 mm, screw=0,
                             rotation=90 deg, cx=(2 * i - 1) * 100 mm, cy=0 mm)
        }
    }

    # drawn with its top at y = 20
    solid beam {
        body = Rectangle(center=(0, 0), width=260, height=40)
        for i in range(2) {
            h = cross_halving(depth=20 mm, thickness=t, rotation=180 deg,
                              cx=(2 * i - 1) * 100 mm, cy=-20 mm)
        }
        hole string { c = Circle(center=(0, 10), diameter=3) }
        drawing label {
            word = Text("SEISMOGRAPH", position=(0, -8), size=10, valign="middle")
        }
    }

    for i in range(2) {
        side = upright()
        Place(side, position=((2 * i - 1) * 100 mm - t / 2, 0, t), face="right", up="up")
        solid guide { g = Rectangle(center=(0, 0), width=8, height=160) }
        Place(guide, position=((2 * i - 1) * 33.5 mm, 0, t))
    }
    for k in range(3) {
        bob = bob_disc()
        Place(bob, position=(0, 0, 40 mm + k * t))
    }
    Place(base, position=(0, 0, 0))
    # beam top at 6 + 250 = 256: its middle at 236, its faces at y = -3 and 3
    Place(beam, position=(0, t / 2, 236 mm), face="front", up="up")

    # flat layout for cutting
    RightOf(side[0], base, gap=6 mm)
    AlignTop(side[0], base)
    RightOf(side[1], side[0], gap=6 mm)
    AlignTop(side[1], base)
    RightOf(guide[0], side[1], gap=6 mm)
    AlignTop(guide[0], base)
    RightOf(guide[1], guide[0], gap=6 mm)
    AlignTop(guide[1], base)
    Below(beam, base, gap=6 mm)
    AlignLeft(beam, base)
    Below(bob[0], beam, gap=6 mm)
    AlignLeft(bob[0], base)
    for k in range(1, 3) {
        RightOf(bob[k], bob[k - 1], gap=6 mm)
        AlignTop(bob[k], bob[0])
    }

    # the request's numbers
    assert base.body.width == 300 mm and base.body.height == 160 mm, "base 300 x 160"
    assert side[0].body.width == 60 mm and side[0].body.height - t == 250 mm, "uprights 60 wide, 250 up"
    assert base.m[1].slot[0].bb.center_x - base.m[0].slot[0].bb.center_x == 200 mm, "200 apart"
    assert base.m[0].slot[0].bb.height == 24 mm, "24 mm tenons"
    assert beam.body.width == 260 mm and beam.body.height == 40 mm, "beam 260 x 40"
    assert beam.h[1].cut.bb.center_x - beam.h[0].cut.bb.center_x == 200 mm, "halvings 200 apart"
    assert side[0].half.cut.bb.height == 20 mm and beam.h[0].cut.bb.height == 20 mm, "20 mm each"
    assert side[0].half.cut.bb.height + beam.h[0].cut.bb.height == beam.body.height,
        "the halvings meet: the beam's top flush with the uprights'"
    assert beam.body.bb.top - beam.string.c.center.y == 10 mm, "string hole 10 below the top"
    assert distance(beam.label, beam.string) >= 2 mm, "label under the string hole"
    assert distance(beam.label, beam.h[0]) >= 3 mm and distance(beam.label, beam.h[1]) >= 3 mm,
        "label clear of the halvings"
    assert len(bob) == 3 and bob[0].disc.diameter == 80 mm, "three 80 mm discs"
    assert bob[0].pen.c.diameter == 12.5 mm, "pen hole"
    assert abs(distance(bob[0].bridle.c[0].center, bob[0].disc.center) - 30 mm) < 0.01 mm,
        "bridle on 30 mm"
    assert 2 * 33.5 mm - 8 mm == 57 mm + 2 * 1 mm, "guides 1 mm clear of the 57 mm strip"
    assert 33.5 mm + 4 mm < 100 mm - 24 mm / 2, "guides clear of the uprights' mortises"
}
