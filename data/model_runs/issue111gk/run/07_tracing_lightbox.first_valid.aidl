# Request: an A5 tracing light box for card making, 3 mm ply with a 3 mm opal acrylic
# diffuser. A closed finger-jointed box 250 x 190 x 45 mm outside (fingers at least 15 mm);
# the lid is a frame round a 220 x 150 mm window (R4 corners), centred; under it a diffuser
# 232 x 162 mm (R3) is glued, overlapping the frame 6 mm all round and fitting inside the
# walls. A millimetre ruler engraved on the frame along the front of the window: 0 to 200 mm,
# a 3 mm tick every 5 mm and a 6 mm tick every 10 mm with its number in cm (2.5 mm tall)
# under it, starting 1 mm from the window. An 8 mm cable hole in the back, 90 mm right of
# its middle, a 12 mm switch hole in the middle of the right end, "LIGHT BOX" engraved 8 mm
# tall in the middle of the front.

import "std/joints.aidl"

thickness 3 mm

assembly light_box {
    box = finger_box(length=250 mm, depth=190 mm, height=45 mm, thickness=3 mm,
                     finger=15 mm, closed=true)

    hole window { w = RoundedRectangle(center=(0, 0), width=220, height=150, corner_radius=4) }
    Coincident(window.w.center, box.lid.outline.center)
    CutInto(window, box.lid)

    # the ruler drawn about the lid's centre; the lid's -y edge is the box's front
    drawing ruler {
        o = Point(0, 0, construction=true)
        for i in range(41) {
            tick = Line((-100 + 5 * i, -76), (-100 + 5 * i, -76 - (6 if i % 2 == 0 else 3)))
        }
        for j in range(21) {
            num = Text(str(j), position=(-100 + 10 * j, -88), size=2.5)
        }
    }
    Coincident(ruler.o, box.lid.outline.center)
    CutInto(ruler, box.lid)

    hole cable { c = Circle(center=(0, 0), diameter=8) }
    AlignCenterY(cable, box.back)
    cable.c.center.x == box.back.outline.center.x + 90 mm
    CutInto(cable, box.back)

    hole switch { c = Circle(center=(0, 0), diameter=12) }
    CenterInside(switch, box.right)
    CutInto(switch, box.right)

    drawing name { t = Text("LIGHT BOX", position=(0, 0), size=8, valign="middle") }
    CenterInside(name, box.front)
    CutInto(name, box.front)

    solid diffuser {
        sheet = RoundedRectangle(center=(0, 0), width=232, height=162, corner_radius=3)
    }
    RightOf(diffuser, box, gap=10)
    AlignBottom(diffuser, box)
    # assembled: glued under the lid, the box standing on z = 0 centred on x = y = 0
    Place(diffuser, position=(0, 0, 45 - 2 * 3), face="up")

    assert box.lid.outline.width == 250 mm and box.lid.outline.height == 190 mm,
        "250 x 190 outside"
    assert window.w.width == 220 mm and window.w.height == 150 mm, "220 x 150 window"
    assert (diffuser.sheet.width - window.w.width) / 2 == 6 mm, "6 mm overlap (length)"
    assert (diffuser.sheet.height - window.w.height) / 2 == 6 mm, "6 mm overlap (depth)"
    assert diffuser.sheet.width <= 250 mm - 2 * 3 mm and diffuser.sheet.height <= 190 mm - 2 * 3 mm,
        "the diffuser fits inside the walls"
    assert len(ruler.tick) == 41 and len(ruler.num) == 21, "0 to 200 mm, cm numbers 0 to 20"
    assert distance(ruler, window) >= 1 mm, "the ruler starts 1 mm from the window"
    assert cable.c.center.x - box.back.outline.center.x == 90 mm, "cable hole 90 mm off centre"
}
