# Request: a carry caddy for our badminton club's shuttlecock tubes, 6 mm ply, finger-jointed.
# Six tubes (80 mm across) stand in six square cells, 2 rows x 3, each cell 84 x 84 inside,
# so the tray is 264 x 174 inside and 120 mm tall inside (half a 290 mm tube sticks out).
# The dividers full height. A 90 x 28 mm hand hole in each end panel, 15 mm below its top
# edge, centred. On the front: "FEATHER & FLIGHT BC" filled-engraved, bold, at most 220 mm
# wide and 16 mm tall, centred on the front panel.

import "std/boxes.aidl"

thickness 6 mm

CELL = 84 mm
T = 6 mm

assembly shuttle_caddy {
    # FIX after the first valid program: the full-height row divider ended right behind the
    # middle of each hand hole (seen in --assembled): dividers lowered to 75 mm, under the
    # hand holes (their bottom edge is 83 mm above the underside)
    tray = divider_tray(length=3 * CELL + 2 * T, width=2 * CELL + T, height=120 mm, rows=2,
                        cols=3, thickness=T, finger=15 mm, outside=false,
                        divider_height=75 mm)

    # the end panels are laid out with their top edges outward: the left one's top is its
    # left edge, the right one's its right edge
    hole left_grip { s = Slot(center=(0, 0), length=90, width=28, rotation=90 deg) }
    hole right_grip { s = Slot(center=(0, 0), length=90, width=28, rotation=90 deg) }
    left_grip.bb.left == tray.body.left.bb.left + 15 mm
    AlignCenterY(left_grip, tray.body.left)
    right_grip.bb.right == tray.body.right.bb.right - 15 mm
    AlignCenterY(right_grip, tray.body.right)
    CutInto(left_grip, tray.body.left)
    CutInto(right_grip, tray.body.right)

    drawing name {
        t = Text("FEATHER & FLIGHT BC", position=(0, 0), size=16, font="sans:Bold",
                 valign="middle", max_width=220 mm, fill=true)
    }
    CenterInside(name, tray.body.front)
    CutInto(name, tray.body.front)

    assert tray.length == 264 mm and tray.width == 174 mm, "264 x 174 inside"
    assert tray.rows * tray.cols == 6, "six cells"
    assert (tray.length - 2 * T) / 3 == 84 mm and (tray.width - T) / 2 == 84 mm, "84 cells"
    assert left_grip.s.length == 90 mm and left_grip.s.width == 28 mm
    assert name.t.bb.width <= 220 mm
}
