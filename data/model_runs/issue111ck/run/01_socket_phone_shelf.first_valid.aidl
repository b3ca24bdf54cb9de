# Request (home): a phone charging shelf that hangs on a UK single wall socket, in 3 mm plywood.
# The back plate is 100 mm wide x 170 mm tall with 6 mm rounded corners. The socket faceplate's
# two screws (60.3 mm apart, side by side) pass through two 4 mm holes, countersunk 8 mm, 40 mm
# above the plate's bottom edge; a 48 x 60 mm window (corners r 4) centred between the screw holes
# lets the plug in. A shelf 100 mm wide x 70 mm deep is glued into the back plate with 2 tabs, its
# top face 120 mm above the plate's bottom edge; it has a 12 x 30 mm cable slot (long side across
# the shelf) centred 12 mm from its back edge. A front lip standing 20 mm above the shelf joins the
# shelf's front edge with 2 tabs and has "CHARGE" engraved 8 mm tall.

import "std/joints.aidl"

thickness 3 mm

param plate_w = 100 mm, min = 90 mm, max = 140 mm
param plate_h = 170 mm, min = 150 mm, max = 220 mm
param shelf_d = 70 mm, min = 50 mm, max = 100 mm
param lip_h = 20 mm, min = 10 mm, max = 40 mm
t = 3 mm
shelf_top = 120 mm     # shelf's top face above the plate's bottom edge
screw_y = 40 mm        # screw holes above the plate's bottom edge
screw_pitch = 60.3 mm

assembly charging_shelf {
    solid back {
        body = RoundedRectangle(center=(0, plate_h / 2), width=plate_w, height=plate_h,
                                corner_radius=6)
        hole screws {
            l = Circle(center=(-screw_pitch / 2, screw_y), diameter=4)
            r = Circle(center=(screw_pitch / 2, screw_y), diameter=4)
        }
        Countersink(screws, diameter=8)
        hole window {
            w = RoundedRectangle(center=(0, screw_y), width=48, height=60, corner_radius=4)
        }
        # slots for the shelf's tabs: the shelf's middle is half a thickness under its top face
        shelf_slots = tab_and_slot(part="slot", length=plate_w, thickness=t, tabs=2, screw=0,
                                   cx=0 mm, cy=shelf_top - t / 2)
    }

    solid shelf {
        s = Rectangle(center=(0, 0), width=plate_w, height=shelf_d)
        # back edge (top in the flat drawing) carries the tabs into the back plate
        back_tabs = tab_and_slot(part="tab", length=plate_w, thickness=t, tabs=2, screw=0,
                                 cx=0 mm, cy=shelf_d / 2)
        hole cable {
            c = Slot(center=(0, shelf_d / 2 - 12), length=30, width=12)
        }
        # slots near the front edge take the lip's tabs
        lip_slots = tab_and_slot(part="slot", length=plate_w, thickness=t, tabs=2, screw=0,
                                 cx=0 mm, cy=-shelf_d / 2 + t / 2)
    }

    solid lip {
        l = Rectangle(center=(0, 0), width=plate_w, height=lip_h + t)
        # bottom edge carries the tabs down through the shelf (panel above the edge)
        tabs = tab_and_slot(part="tab", length=plate_w, thickness=t, tabs=2, screw=0,
                            rotation=180 deg, cx=0 mm, cy=-(lip_h + t) / 2)
        drawing label {
            word = Text("CHARGE", position=(0, t / 2), size=8, valign="middle")
        }
    }

    RightOf(shelf, back, gap=10)
    AlignTop(shelf, back)
    Below(lip, shelf, gap=10)
    AlignCenterX(lip, shelf)

    # the request's numbers
    assert back.body.bb.width == 100 mm, "back plate 100 mm wide"
    assert back.body.bb.height == 170 mm, "back plate 170 mm tall"
    assert back.screws.r.center.x - back.screws.l.center.x == 60.3 mm, "screws 60.3 mm apart"
    assert back.screws.l.center.y - back.body.bb.bottom == 40 mm, "screws 40 mm up"
    assert back.window.w.center.x == (back.screws.l.center.x + back.screws.r.center.x) / 2,
        "window centred between the screws"
    assert back.window.bb.width == 48 mm and back.window.bb.height == 60 mm, "window 48 x 60"
    assert back.shelf_slots.bb.top - back.body.bb.bottom == 120 mm, "shelf top face 120 mm up"
    assert shelf.s.bb.width == 100 mm and shelf.s.bb.height == 70 mm, "shelf 100 x 70"
    assert shelf.s.bb.top - shelf.cable.c.center.y == 12 mm, "cable slot 12 mm from back edge"
    assert shelf.cable.bb.width == 30 mm and shelf.cable.bb.height == 12 mm, "cable slot 12 x 30"
    assert lip.l.bb.height - 3 mm == 20 mm, "lip stands 20 mm above the shelf"
    assert len(back.shelf_slots.slot) == 2 and len(shelf.lip_slots.slot) == 2, "2 tabs each"
}
