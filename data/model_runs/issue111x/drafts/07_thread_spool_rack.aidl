# Crafts: a wall rack for sewing-thread spools, 6 mm plywood. Plate 240 mm wide x 160 mm
# tall, R6 corners. 18 holes of 6.2 mm for 6 mm dowel pegs, 3 rows x 6 columns, 36 mm apart
# across and 48 mm apart up, the grid centred across, the bottom row's centres 30 mm above
# the bottom edge. Two keyholes to hang it (8 mm head, 4 mm slot 10 mm long, upward), head
# centres 15 mm in from the sides and 25 mm below the top. "THREADS" engraved as filled
# sans Bold letters 10 mm tall, centred across, their middle 12 mm below the top.

import "std/plates.aidl"

thickness 6 mm

solid rack {
    plate = RoundedRectangle(center=(0, 0), width=240, height=160, corner_radius=6)

    hole peg {
        c = Circle(center=(-90, -50), diameter=6.2)
    }
    pegs = GridPattern(peg, 3, 6, col_spacing=36, row_spacing=48)
    peg.c.center.y == plate.bb.bottom + 30 mm
    (pegs[0].c.center.x + pegs[5].c.center.x) / 2 == plate.center.x

    left_key = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg)
    right_key = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg)
    left_key.head_hole.center == (plate.bb.left + 15 mm, plate.bb.top - 25 mm)
    right_key.head_hole.center == (plate.bb.right - 15 mm, plate.bb.top - 25 mm)

    drawing title {
        t = Text("THREADS", (0, 68), size=10, font="sans:Bold", valign="middle", fill=true)
    }
    AlignCenterX(title, plate)
    title.bb.center_y == plate.bb.top - 12 mm
}

assert rack.plate.bb.width == 240 mm and rack.plate.bb.height == 160 mm, "plate 240 x 160"
assert len(rack.pegs) == 18, "18 peg holes"
assert rack.pegs[1].c.center.x - rack.pegs[0].c.center.x == 36 mm, "36 mm across"
assert rack.pegs[6].c.center.y - rack.pegs[0].c.center.y == 48 mm, "48 mm up"
assert rack.pegs[0].c.center.y - rack.bb.bottom == 30 mm, "bottom row 30 up"
assert rack.pegs[0].c.diameter == 6.2 mm, "6.2 mm holes"
assert rack.left_key.head_hole.center.x - rack.bb.left == 15 mm, "keyhole 15 in"
assert rack.bb.top - rack.left_key.head_hole.center.y == 25 mm, "keyhole 25 down"
assert rack.bb.top - rack.title.bb.center_y == 12 mm, "title 12 below the top"
assert rack.title.bb.bottom > rack.pegs[17].c.center.y + 3.1 mm, "title clear of the pegs"
