# Request (garden): a gutter garden for strawberries on the fence: 112 mm half-round
# gutter (outer radius 56 mm) held by brackets cut from 6 mm exterior ply (I cut two of
# each part). The bracket's cradle plate is 156 x 130 mm and stands out from the fence; a
# half-round seat of radius 57 mm (1 mm clearance) is cut from its top edge, its centre
# 12 mm + 57 mm from the fence face; its fence edge has two 20 mm tabs into the back plate.
# The back plate, 60 x 170 mm, is screwed flat to the fence with two 5 mm countersunk holes
# (10 mm heads) 70 mm above and below its centre, and has the two mortises. An end cap to
# glue into each gutter end: a half disc of radius 54 mm with an 8 mm drain hole 12 mm
# above its lowest point. A plant label 120 x 25 mm on a 60 mm pointed stake, with
# "STRAWBERRIES" engraved filled, 10 mm letters.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
GUTTER_R = 56 mm
SEAT_R = GUTTER_R + 1 mm
STANDOFF = 12 mm
CRADLE_W = 156 mm
CRADLE_H = 130 mm
BACK_H = 170 mm

assembly gutter_garden {
    solid cradle {
        body = Rectangle(center=(0, 0), width=CRADLE_W, height=CRADLE_H)
        hole seat {
            c = Circle(center=(-CRADLE_W / 2 + T + STANDOFF + SEAT_R, CRADLE_H / 2),
                       radius=SEAT_R)
        }
        # the fence edge (x = -78): two tabs, the plate toward +x
        fence = tab_and_slot(part="tab", length=CRADLE_H, thickness=T, tabs=2, tab=20,
                             screw=0, cx=-CRADLE_W / 2, cy=0, rotation=90 deg)
        Fillet(body.top_right, 8)
    }
    solid back {
        plate = RoundedRectangle(center=(0, 0), width=60, height=BACK_H, corner_radius=6)
        mortise = tab_and_slot(part="slot", length=CRADLE_H, thickness=T, tabs=2, tab=20,
                               screw=0, cx=0, cy=0, rotation=90 deg)
        hole screw_top { c = Circle(center=(0, 70), diameter=5) }
        hole screw_bottom { c = Circle(center=(0, -70), diameter=5) }
        Countersink([screw_top, screw_bottom], diameter=10)
    }
    solid end_cap {
        disc = Sector(center=(0, 0), radius=54, start_angle=180 deg, end_angle=360 deg)
        hole drain { c = Circle(center=(0, -54 + 12), diameter=8) }
    }
    solid label {
        card = RoundedRectangle(center=(0, 0), width=120, height=25, corner_radius=4)
        stake = Polygon([(-8, -12.5), (8, -12.5), (0, -72.5)])
        drawing name {
            t = Text("STRAWBERRIES", (0, 0), size=10, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }

    back.bb.center == (-140, 0)
    cradle.bb.center == (0, 0)
    end_cap.bb.center == (150, 30)
    label.bb.center == (0, -140)

    assert cradle.body.width == 156 mm and cradle.body.height == 130 mm, "cradle 156 x 130"
    assert cradle.seat.c.radius == 56 mm + 1 mm, "seat radius 57"
    assert cradle.seat.c.center.x - cradle.fence.gap[0].bb.right == 12 mm + 57 mm,
        "seat centre 12 + 57 from the fence face"
    assert cradle.seat.c.center.y == cradle.body.bb.top, "seat centred on the top edge"
    assert back.plate.width == 60 mm and back.plate.height == 170 mm, "back 60 x 170"
    assert back.screw_top.c.center.y - back.plate.center.y == 70 mm, "screw 70 above"
    assert back.plate.center.y - back.screw_bottom.c.center.y == 70 mm, "screw 70 below"
    assert len(cradle.fence.gap) == 3 and len(back.mortise.slot) == 2, "two tabs"
    # the tabs meet the mortises: the same spacing on both parts
    assert back.mortise.slot[1].center.y - back.mortise.slot[0].center.y ==
        CRADLE_H / 2, "mortise pitch"
    assert back.screw_top.c.bb.bottom - back.mortise.bb.top >= 5 mm, "screw clear of the slot"
    assert back.plate.bb.top - back.screw_top.c.bb.top >= 5 mm, "wood above the screw"
    assert end_cap.disc.radius == 54 mm, "cap radius 54"
    assert end_cap.drain.c.center.y - end_cap.disc.bb.bottom == 12 mm, "drain 12 up"
    assert label.card.width == 120 mm and label.card.height == 25 mm, "label 120 x 25"
    assert label.card.bb.bottom - label.stake.bb.bottom == 60 mm, "60 mm stake"
    assert label.name.t.bb.width <= 120 mm - 8 mm, "the name fits on the label"
}
