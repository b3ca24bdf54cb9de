# Request (workshop): a wall rack for 5 claw hammers, cut from 6 mm birch ply.
# - Back plate 420 x 130 mm, R8 corners, screwed to the wall through two 4.5 mm
#   holes countersunk for 9 mm flat heads, 150 mm either side of centre and 25 mm
#   above the bottom edge. "HAMMERS" engraved (bold, filled, 14 mm) above the shelf.
# - Shelf 420 mm wide standing 90 mm out from the back plate, its underside 40 mm
#   below the plate's top edge; glued into the back plate by 3 tabs 40 mm wide.
# - 5 handle slots in the shelf, 30 mm wide, 60 mm deep from the front edge with a
#   round end, on an 80 mm pitch, centred. Front corners of the shelf R6.
# - Two triangular brackets (80 mm down the wall x 80 mm under the shelf), 15 mm in
#   from each end, each tabbed (one 30 mm tab) into the back plate and the shelf.

import "std/joints.aidl"

thickness 6 mm

param t = 6 mm
param hammers = 5, min = 2, max = 6
param pitch = 80 mm, min = 60 mm, max = 90 mm

plate_w = 420 mm
plate_h = 130 mm
shelf_depth = 90 mm
shelf_low = plate_h / 2 - 40 mm      # shelf underside, in the back plate's frame
slot_w = 30 mm
slot_depth = 60 mm
leg = 80 mm
bracket_x = plate_w / 2 - 15 mm      # bracket centre from the middle
tab_c = 37 mm                         # bracket tab centres from the inside corner

def bracket() -> solid {
    # inside corner at (0, 0): x runs out under the shelf, y down the wall;
    # a strip t wide beyond each leg carries the tab
    body = Polygon([(-t, t), (leg, t), (leg, 0), (0, -leg), (-t, -leg)])
    top = tab_and_slot(part="tab", length=leg + t, thickness=t, tabs=1, tab=30 mm,
                       screw=0, cx=(leg - t) / 2, cy=t)
    back = tab_and_slot(part="tab", length=leg + t, thickness=t, tabs=1, tab=30 mm,
                        screw=0, rotation=90 deg, cx=-t, cy=-(leg - t) / 2)
}

assembly hammer_rack {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=8)
        hole screws {
            l = Circle(center=(-150, -plate_h / 2 + 25), diameter=4.5)
            r = Circle(center=(150, -plate_h / 2 + 25), diameter=4.5)
        }
        Countersink(screws, diameter=9)
        shelf_joint = tab_and_slot(part="slot", length=plate_w, thickness=t, tabs=3,
                                   tab=40 mm, screw=0, cx=0, cy=shelf_low + t / 2)
        left_mortise = tab_and_slot(part="slot", length=leg + t, thickness=t, tabs=1,
                                    tab=30 mm, screw=0, rotation=90 deg,
                                    cx=-bracket_x, cy=shelf_low - tab_c)
        right_mortise = tab_and_slot(part="slot", length=leg + t, thickness=t, tabs=1,
                                     tab=30 mm, screw=0, rotation=90 deg,
                                     cx=bracket_x, cy=shelf_low - tab_c)
        drawing label {
            word = Text("HAMMERS", position=(0, (shelf_low + t + plate_h / 2) / 2), size=14,
                        font="sans:Bold", valign="middle", fill=true)
        }
        Fixed(body)
    }

    solid shelf {
        # front edge at y = -shelf_depth / 2, back face of the back plate at the tab tips
        body = RoundedRectangle(center=(0, t / 2), width=plate_w, height=shelf_depth + t,
                                corner_radii=[0, 0, 6, 6])
        joint = tab_and_slot(part="tab", length=plate_w, thickness=t, tabs=3, tab=40 mm,
                             screw=0, cx=0, cy=shelf_depth / 2 + t)
        hole slots {
            for i in range(hammers) {
                mouth = Rectangle(center=((i - (hammers - 1) / 2) * pitch,
                                          -shelf_depth / 2 + (slot_depth - slot_w / 2) / 2 - 0.5),
                                  width=slot_w, height=slot_depth - slot_w / 2 + 1,
                                  overrun=true)
                end = Circle(center=((i - (hammers - 1) / 2) * pitch,
                                     -shelf_depth / 2 + slot_depth - slot_w / 2),
                             diameter=slot_w)
            }
        }
        left_mortise = tab_and_slot(part="slot", length=leg + t, thickness=t, tabs=1,
                                    tab=30 mm, screw=0, rotation=90 deg,
                                    cx=-bracket_x, cy=shelf_depth / 2 - tab_c)
        right_mortise = tab_and_slot(part="slot", length=leg + t, thickness=t, tabs=1,
                                     tab=30 mm, screw=0, rotation=90 deg,
                                     cx=bracket_x, cy=shelf_depth / 2 - tab_c)
    }

    left_bracket = bracket()
    right_bracket = bracket()

    # on the sheet: shelf under the back plate, brackets beside each other under it
    Below(shelf, back, gap=10)
    AlignLeft(shelf, back)
    Below(left_bracket, shelf, gap=10)
    AlignLeft(left_bracket, shelf)
    RightOf(right_bracket, left_bracket, gap=10)
    AlignTop(right_bracket, left_bracket)

    # in 3D: the back plate's front face in the plane y = 0, its bottom edge at z = 0
    Place(back, position=(0, t, plate_h / 2), face="front", up="up")
    Place(shelf, position=(0, -shelf_depth / 2, plate_h / 2 + shelf_low), face="up")
    Place(left_bracket, position=(-bracket_x + t / 2, 0, plate_h / 2 + shelf_low),
          face="left", up="up")
    Place(right_bracket, position=(bracket_x + t / 2, 0, plate_h / 2 + shelf_low),
          face="left", up="up")

    # the request's numbers
    assert back.body.width == 420 mm and back.body.height == 130 mm, "plate 420 x 130"
    assert len(shelf.slots.end) == 5, "5 hammer slots"
    assert shelf.slots.end[1].center.x - shelf.slots.end[0].center.x == 80 mm, "80 mm pitch"
    assert shelf.slots.end[0].diameter == 30 mm, "slots 30 mm wide"
    assert shelf.slots.end[0].top.y - shelf.body.bb.bottom == 60 mm, "slots 60 mm deep"
    assert shelf.joint.gap[0].bb.bottom - shelf.body.bb.bottom == 90 mm, "shelf stands 90 out"
    assert back.body.bb.top - shelf_low == 40 mm, "shelf underside 40 below the top"
    assert back.screws.r.center.x - back.screws.l.center.x == 300 mm, "screws 150 either side"
    assert back.screws.l.center.y - back.body.bb.bottom == 25 mm, "screws 25 up"
}
