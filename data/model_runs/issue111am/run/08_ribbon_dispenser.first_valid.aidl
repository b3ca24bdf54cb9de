# Request (crafts/gifts): a gift-wrap ribbon dispenser in 4 mm ply, four parts. Two side
# plates 120 mm deep x 140 mm tall, top corners R20, an 8.3 mm hole for an 8 mm dowel 75 mm up
# in the middle (spools up to 110 mm). A front bar 200 x 40 mm with five 28 x 3 mm ribbon
# slots 36 mm apart, 10 mm below its top edge, and "RIBBONS" engraved (bold, filled, 9 mm)
# under them; a back bar 200 x 30 mm. Each bar is glued into each side by one 16 mm tenon into
# a mortise 8 mm in from the side's front or back edge, bars standing on the table.
units mm
thickness 4 mm
import "std/joints.aidl"

def side_plate() -> solid {
    body = RoundedRectangle(bottom_left=(-60, 0), width=120, height=140,
                            corner_radii=[20, 20, 0, 0])
    hole axle {
        c = Circle(center=(0, 75), diameter=8.3)
    }
    mf = tab_and_slot(part="slot", length=40 mm, thickness=4 mm, tabs=1, tab=16 mm, screw=0,
                      rotation=90 deg, cx=-52 mm, cy=20 mm)
    mb = tab_and_slot(part="slot", length=30 mm, thickness=4 mm, tabs=1, tab=16 mm, screw=0,
                      rotation=90 deg, cx=52 mm, cy=15 mm)
}

def bar(h=30 mm) -> solid {
    board = Rectangle(center=(0, 0), width=200, height=h)
    tl = tab_and_slot(part="tab", length=h, thickness=4 mm, tabs=1, tab=16 mm, screw=0,
                      rotation=90 deg, cx=-100 mm, cy=0 mm)
    tr = tab_and_slot(part="tab", length=h, thickness=4 mm, tabs=1, tab=16 mm, screw=0,
                      rotation=-90 deg, cx=100 mm, cy=0 mm)
}

assembly dispenser {
    left = side_plate()
    right = side_plate()
    RightOf(right, left, gap=10)
    AlignBottom(right, left)
    front = bar(h=40 mm)
    hole ribbon_slots {
        s = Slot(center=(0, 0), length=28, width=3)
    }
    row = LinearPattern(ribbon_slots, 5, (36, 0))
    CutInto(row, front)
    row[0].s.center.x == front.board.center.x - 2 * 36
    row[0].s.center.y == front.board.bb.top - 10
    drawing label {
        t = Text("RIBBONS", (0, 0), size=9, font="sans:Bold", fill=true, valign="middle")
    }
    CutInto(label, front)
    AlignCenterX(label, front.board)
    label.bb.center_y == (front.board.bb.bottom + row[0].bb.bottom) / 2
    back = bar(h=30 mm)
    Below(front, left, gap=10)
    AlignLeft(front, left)
    Below(back, front, gap=10)
    AlignLeft(back, front)
    assert left.body.width == 120 mm and left.body.height == 140 mm, "side size"
    assert left.axle.c.center.y - left.body.bb.bottom == 75 mm, "dowel 75 up"
    assert len(row) == 5, "five ribbon slots"
    assert row[1].s.center.x - row[0].s.center.x == 36 mm, "36 apart"
    assert front.board.height == 40 mm and back.board.height == 30 mm, "bar heights"
    # a 110 mm spool on the dowel: clear of the table, and over the front bar where it stands
    assert left.axle.c.center.y - 55 mm > 0 mm, "a 110 mm spool clears the table"
    assert left.axle.c.center.y - sqrt(55 ** 2 - 52 ** 2) > 40, "and the front bar"
}
