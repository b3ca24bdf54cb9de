# Request: a pair of wooden handles for a sewn tote bag, in 6 mm birch ply. Each handle is
# a half-ellipse 200 wide x 90 tall on a straight bottom edge, its two bottom corners
# rounded R6. A fabric slot 120 x 8 mm (round ends) runs along the bottom, its lower edge
# 10 mm above the bottom edge; the hand opening above it is 100 wide x 32 tall with round
# ends, centred 48 mm up. "handmade" engraved filled in serif italic, 7 mm, on the grip
# above the hand opening.

units mm
thickness 6 mm

def handle() -> solid {
    shape = Intersect(Ellipse(center=(0, 0), rx=100, ry=90),
                      Rectangle(bottom_left=(-100, 0), width=200, height=90))
    hole fabric { s = Slot(center=(0, 10 + 4), length=120, width=8) }
    hole grip { s = Slot(center=(0, 48), length=100, width=32) }
    drawing mark {
        t = Text("handmade", position=(0, 76), size=7, font="serif:Italic", valign="middle",
                 fill=true)
    }
    Fillet(6)
}

assembly tote_handles {
    front = handle()
    back = handle()
    RightOf(back, front, gap=10)
    AlignBottom(back, front)

    assert front.shape.bb.width == 200 mm and front.shape.bb.height == 90 mm, "200 x 90"
    assert front.fabric.s.bb.width == 120 mm and front.fabric.s.bb.height == 8 mm, "fabric slot 120 x 8"
    assert front.fabric.s.bb.bottom - front.shape.bb.bottom == 10 mm, "fabric slot 10 above the bottom"
    assert front.grip.s.bb.width == 100 mm and front.grip.s.bb.height == 32 mm, "hand opening 100 x 32"
    assert front.grip.s.center.y - front.shape.bb.bottom == 48 mm, "hand opening centred 48 up"
    assert front.shape.bb.top - front.grip.s.bb.top >= 20 mm, "at least 20 mm of grip above the hand"
    assert distance(front.grip, front.fabric) >= 12 mm, "a strong bar between the slots"
    assert distance(front.mark, front.grip) >= 2 mm, "the mark clear of the opening"
    assert front.mark.bb.top <= 90 mm - 3 mm, "the mark inside the handle"
}
