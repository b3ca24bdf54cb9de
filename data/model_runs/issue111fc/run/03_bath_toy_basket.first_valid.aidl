# Request: a wall-hung bath toy basket in 3 mm clear acrylic (it lives wet).
# An open-top finger-jointed box 240 long x 120 deep x 140 tall outside, 15 mm
# fingers. The bottom drains through 24 holes of 8 mm, 3 rows x 8 columns at
# 25 mm pitch, centred. The front has seven upright 70 x 10 mm slots at 25 mm
# pitch, centred 5 mm below its middle, so toys drip dry and can be seen, and
# "BATH TOYS" engraved (filled sans bold, 12 mm capitals) centred above them with
# its baseline 45 mm above the front's middle. The back hangs on two screws
# through keyholes (9 mm head, 4.5 mm slot 10 mm long, upwards) 120 mm apart,
# their heads 35 mm above the back's middle.

units mm
thickness 3 mm
import "std/joints.aidl"
import "std/plates.aidl"

assembly bath_toy_basket {
    box = finger_box(length=240 mm, depth=120 mm, height=140 mm, thickness=3 mm, finger=15 mm,
                     closed=false)

    # drain holes in the bottom
    hole drain { c = Circle(center=(0, 0), diameter=8) }
    drains = GridPattern(drain, 3, 8, (25, 25))
    At(drain.c.center, box.bottom.bb.center, dx=-3.5 * 25 mm, dy=-25 mm)
    CutInto(drain, box.bottom)

    # upright slots in the front
    hole vent { s = Slot(center=(0, 0), length=70, width=10, rotation=90 deg) }
    vents = LinearPattern(vent, 7, (25, 0))
    At(vent.s.center, box.front.bb.center, dx=-3 * 25 mm, dy=-5 mm)
    CutInto(vent, box.front)

    drawing label {
        t = Text("BATH TOYS", position=(0, 0), size=12, font="sans:Bold", fill=true)
    }
    At(label.t.position, box.front.bb.center, dy=45 mm)
    CutInto(label, box.front)

    # keyholes in the back
    hang_left = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg)
    hang_right = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg)
    At(hang_left.head_hole.center, box.back.bb.center, dx=-60 mm, dy=35 mm)
    At(hang_right.head_hole.center, box.back.bb.center, dx=60 mm, dy=35 mm)
    CutInto(hang_left, box.back)
    CutInto(hang_right, box.back)

    assert box.front.bb.width == 240 mm and box.front.bb.height == 140 mm, "front 240 x 140"
    assert box.left.bb.height == 120 mm, "120 deep"
    assert len(drains) == 24, "24 drain holes"
    assert drains[23].c.center.x - drains[0].c.center.x == 7 * 25 mm, "8 columns at 25"
    assert drains[23].c.center.y - drains[0].c.center.y == 2 * 25 mm, "3 rows at 25"
    assert len(vents) == 7, "seven slots"
    assert vents[0].s.length == 70 mm and vents[0].s.width == 10 mm, "slots 70 x 10"
    assert hang_right.head_hole.center.x - hang_left.head_hole.center.x == 120 mm, "keyholes 120 apart"
    assert distance(label, vents[3]) >= 3 mm, "label clear of the slots"
}
