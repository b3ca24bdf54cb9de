# Request: a tofu press for a 400 g block (about 110 x 75 x 45 mm), from 6 mm ply.
# A base 180 x 130 mm (R8 corners) with four M6 holes 12 mm in from each corner for
# threaded rods and a grid of 5 mm drain holes, 7 x 5 at 14 mm pitch, in the middle; the
# block's place (110 x 75) engraved round the grid. Two side rails 120 long and 30 mm tall
# glued into the base with two 20 mm tenons each, standing 79 mm apart inside (2 mm each
# side of the block): they keep the block centred and stop the press plate 30 mm above the
# base so the tofu is squeezed, not crushed. A press plate 180 x 130 (R8) rides down the
# rods in loose M6 holes, "TOFU PRESS" engraved filled 12 mm high on its top.

units mm
t = 6 mm
thickness t
import "std/plates.aidl"
import "std/joints.aidl"

plate_w = 180 mm
plate_h = 130 mm
rail_len = 120 mm
rail_h = 30 mm
rail_y = 75 mm / 2 + 2 mm + t / 2    # the rails' middle planes, either side of the block

def side_rail() -> solid {
    body = Rectangle(bottom_left=(-rail_len / 2, -t), width=rail_len, height=rail_h + t)
    tenons = tab_and_slot(part="tab", length=rail_len, thickness=t, tabs=2, tab=20 mm,
                          screw=0, clearance=0.1 mm, rotation=180 deg, cx=0, cy=-t)
}

assembly tofu_press {
    solid base {
        plate = mounting_plate(width=plate_w, height=plate_h, corner_radius=8 mm, screw=6,
                               fit="medium", inset=12 mm)
        hole drain {
            c = Circle(center=(-3 * 14 mm, -2 * 14 mm), diameter=5 mm)
        }
        grid = GridPattern(drain, 5, 7, (14 mm, 14 mm))
        mortise_a = tab_and_slot(part="slot", length=rail_len, thickness=t, tabs=2,
                                 tab=20 mm, screw=0, clearance=0.1 mm, cx=0, cy=rail_y)
        mortise_b = tab_and_slot(part="slot", length=rail_len, thickness=t, tabs=2,
                                 tab=20 mm, screw=0, clearance=0.1 mm, cx=0, cy=-rail_y)
        drawing block_place {
            r = Rectangle(center=(0, 0), width=110 mm, height=75 mm)
        }
    }
    rail_a = side_rail()
    rail_b = side_rail()
    solid press {
        plate = mounting_plate(width=plate_w, height=plate_h, corner_radius=8 mm, screw=6,
                               fit="coarse", inset=12 mm)
        drawing word {
            w = Text("TOFU PRESS", position=(0, 0), size=12 mm, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    # flat on the sheet
    RightOf(press, base, gap=10 mm)
    AlignTop(press, base)
    Below(rail_a, base, gap=10 mm)
    AlignLeft(rail_a, base)
    RightOf(rail_b, rail_a, gap=10 mm)
    AlignTop(rail_b, rail_a)

    # assembled
    Place(base, position=(0, 0, 0))
    Place(rail_a, position=(0, rail_y + t / 2, t), face="front", up="up")
    Place(rail_b, position=(0, -rail_y + t / 2, t), face="front", up="up")
    Place(press, position=(0, 0, t + rail_h))

    assert base.plate.body.width == 180 mm and base.plate.body.height == 130 mm, "base size"
    assert press.plate.body.width == 180 mm and press.plate.body.height == 130 mm, "press size"
    assert len(base.grid) == 35, "7 x 5 drain holes"
    assert base.drain.c.diameter == 5 mm, "5 mm drain holes"
    assert base.grid[1].c.center.x - base.grid[0].c.center.x == 14 mm, "14 mm pitch across"
    assert base.grid[7].c.center.y - base.grid[0].c.center.y == 14 mm, "14 mm pitch up"
    assert base.plate.corner[0].c.center.x - base.plate.body.bb.left == 12 mm, "rods 12 mm in"
    assert base.plate.corner[0].c.diameter >= 6.4 mm, "M6 rod holes"
    assert press.plate.corner[0].c.diameter > base.plate.corner[0].c.diameter, "press rides loose"
    assert rail_a.body.height - t == 30 mm, "rails 30 mm above the base"
    assert 2 * rail_y - t == 79 mm, "79 mm between the rails"
    assert distance(base.block_place, base.grid) >= 2 mm, "outline clear of the drain holes"
    assert distance(base.block_place, base.mortise_a) >= 1 mm, "outline clear of the mortises"
}
