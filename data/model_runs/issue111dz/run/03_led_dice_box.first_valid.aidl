# Request: a box for my electronic LED dice kit, 3 mm ply, finger-jointed (10 mm fingers),
# closed, 80 x 60 x 40 mm outside.
# - Lid: 7 LED holes of 5.1 mm (5 mm LEDs) in the dice layout on a 12 mm pitch (centre, four
#   corners, middle left and right), the dice centred 14 mm left of the lid's centre inside an
#   engraved 38 mm rounded square (R6); a 12.2 mm hole for a 12 mm push button 20 mm right of
#   the centre, "ROLL" engraved (bold, 5 mm) 3 mm under it.
# - Right side: a 9 x 4 mm window for a slide switch, its long side horizontal, centred.
# - Bottom: four M3 clearance holes for the 50 x 30 perfboard's standoffs, 44 x 24 apart,
#   centred.

import "std/joints.aidl"

thickness 3 mm

PITCH = 12 mm
PIPS = [(0, 0), (-PITCH, PITCH), (PITCH, PITCH), (-PITCH, -PITCH), (PITCH, -PITCH),
        (-PITCH, 0), (PITCH, 0)]

assembly dice_box {
    box = finger_box(length=80 mm, depth=60 mm, height=40 mm, thickness=3 mm, finger=10 mm,
                     closed=true)

    hole pips {
        for i in range(7) {
            c = Circle(center=PIPS[i], diameter=5.1)
        }
        Rigid(self)
    }
    drawing face {
        r = RoundedRectangle(center=(0, 0), width=38, height=38, corner_radius=6)
    }
    hole button {
        c = Circle(center=(0, 0), diameter=12.2)
    }
    drawing roll {
        t = Text("ROLL", position=(0, 0), size=5, font="sans:Bold", fill=true)
    }
    AlignCenterY(pips, box.lid)
    pips.c[0].center.x == box.lid.bb.center_x - 14 mm
    Concentric(face.r, pips.c[0])
    AlignCenterY(button, box.lid)
    button.c.center.x == box.lid.bb.center_x + 20 mm
    AlignCenterX(roll, button)
    Below(roll, button, gap=3)
    CutInto(pips, box.lid)
    CutInto(face, box.lid)
    CutInto(button, box.lid)
    CutInto(roll, box.lid)

    # the right side lies on its side in the net: the box's depth runs along its y
    hole switch {
        w = Rectangle(center=(0, 0), width=4, height=9)
    }
    CenterInside(switch, box.right)
    CutInto(switch, box.right)

    hole standoffs {
        for i in range(4) {
            c = Circle(center=(-22 + 44 * (i % 2), -12 + 24 * (i // 2)), diameter=3.4)
        }
        Rigid(self)
    }
    CenterInside(standoffs, box.bottom)
    CutInto(standoffs, box.bottom)

    # the request's numbers
    assert box.length == 80 mm and box.depth == 60 mm and box.height == 40 mm, "80 x 60 x 40"
    assert len(pips.c) == 7, "7 LEDs"
    assert pips.c[2].center.x - pips.c[1].center.x == 24 mm, "12 mm pitch, corner to corner 24"
    assert pips.c[0].center.x - box.lid.bb.center_x == -14 mm, "dice 14 left of centre"
    assert button.c.center.x - box.lid.bb.center_x == 20 mm, "button 20 right of centre"
    assert button.c.diameter == 12.2 mm, "12.2 mm button hole"
    assert face.r.width == 38 mm, "38 mm dice square"
    assert standoffs.c[1].center.x - standoffs.c[0].center.x == 44 mm, "standoffs 44 apart"
    assert standoffs.c[2].center.y - standoffs.c[0].center.y == 24 mm, "standoffs 24 apart"
    assert button.bb.bottom - roll.bb.top == 3 mm, "ROLL 3 mm under the button"
}
