# Kitchen utensil crock: an open-top finger-jointed box 100 x 100 x 150 mm (outside),
# 3 mm plywood, 10 mm fingers; "COOK" in sans Bold 20 mm engraved (filled) on the
# front, centered 90 mm above the front's bottom edge; four 6 mm drain holes in the
# bottom, 25 mm from its centre along the diagonals.
import "std/joints.aidl"

thickness 3 mm

param size = 100 mm, min = 70 mm, max = 160 mm
param tall = 150 mm, min = 100 mm, max = 220 mm

assembly crock {
    box = finger_box(length=size, depth=size, height=tall, thickness=3 mm, finger=10 mm,
                     closed=false)

    drawing word {
        t = Text("COOK", (0, 0), size=20, font="sans:Bold", fill=true, valign="middle")
    }
    AlignCenterX(word, box.front)
    word.t.position.y == box.front.bb.bottom + 90 mm
    CutInto(word, box.front)

    hole drain {
        c = Circle(center=(0, 0), diameter=6)
    }
    drains = CircularPattern(drain, 4, box.bottom.outline.center)
    Coincident(drain.c.center, polar(box.bottom.outline.center, 25 mm, 45 deg))
    CutInto(drain, box.bottom)

    assert box.front.bb.width == 100 mm, "front 100 wide"
    assert box.front.bb.height == 150 mm, "front 150 tall"
    assert box.bottom.bb.width == 100 mm, "bottom 100 wide"
    assert len(drains) == 4, "four drain holes"
    assert drain.c.diameter == 6 mm, "6 mm drains"
}
