# Request: for our garden party buffet, clips that hold a wine glass on the rim of a paper
# plate, so every guest has a hand free. 3 mm clear acrylic, one per guest with the guest's
# name. Each clip is an oval 84 x 64 mm with:
# - a slot 9 mm wide for the glass stem, running in from the right end along the long axis,
#   its round end 10 mm right of the oval's centre (the stem sits there, bowl above);
# - a slit 1.5 mm wide and 22 mm deep running in from the left end for the plate's rim,
#   flared to 8 mm at the mouth (5 mm long) so the rim slides in, ending in a 3 mm relief hole
#   so the acrylic doesn't crack;
# - the guest's name engraved filled (bold, 7 mm letters, at most 50 mm wide) centred 14 mm
#   above the centre, and "CHEERS" engraved (4 mm) centred 16 mm below it.
# This batch: ANNA, BEN, CLARA, DEV, EMMA, FINN, laid out 3 to a row, 5 mm apart.

units mm
thickness 3 mm

NAMES = ["ANNA", "BEN", "CLARA", "DEV", "EMMA", "FINN"]
RX = 42 mm
RY = 32 mm

def clip(name="GUEST") -> solid {
    body = Ellipse(center=(0, 0), rx=RX, ry=RY)
    hole stem {
        s = Slot(start=(10, 0), end=(RX + 6, 0), width=9)
    }
    hole rim_slit {
        slit = Rectangle(corner=(-RX - 1, -0.75), opposite=(-RX + 22, 0.75))
        mouth = Polygon([(-RX - 1, 4), (-RX + 5, 0.75), (-RX + 5, -0.75), (-RX - 1, -4)])
        relief = Circle(center=(-RX + 22, 0), diameter=3)
    }
    drawing label {
        who = Text(name, position=(0, 14), size=7, font="sans:Bold", valign="middle",
                   max_width=50, fill=true)
        toast = Text("CHEERS", position=(0, -16), size=4, valign="middle")
    }
}

assembly party_clips {
    for i in range(len(NAMES)) {
        c = clip(name=NAMES[i])
    }
    # on the sheet: 3 to a row
    for i in range(1, len(NAMES)) {
        if i % 3 == 0 {
            Below(c[i].body, c[i - 3].body, gap=5)
            AlignCenterX(c[i].body, c[i - 3].body)
        } else {
            RightOf(c[i].body, c[i - 1].body, gap=5)
            AlignCenterY(c[i].body, c[i - 1].body)
        }
    }

    # the request's numbers
    assert len(c) == 6, "six guests"
    assert c[0].body.bb.width == 84 mm and c[0].body.bb.height == 64 mm, "oval 84 x 64"
    assert c[0].stem.s.width == 9 mm, "stem slot 9 wide"
    assert c[0].stem.s.start.x - c[0].body.center.x == 10 mm, "stem seat 10 right of centre"
    assert c[0].rim_slit.slit.bb.height == 1.5 mm, "slit 1.5 wide"
    assert c[0].rim_slit.relief.center.x - c[0].body.bb.left == 22 mm, "slit 22 deep"
    assert c[0].rim_slit.mouth.bb.height == 8 mm, "mouth flared to 8"
    assert c[0].rim_slit.relief.diameter == 3 mm, "3 mm relief hole"
    assert c[0].label.who.position.y - c[0].body.center.y == 14 mm, "name 14 above centre"
    assert c[0].body.center.y - c[0].label.toast.position.y == 16 mm, "CHEERS 16 below centre"
}
