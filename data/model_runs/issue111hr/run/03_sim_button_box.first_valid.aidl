# Request (electronics): a sim-racing button box, 3 mm black acrylic, finger-jointed box
# 200 mm long, 110 mm deep, 60 mm tall outside, 10 mm fingers. Top panel, measured from its
# centre: a back row 25 mm behind the centre with three toggle switches (12.2 mm holes, each
# with a 3 mm anti-rotation key hole 8.5 mm behind it) at x = -60, -20, 20 and a rotary encoder
# (7.2 mm hole) at x = 60; a front row 20 mm in front of the centre with four 16 mm momentary
# buttons 30 mm apart starting at x = -75 and a 22 mm START button at x = 60. Each control has
# a 4 mm engraved label under it: IGN, PIT, WIPER, BIAS for the back row 13 mm below the hole
# centre; 1 to 4 13 mm below the buttons, START 17 mm below the big button. A 12.5 mm hole for
# a PG7 cable gland in the middle of the back panel.

units mm
thickness 3 mm
import "std/joints.aidl"

toggle_x = [-60, -20, 20]
toggle_names = ["IGN", "PIT", "WIPER"]

assembly button_box {
    box = finger_box(length=200 mm, depth=110 mm, height=60 mm, thickness=3 mm, finger=10 mm)

    hole controls {
        ref = Point(0, 0, construction=true)
        for i in range(3) {
            toggle = Circle(center=(toggle_x[i], 25), diameter=12.2)
            key = Circle(center=(toggle_x[i], 25 + 8.5), diameter=3)
        }
        encoder = Circle(center=(60, 25), diameter=7.2)
        for j in range(4) {
            button = Circle(center=(-75 + 30 * j, -20), diameter=16)
        }
        start = Circle(center=(60, -20), diameter=22)
    }
    controls.ref.x == box.lid.bb.center_x
    controls.ref.y == box.lid.bb.center_y
    CutInto(controls, box.lid)

    drawing labels {
        ref = Point(0, 0, construction=true)
        for i in range(3) {
            tl = Text(toggle_names[i], position=(toggle_x[i], 25 - 13), size=4, valign="middle")
        }
        el = Text("BIAS", position=(60, 25 - 13), size=4, valign="middle")
        for j in range(4) {
            bl = Text(str(j + 1), position=(-75 + 30 * j, -20 - 13), size=4, valign="middle")
        }
        sl = Text("START", position=(60, -20 - 17), size=4, valign="middle")
    }
    labels.ref.x == box.lid.bb.center_x
    labels.ref.y == box.lid.bb.center_y
    CutInto(labels, box.lid)

    hole gland { c = Circle(center=(0, 0), diameter=12.5) }
    CenterInside(gland, box.back)
    CutInto(gland, box.back)

    # the request's numbers
    assert len(controls.toggle) == 3 and len(controls.button) == 4, "3 toggles, 4 buttons"
    assert controls.key[0].center.y - controls.toggle[0].center.y == 8.5 mm, "key hole 8.5 behind"
    assert controls.button[1].center.x - controls.button[0].center.x == 30 mm, "buttons 30 apart"
    assert controls.toggle[0].center.y - controls.button[0].center.y == 45 mm, "rows 25 + 20 apart"
    assert controls.button[0].center.x - controls.ref.x == -75 mm, "first button at x = -75"
    assert controls.start.diameter == 22 mm and controls.button[0].diameter == 16 mm, "button sizes"
    assert controls.toggle[0].center.y - labels.tl[0].position.y == 13 mm, "toggle labels 13 below"
    assert controls.start.center.y - labels.sl.position.y == 17 mm, "START label 17 below"
    assert distance(labels, controls) >= 1.5 mm, "labels clear of the holes"
    assert controls.bb.left >= box.lid.bb.left + 8 mm and controls.bb.right <= box.lid.bb.right - 8 mm,
        "controls clear of the finger joints left and right"
    assert controls.bb.bottom >= box.lid.bb.bottom + 8 mm and controls.bb.top <= box.lid.bb.top - 8 mm,
        "controls clear of the front and back edges"
    assert labels.bb.bottom >= box.lid.bb.bottom + 6 mm, "labels on the lid"
}
