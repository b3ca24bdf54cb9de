# Request: a Danish woven Christmas heart (julehjerte) laser-cut from 300 gsm card (0.4 mm),
# one half in red card and one in white. Each half is cut flat and folded in two: a strip 60 mm
# wide and 180 mm from end to end with both ends rounded (radius 30), three slits 120 mm long
# along it, 15 mm apart, centred on the fold, so each folded half has four loops 15 mm wide
# and 60 mm deep; the fold line across the middle is engraved (scored). A handle strip
# 150 x 12 mm with round ends, "GLÆDELIG JUL" engraved filled along it, 5 mm tall.

units mm
thickness 0.4 mm

W = 60 mm        # width of a half
DEPTH = 60 mm    # woven depth of each folded half
SLITS = 3
PITCH = W / (SLITS + 1)

def half() -> solid {
    strip = Slot(center=(0, 0), length=2 * DEPTH + W, width=W)
    cut slits {
        for i in range(SLITS) {
            s = Line((-DEPTH, -W / 2 + (i + 1) * PITCH), (DEPTH, -W / 2 + (i + 1) * PITCH))
        }
    }
    drawing fold {
        l = Line((0, -W / 2), (0, W / 2))
    }
}

assembly heart {
    red = half()
    white = half()
    Below(white, red, gap=8 mm)
    AlignLeft(white, red)

    solid handle {
        band = Slot(center=(0, 0), length=150, width=12)
        drawing words {
            t = Text("GLÆDELIG JUL", position=(0, 0), size=5, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }
    Below(handle, white, gap=8 mm)
    AlignCenterX(handle, white)

    assert red.strip.width == 60 mm, "60 mm wide"
    assert red.strip.length == 180 mm, "180 mm end to end"
    assert red.strip.radius == 30 mm, "ends rounded R30"
    assert len(red.slits.s) == 3, "three slits"
    assert red.slits.s[0].length == 120 mm, "slits 120 long"
    assert red.slits.s[1].start.y - red.slits.s[0].start.y == 15 mm, "15 mm apart"
    assert red.slits.s[0].start.y - red.strip.bb.bottom == 15 mm, "outer loops 15 wide"
    assert red.strip.bb.top - red.slits.s[2].start.y == 15 mm, "outer loops 15 wide"
    assert (red.slits.s[0].start.x + red.slits.s[0].end.x) / 2 == red.fold.l.start.x,
        "slits centred on the fold"
    assert handle.band.length == 150 mm and handle.band.width == 12 mm, "handle 150 x 12"
}
