# Request: an office waste-paper bin, 4 mm birch ply, an open-top finger-jointed box
# 200 x 200 mm and 280 mm tall (outside), 15 mm fingers. The front and the back each carry a
# honeycomb of hexagonal windows, 20 mm across flats with 4 mm webs (pointed tops, rows
# staggered), 5 windows a row and 10 rows, kept at least 25 mm from every edge of the panel.
# The left and right sides each have a 90 x 30 mm hand slot, its top 25 mm below the rim.
# "PAPER" is engraved (filled, 30 mm bold letters) upright on the right side, under its slot.

import "std/joints.aidl"

thickness 4 mm

param bin_w = 200 mm, min = 150 mm, max = 260 mm
param bin_h = 280 mm, min = 240 mm, max = 340 mm
web = 4 mm
hex_af = 20 mm
dx = hex_af + web
dy = dx * sqrt(3) / 2
rows = 10
cols = 5
# the honeycomb's centres span this much (odd rows moved by dx / 2)
span_x = (cols - 1) * dx + dx / 2
span_y = (rows - 1) * dy

assembly bin {
    box = finger_box(length=bin_w, depth=bin_w, height=bin_h, thickness=4 mm, finger=15 mm,
                     closed=false)

    hole hex_f { h = RegularPolygon(center=(0, 0), across_flats=hex_af, sides=6, rotation=30 deg) }
    front_grid = GridPattern(hex_f, rows, cols, (dx, dy), stagger=true)
    At(hex_f.h.center, box.front.bb.center, dx=-span_x / 2, dy=-span_y / 2)
    CutInto(hex_f, box.front)

    hole hex_b { h = RegularPolygon(center=(0, 0), across_flats=hex_af, sides=6, rotation=30 deg) }
    back_grid = GridPattern(hex_b, rows, cols, (dx, dy), stagger=true)
    At(hex_b.h.center, box.back.bb.center, dx=-span_x / 2, dy=-span_y / 2)
    CutInto(hex_b, box.back)

    # the sides lie on their side, the left's rim at -x, the right's at +x
    hole grip_l { s = Slot(center=(0, 0), length=90, width=30, rotation=90) }
    AlignCenterY(grip_l, box.left)
    grip_l.bb.left == box.left.bb.left + 25
    CutInto(grip_l, box.left)

    hole grip_r { s = Slot(center=(0, 0), length=90, width=30, rotation=90) }
    AlignCenterY(grip_r, box.right)
    grip_r.bb.right == box.right.bb.right - 25
    CutInto(grip_r, box.right)

    drawing label {
        w = Text("PAPER", position=(0, 0), size=30, font="sans:Bold", fill=true,
                 rotation=-90 deg, valign="middle")
    }
    AlignCenterY(label, box.right)
    label.bb.center_x == box.right.bb.right - 150
    CutInto(label, box.right)

    assert box.front.bb.width == 200 mm and box.front.bb.height == 280 mm, "200 wide, 280 tall"
    assert box.left.bb.height == 200 mm, "200 deep"
    assert len(front_grid) == 50 and len(back_grid) == 50, "5 x 10 windows"
    assert front_grid[0].bb.left - box.front.bb.left >= 25 mm, "left border"
    assert box.front.bb.right - front_grid[9].bb.right >= 25 mm, "right border"
    assert front_grid[0].bb.bottom - box.front.bb.bottom >= 25 mm, "bottom border"
    assert box.front.bb.top - front_grid[49].bb.top >= 25 mm, "top border"
    assert grip_l.bb.width == 30 mm and grip_l.bb.height == 90 mm, "hand slot 90 x 30"
    assert grip_l.bb.left - box.left.bb.left == 25 mm, "slot 25 below the rim"
    assert box.right.bb.right - grip_r.bb.right == 25 mm, "slot 25 below the rim"
    assert label.bb.right < grip_r.bb.left - 10 mm, "label under the slot"
}
