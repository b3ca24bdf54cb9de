# Request (sport): a wall display for six ice-hockey pucks (76.2 mm x 25.4 mm), 6 mm ply.
# - Back plate 300 x 250 mm, R12 corners; two keyholes (8 mm head, 4 mm slot, 10 mm
#   up) 120 mm either side of centre, 30 mm below the top edge; "HAT TRICKS" engraved
#   bold, filled, 12 mm high, centred 22 mm below the top edge.
# - Two shelves 290 mm wide, their top faces 30 mm and 130 mm above the plate's bottom
#   edge, each glued into the plate by two 60 mm tabs. Each shelf holds three pucks on
#   edge, face out, on a 95 mm pitch, in a 26 mm groove between the plate and a lip.
# - The lip: 284 mm long, standing 12 mm above the shelf at its front edge, glued into
#   three 30 mm mortises; under each puck a caption engraved on the lip (6 mm strokes).

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

param t = 6 mm
plate_w = 300 mm
plate_h = 250 mm
shelf_w = 290 mm
groove = 26 mm
lip_w = 284 mm
lip_h = 12 mm
pitch = 95 mm
shelf_tops = [30 mm, 130 mm]       # above the plate's bottom edge
shelf_d = groove + t + t            # groove, lip, tabs into the plate

def shelf() -> solid {
    # y = shelf_d / 2: the tabs' tips (the plate's back face); the plate's front face
    # t below it; the lip's mortises 3 mm in from the front edge
    body = RoundedRectangle(center=(0, 0), width=shelf_w, height=shelf_d,
                            corner_radii=[0, 0, 3, 3])
    joint = tab_and_slot(part="tab", length=shelf_w, thickness=t, tabs=2, tab=60 mm,
                         screw=0, cx=0, cy=shelf_d / 2)
    lip_slots = tab_and_slot(part="slot", length=lip_w, thickness=t, tabs=3, tab=30 mm,
                             screw=0, cx=0, cy=-shelf_d / 2 + t / 2)
    Fixed(body)
}

def lip(c1="", c2="", c3="") -> solid {
    # y = -(lip_h + t) / 2: the tabs' tips, under the shelf
    body = Rectangle(center=(0, 0), width=lip_w, height=lip_h + t)
    joint = tab_and_slot(part="tab", length=lip_w, thickness=t, tabs=3, tab=30 mm,
                         screw=0, rotation=180 deg, cx=0, cy=-(lip_h + t) / 2)
    drawing captions {
        a = Text(c1, position=(-pitch, (lip_h + t) / 2 - lip_h / 2), size=6, valign="middle")
        b = Text(c2, position=(0, (lip_h + t) / 2 - lip_h / 2), size=6, valign="middle")
        c = Text(c3, position=(pitch, (lip_h + t) / 2 - lip_h / 2), size=6, valign="middle")
    }
    Fixed(body)
    Fixed(captions)
}

assembly puck_display {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=12)
        low_joint = tab_and_slot(part="slot", length=shelf_w, thickness=t, tabs=2, tab=60 mm,
                                 screw=0, cx=0, cy=-plate_h / 2 + shelf_tops[0] - t / 2)
        high_joint = tab_and_slot(part="slot", length=shelf_w, thickness=t, tabs=2, tab=60 mm,
                                  screw=0, cx=0, cy=-plate_h / 2 + shelf_tops[1] - t / 2)
        left_hang = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                            cx=-120 mm, cy=plate_h / 2 - 30 mm)
        right_hang = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                             cx=120 mm, cy=plate_h / 2 - 30 mm)
        drawing title {
            word = Text("HAT TRICKS", position=(0, plate_h / 2 - 22 mm), size=12,
                        font="sans:Bold", valign="middle", fill=true)
        }
        Fixed(body)
        Fixed(title)
    }

    low_shelf = shelf()
    high_shelf = shelf()
    low_lip = lip(c1="FIRST GOAL", c2="HAT TRICK", c3="CUP FINAL")
    high_lip = lip(c1="MVP 2023", c2="SHUTOUT", c3="100TH GAME")

    # on the sheet
    Below(low_shelf, back, gap=8)
    AlignLeft(low_shelf, back)
    Below(high_shelf, low_shelf, gap=8)
    AlignLeft(high_shelf, low_shelf)
    Below(low_lip, high_shelf, gap=8)
    AlignLeft(low_lip, high_shelf)
    Below(high_lip, low_lip, gap=8)
    AlignLeft(high_lip, low_lip)

    # in 3D: the plate's front face in y = 0, its bottom edge on z = 0
    Place(back, position=(0, t, plate_h / 2), face="front", up="up")
    Place(low_shelf, position=(0, -(shelf_d / 2 - t), shelf_tops[0] - t), face="up")
    Place(high_shelf, position=(0, -(shelf_d / 2 - t), shelf_tops[1] - t), face="up")
    Place(low_lip, position=(0, -groove, shelf_tops[0] - t + (lip_h + t) / 2), face="front",
          up="up")
    Place(high_lip, position=(0, -groove, shelf_tops[1] - t + (lip_h + t) / 2), face="front",
          up="up")

    # the request's numbers
    assert back.body.width == 300 mm and back.body.height == 250 mm, "300 x 250 plate"
    assert shelf_tops[1] - shelf_tops[0] >= 76.2 mm + 20 mm, "a puck fits under the shelf above"
    assert plate_h - shelf_tops[1] - 76.2 mm >= 30 mm + 4 mm, "top pucks clear the keyholes"
    assert groove >= 25.4 mm, "a puck fits the groove"
    assert 3 * pitch <= shelf_w, "three pucks per shelf"
    assert pitch - 76.2 mm >= 15 mm, "gaps between pucks"
    assert back.right_hang.head_hole.center.x - back.left_hang.head_hole.center.x == 240 mm,
        "keyholes 120 either side"
    assert back.body.bb.top - back.left_hang.head_hole.center.y == 30 mm, "keyholes 30 down"
}
