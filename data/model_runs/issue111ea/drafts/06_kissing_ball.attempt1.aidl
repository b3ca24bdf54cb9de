# Request (holidays): a mistletoe kissing ball, 3 mm ply: two rings 200 mm across, 18 mm
# wide, crossed at right angles by half-width halvings (0.15 mm clearance) so that they
# slide together along the vertical axis: ring A has its slot from the inner edge at the top
# and from the outer edge at the bottom, ring B from the outer edge at the top and from the
# inner edge at the bottom, each 9 mm deep. A round lug (R7) on top of ring A with a 4 mm
# ribbon hole, and one under ring B with a 4 mm hole for the mistletoe bunch's wire. Ring A
# engraved "MERRY CHRISTMAS" over its top, ring B "UNDER THE MISTLETOE" under its bottom
# (readable), both 6 mm single-stroke letters on the outer half of the ring.

import "std/joints.aidl"

thickness 3 mm

ply = 3 mm
r_out = 100 mm
band = 18 mm
r_in = r_out - band
depth = band / 2
fit = 0.15 mm
lug_r = 7 mm
text_r = r_out - 5 mm

def ring(top_inner=true, lug_up=true, words="", under=false) -> solid {
    rim = Circle(center=(0, 0), radius=r_out)
    hole bore { c = Circle(center=(0, 0), radius=r_in) }
    solid lug {
        boss = Circle(center=(0, (r_out + 3 mm) if lug_up else -(r_out + 3 mm)),
                      radius=lug_r)
        hole eye {
            c = Circle(center=(0, (r_out + 4 mm) if lug_up else -(r_out + 4 mm)),
                       diameter=4)
        }
    }
    # top: from the inner edge up, or from the outer edge down; the bottom the other way
    if top_inner {
        top_cut = cross_halving(depth=depth, thickness=ply, clearance=fit,
                                rotation=180 deg, cx=0 mm, cy=r_in)
        bot_cut = cross_halving(depth=depth, thickness=ply, clearance=fit,
                                rotation=180 deg, cx=0 mm, cy=-r_out)
    } else {
        top_cut = cross_halving(depth=depth, thickness=ply, clearance=fit, cx=0 mm,
                                cy=r_out)
        bot_cut = cross_halving(depth=depth, thickness=ply, clearance=fit, cx=0 mm,
                                cy=-r_in)
    }
    drawing label {
        path = Circle(center=(0, 0), radius=text_r, construction=true)
        t = Text(words, along=path, size=6, valign="middle", flip=under)
    }
}

assembly kissing_ball {
    ring_a = ring(top_inner=true, lug_up=true, words="MERRY CHRISTMAS", under=false)
    ring_b = ring(top_inner=false, lug_up=false, words="UNDER THE MISTLETOE", under=true)

    RightOf(ring_b, ring_a, gap=10)
    AlignCenterY(ring_b.rim, ring_a.rim)

    # 3D: A in the x-z plane, B in the y-z plane, crossing on the vertical axis
    Place(ring_a, position=(0, ply / 2, 0), face="front", up="up")
    Place(ring_b, position=(-ply / 2, 0, 0), face="right", up="up")

    assert ring_a.rim.diameter == 200 mm, "rings 200 across"
    assert ring_a.rim.radius - ring_a.bore.c.radius == 18 mm, "rings 18 wide"
    assert ring_a.top_cut.cut.bb.height == 9 mm, "halvings 9 deep"
    assert ring_a.top_cut.cut.bb.width == 3 mm + 0.15 mm, "0.15 clearance"
    assert ring_a.top_cut.cut.bb.bottom == ring_a.bore.c.center.y + r_in,
        "A: top slot from the inner edge"
    assert ring_b.top_cut.cut.bb.top == ring_b.rim.center.y + r_out,
        "B: top slot from the outer edge"
    assert ring_a.lug.boss.radius == 7 mm, "R7 lugs"
    assert ring_a.lug.eye.c.diameter == 4 mm and ring_b.lug.eye.c.diameter == 4 mm,
        "4 mm holes"
    assert ring_a.label.t.size == 6 mm, "6 mm letters"
    assert distance(ring_a.label, ring_a.top_cut) >= 1 mm, "words clear of the slot"
    assert distance(ring_b.label, ring_b.bot_cut) >= 1 mm, "words clear of the slot"
    assert distance(ring_b.label, ring_b.lug.eye) >= 1 mm, "words clear of the wire hole"
}
