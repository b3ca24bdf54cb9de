# Request (music): a resonance box for an A 440 Hz tuning fork, 3 mm ply, finger-jointed and
# glued. A quarter-wave tube: closed at one end, open at the other, inside 195 mm long
# (343 m/s / 440 Hz / 4), 80 mm wide, 40 mm tall. The top panel has a 9 mm hole for the fork's
# stem, centred across, its centre 30 mm from the inside of the closed end, and "A 440 Hz"
# engraved 12 mm tall along the box, centred in the top panel's remaining length beyond the hole.
# The box lies on its bottom panel with the open end to the back.

import "std/joints.aidl"

thickness 3 mm

param F = 440, min = 256, max = 1000      # the fork's frequency, Hz
C = 343000 mm                             # speed of sound per second
INSIDE_L = C / F / 4                      # quarter wavelength (195 mm at 440 Hz)
INSIDE_W = 80 mm
INSIDE_H = 40 mm
T = 3 mm

assembly resonator {
    # the box is built standing on its closed end; its open "top" is the open end, its
    # "front" panel becomes the resonator's top, its "back" the resonator's bottom
    box = finger_box(length=INSIDE_W, depth=INSIDE_H, height=INSIDE_L, thickness=T,
                     finger=10 mm, closed=false, outside=false)

    hole stem { c = Circle(center=(0, 0), diameter=9 mm) }
    AlignCenterX(stem, box.front)
    stem.c.center.y == box.front.bb.bottom + T + 30 mm
    CutInto(stem, box.front)

    drawing label {
        t = Text("A 440 Hz", position=(0, 0), size=12 mm, rotation=90 deg, valign="middle")
    }
    AlignCenterX(label, box.front)
    label.t.position.y == (stem.c.center.y + 4.5 mm + box.front.bb.top) / 2
    CutInto(label, box.front)

    # lying down: the box's +z (its length) goes to +y (the back), its front panel looks up
    Place(box, position=(0, 0, (INSIDE_H + 2 * T) / 2), rotation=(-90 deg, 0, 0))

    assert abs(INSIDE_L - 195 mm) < 1 mm, "inside 195 long for 440 Hz"
    assert box.front.bb.height - T == INSIDE_L, "open end: the walls are the inside length + the closed end"
    assert box.front.bb.width - 2 * T == 80 mm, "80 wide inside"
    assert box.left.bb.height - 2 * T == 40 mm, "40 tall inside"
    assert stem.c.center.y - (box.front.bb.bottom + T) == 30 mm, "stem 30 from the closed end"
    assert stem.c.diameter == 9 mm, "9 mm stem hole"
}
