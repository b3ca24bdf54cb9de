# Electronics: top panel of a small MIDI controller box, 3 mm plywood, 200 x 120 mm
# outer size with 10 mm finger joints on all four edges (the walls carry the slots);
# eight 7 mm potentiometer holes in 2 rows x 4 columns, 35 mm apart across and 40 mm
# apart up, the bottom-left one at (-75, -15) from the middle; under each knob its
# name "CC1" .. "CC8" engraved 4 mm tall, baseline 11 mm below the hole's centre; one
# 24 mm arcade-button hole at (70, 5); four 3.2 mm PCB screw holes 15 mm in from each
# side; "MIDI 8" engraved 6 mm tall, centred over the button, baseline 20 mm above it.

import "std/joints.aidl"

thickness 3 mm

param finger = 10 mm, min = 8 mm, max = 20 mm

solid top {
    p = finger_panel(width=200 mm, height=120 mm, thickness=3 mm, finger=finger)

    hole knob {
        c = Circle(center=(-75, -15), diameter=7)
    }
    knobs = GridPattern(knob, 2, 4, (35, 40))

    hole button {
        c = Circle(center=(70, 5), diameter=24)
    }

    hole screw {
        c = Circle(center=(-85, -45), diameter=3.2)
    }
    screws = CornerPattern(screw, p.outline, inset=15)

    drawing names {
        for i in range(8) {
            t = Text(f"CC{i + 1}", (-75 + (i % 4) * 35, -15 + (i // 4) * 40 - 11), size=4)
        }
    }
    drawing title {
        word = Text("MIDI 8", (70, 5 + 20), size=6)
    }

    assert p.outline.width == 200 mm and p.outline.height == 120 mm, "panel 200 x 120"
    assert len(knobs) == 8, "eight knobs"
    assert knob.c.diameter == 7 mm, "7 mm pot holes"
    assert knob.c.center.x - p.outline.center.x == -75 mm, "first knob at x -75"
    assert knob.c.center.y - p.outline.center.y == -15 mm, "first knob at y -15"
    assert button.c.diameter == 24 mm, "24 mm button"
    assert button.c.center.x - p.outline.center.x == 70 mm, "button at x 70"
    assert len(screws) == 4, "four screws"
    assert screw.c.diameter == 3.2 mm, "3.2 mm screws"
    assert screw.c.center.x - p.outline.bb.left == 15 mm, "screws 15 in from the side"
    assert screw.c.center.y - p.outline.bb.bottom == 15 mm, "screws 15 up from the bottom"
    assert knob.c.center.y - names.t[0].position.y == 11 mm, "names 11 below the knobs"
    assert names.t[0].size == 4 mm, "names 4 tall"
    assert title.word.position.y - button.c.center.y == 20 mm, "title 20 above the button"
    assert title.word.position.x == button.c.center.x, "title over the button"
}
