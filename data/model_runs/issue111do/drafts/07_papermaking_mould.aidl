# Request: a mould and deckle for making A5 sheets of paper, cut from 6 mm ply (to be
# varnished). Every frame is 190 x 290 mm outside with R8 corners and has a 70 x 22 mm
# hand slot centred 127 mm from the middle at each short end, and four 6.3 mm holes for
# 6 mm dowel pins (centred 84.5 mm either side and 95 mm up and down from the middle) that
# keep the deckle in register on the mould. The mould is two frames with the mesh glued
# between them: the top one has one A5 opening 148 x 210 mm (R3 corners); the bottom one
# has the same opening split into 3 windows by two 10 mm ribs that hold the mesh flat. The
# deckle is two frames with the single A5 opening glued together. Each frame's name is
# engraved (single stroke, 6 mm) along its right side.

units mm
thickness 6 mm

opening_w = 148 mm
opening_h = 210 mm
rib = 10 mm

def frame(windows=1, name="MOULD") -> solid {
    outer = RoundedRectangle(center=(0, 0), width=190, height=290, corner_radius=8)
    hole opening {
        for i in range(windows) {
            w = RoundedRectangle(center=(0, -opening_h / 2 + (opening_h - (windows - 1) * rib) / windows / 2
                                        + i * ((opening_h - (windows - 1) * rib) / windows + rib)),
                                 width=opening_w,
                                 height=(opening_h - (windows - 1) * rib) / windows,
                                 corner_radius=3)
        }
    }
    hole hands {
        top = Slot(center=(0, 127), length=70, width=22)
        bottom = Slot(center=(0, -127), length=70, width=22)
    }
    hole pin { c = Circle(center=(-84.5, -95), diameter=6.3) }
    pins = CornerPattern(pin, at=[(-84.5, -95), (84.5, -95), (84.5, 95), (-84.5, 95)])
    drawing label {
        t = Text(name, position=(84.5, 0), size=6, rotation=90 deg, valign="middle")
    }
}

assembly mould_and_deckle {
    mould_bottom = frame(windows=3, name="MOULD - BOTTOM")
    mould_top = frame(windows=1, name="MOULD - TOP, MESH UNDER")
    deckle_lower = frame(windows=1, name="DECKLE")
    deckle_upper = frame(windows=1, name="DECKLE")

    # flat layout: a row
    RightOf(mould_top, mould_bottom, gap=10)
    AlignTop(mould_top, mould_bottom)
    RightOf(deckle_lower, mould_top, gap=10)
    AlignTop(deckle_lower, mould_bottom)
    RightOf(deckle_upper, deckle_lower, gap=10)
    AlignTop(deckle_upper, mould_bottom)

    # 3D: stacked, the deckle on the mould
    Place(mould_bottom, position=(0, 0, 0), face="up")
    Place(mould_top, position=(0, 0, 6), face="up")
    Place(deckle_lower, position=(0, 0, 12), face="up")
    Place(deckle_upper, position=(0, 0, 18), face="up")

    # the request's numbers
    assert mould_top.outer.width == 190 mm and mould_top.outer.height == 290 mm, "190 x 290"
    assert mould_top.opening.w[0].width == 148 mm and mould_top.opening.w[0].height == 210 mm, "A5 opening"
    assert len(mould_bottom.opening.w) == 3, "3 windows"
    assert mould_bottom.opening.w[1].bb.bottom - mould_bottom.opening.w[0].bb.top == 10 mm, "10 mm ribs"
    assert mould_bottom.opening.bb.height == 210 mm, "windows span the A5 opening"
    assert len(mould_top.pins) == 4, "4 dowels"
    assert mould_top.hands.top.length == 70 mm and mould_top.hands.top.width == 22 mm, "hand slots 70 x 22"
    # margins stay wide enough to hold the pins and the slots
    assert mould_top.hands.top.bb.bottom - mould_top.opening.bb.top >= 8 mm, "web under the hand slot"
    assert mould_top.outer.bb.top - mould_top.hands.top.bb.top >= 6 mm, "web over the hand slot"
    assert mould_top.pins[0].c.bb.left - mould_top.outer.bb.left >= 5 mm, "pins off the edge"
    assert mould_top.opening.bb.left - mould_top.pins[0].c.bb.right >= 5 mm, "pins off the opening"
}
