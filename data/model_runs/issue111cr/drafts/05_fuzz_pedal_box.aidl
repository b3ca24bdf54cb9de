# Request: a plywood enclosure for a DIY guitar fuzz pedal, 3 mm birch ply, finger-jointed,
# 120 x 95 x 45 mm outside. Lid (the top), from its centre, the box's back at +y: three 7.2 mm
# pot holes 35 mm apart on a row 28 mm behind the centre, each with a knob scale of 11 engraved
# ticks (r 11.5 to 13.5 mm) over 270 degrees (from 225 deg round to -45 deg) and its name
# engraved 3.5 mm high 18 mm in front of it (GAIN, TONE, LEVEL); a 5 mm LED hole at the centre;
# a 12.2 mm footswitch hole 22 mm in front of the centre; "FUZZ" filled-engraved 8 mm high
# (bold sans), its baseline 40 mm in front of the centre. A 9.7 mm jack hole in the middle of
# each side (input right, output left), an 8 mm DC jack hole 3 mm above the middle of the back
# with "9V" engraved 4 mm high below it.

import "std/joints.aidl"

units mm
thickness 3 mm

POT_Y = 28 mm
POT_PITCH = 35 mm
NAMES = ["GAIN", "TONE", "LEVEL"]

assembly fuzz_pedal {
    box = finger_box(length=120 mm, depth=95 mm, height=45 mm, thickness=3 mm, finger=10 mm)

    hole lid_holes {
        o = Point(0, 0, construction=true)
        for p in range(3) {
            pot = Circle(center=((p - 1) * POT_PITCH, POT_Y), diameter=7.2 mm)
        }
        led = Circle(center=(0, 0), diameter=5 mm)
        switch = Circle(center=(0, -22 mm), diameter=12.2 mm)
    }
    drawing lid_art {
        o = Point(0, 0, construction=true)
        for p in range(3) {
            for t in range(11) {
                tick = Line(polar(((p - 1) * POT_PITCH, POT_Y), 11.5 mm, 225 deg - t * 27 deg),
                            polar(((p - 1) * POT_PITCH, POT_Y), 13.5 mm, 225 deg - t * 27 deg))
            }
            name = Text(NAMES[p], position=((p - 1) * POT_PITCH, POT_Y - 18 mm), size=3.5 mm)
        }
        title = Text("FUZZ", position=(0, -40 mm), size=8 mm, font="sans:Bold", fill=true)
    }
    At(lid_holes.o, box.lid.bb.center)
    At(lid_art.o, box.lid.bb.center)
    CutInto(lid_holes, box.lid)
    CutInto(lid_art, box.lid)

    hole jack_in { c = Circle(center=(0, 0), diameter=9.7 mm) }
    hole jack_out { c = Circle(center=(0, 0), diameter=9.7 mm) }
    CenterInside(jack_in, box.right)
    CenterInside(jack_out, box.left)
    CutInto(jack_in, box.right)
    CutInto(jack_out, box.left)

    hole dc { c = Circle(center=(0, 0), diameter=8 mm) }
    drawing dc_label { t = Text("9V", position=(0, -10 mm), size=4 mm) }
    At(dc.c.center, box.back.bb.center, dy=3 mm)
    At(dc_label.t.position, dc.c.center, dy=-13 mm)
    CutInto(dc, box.back)
    CutInto(dc_label, box.back)

    # the request's numbers
    assert box.front.bb.width == 120 mm and box.front.bb.height == 45 mm, "120 long, 45 high"
    assert box.left.bb.height == 95 mm, "95 deep"
    assert len(lid_holes.pot) == 3 and lid_holes.pot[0].diameter == 7.2 mm, "three 7.2 mm pots"
    assert lid_holes.pot[2].center.x - lid_holes.pot[1].center.x == 35 mm, "35 mm apart"
    assert lid_holes.pot[1].center.y - box.lid.bb.center_y == 28 mm, "28 mm behind the centre"
    assert len(lid_art.tick) == 3 and len(lid_art.tick[0]) == 11, "11 ticks per knob"
    assert box.lid.bb.center_y - lid_holes.switch.center.y == 22 mm, "switch 22 mm in front"
    assert lid_holes.switch.diameter == 12.2 mm and lid_holes.led.diameter == 5 mm, "switch, LED"
    assert jack_in.c.diameter == 9.7 mm and dc.c.diameter == 8 mm, "jacks"
    assert dc.c.center.y - box.back.bb.center_y == 3 mm, "DC jack 3 mm above the middle"
}
