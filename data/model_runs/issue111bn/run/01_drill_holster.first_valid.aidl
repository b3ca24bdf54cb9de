# Request: a wall holster for my cordless drill, cut from 6 mm plywood. A back plate 200 wide x
# 160 tall, screwed to the wall through four 4.5 mm holes countersunk for 9 mm heads, the holes
# 60 mm either side of the centre line, 18 mm down from the top and 15 mm up from the bottom.
# A shelf 200 wide sticking out 120 mm from the face of the back plate, its top 40 mm below the
# plate's top; the drill hangs handle-down through a U slot in the shelf, 45 mm wide and 80 mm
# deep from the front edge, its mouth corners rounded r5. The shelf is glued into the back plate
# with three 20 mm tabs. Two right-triangle brackets under the shelf, 100 x 100, 90 mm either
# side of the centre (centre of their thickness), each tabbed into the back plate and into the
# shelf with two 20 mm tabs. "DRILL" engraved on the back plate above the shelf, 10 mm tall.

import "std/joints.aidl"

thickness 6 mm
T = 6 mm
W = 200 mm          # back plate and shelf width
H = 160 mm          # back plate height
DEPTH = 120 mm      # shelf out from the back plate's face
SHELF_DROP = 40 mm  # shelf top below the plate top
LEG = 100 mm        # bracket legs
BX = 90 mm          # bracket centre from the middle
SLOT_W = 45 mm
SLOT_D = 80 mm

def bracket() -> solid {
    tri = Polygon([(0, 0), (LEG, 0), (0, -LEG)])
    top_strip = Rectangle(bottom_left=(0, 0), width=LEG, height=T)
    back_strip = Rectangle(bottom_left=(-T, -LEG), width=T, height=LEG)
    top_tabs = tab_and_slot(part="tab", length=LEG, thickness=T, tabs=2, tab=20 mm, screw=0,
                            cx=LEG / 2, cy=T)
    back_tabs = tab_and_slot(part="tab", length=LEG, thickness=T, tabs=2, tab=20 mm, screw=0,
                             rotation=90 deg, cx=-T, cy=-LEG / 2)
}

assembly holster {
    solid back {
        plate = Rectangle(center=(0, 0), width=W, height=H)
        # shelf joint: its middle T/2 below the shelf top
        shelf_slots = tab_and_slot(part="slot", length=W, thickness=T, tabs=3, tab=20 mm, screw=0,
                                   cx=0, cy=H / 2 - SHELF_DROP - T / 2)
        # bracket joints: from the shelf's underside down LEG
        left_slots = tab_and_slot(part="slot", length=LEG, thickness=T, tabs=2, tab=20 mm, screw=0,
                                  rotation=90 deg, cx=-BX, cy=H / 2 - SHELF_DROP - T - LEG / 2)
        right_slots = tab_and_slot(part="slot", length=LEG, thickness=T, tabs=2, tab=20 mm, screw=0,
                                   rotation=90 deg, cx=BX, cy=H / 2 - SHELF_DROP - T - LEG / 2)
        hole screws {
            a = Circle(center=(-60, H / 2 - 18), diameter=4.5)
            b = Circle(center=(60, H / 2 - 18), diameter=4.5)
            c = Circle(center=(-60, -H / 2 + 15), diameter=4.5)
            d = Circle(center=(60, -H / 2 + 15), diameter=4.5)
        }
        Countersink(screws, diameter=9 mm)
        drawing label {
            t = Text("DRILL", position=(0, H / 2 - SHELF_DROP / 2), size=10, valign="middle")
        }
        Fixed(plate)
        assert plate.bb.width == 200 mm and plate.bb.height == 160 mm, "back plate 200 x 160"
        assert screws.b.center.x - screws.a.center.x == 120 mm, "holes 60 either side"
        assert plate.bb.top - screws.a.center.y == 18 mm, "top holes 18 down"
        assert screws.c.center.y - plate.bb.bottom == 15 mm, "bottom holes 15 up"
    }

    solid shelf {
        # local: back edge (tab tips) at the top, front edge at the bottom
        board = Rectangle(center=(0, 0), width=W, height=DEPTH + T)
        tabs = tab_and_slot(part="tab", length=W, thickness=T, tabs=3, tab=20 mm, screw=0,
                            cx=0, cy=(DEPTH + T) / 2)
        left_slots = tab_and_slot(part="slot", length=LEG, thickness=T, tabs=2, tab=20 mm, screw=0,
                                  rotation=90 deg, cx=-BX, cy=(DEPTH + T) / 2 - T - LEG / 2)
        right_slots = tab_and_slot(part="slot", length=LEG, thickness=T, tabs=2, tab=20 mm, screw=0,
                                   rotation=90 deg, cx=BX, cy=(DEPTH + T) / 2 - T - LEG / 2)
        hole drill {
            mouth = Rectangle(bottom_left=(-SLOT_W / 2, -(DEPTH + T) / 2 - 1),
                              width=SLOT_W, height=SLOT_D - SLOT_W / 2 + 1)
            end = Circle(center=(0, -(DEPTH + T) / 2 + SLOT_D - SLOT_W / 2), diameter=SLOT_W)
        }
        Fillet([board, drill.mouth], 5 mm)
        Fixed(board)
        assert board.bb.height - T == 120 mm, "shelf sticks out 120"
        assert drill.end.top.y - board.bb.bottom == 80 mm, "U slot 80 deep"
        assert drill.end.diameter == 45 mm, "U slot 45 wide"
    }

    left = bracket()
    right = bracket()

    RightOf(shelf, back, gap=10)
    AlignTop(shelf, back)
    Below(left, back, gap=10)
    AlignLeft(left, back)
    RightOf(right, left, gap=10)
    AlignTop(right, left)

    # 3D: the back plate upright, its face at y = 0, the shelf and brackets in front (+y)
    Place(back, rotation=(90 deg, 0, 0), position=(0, 0, 0))
    Place(shelf, rotation=(180 deg, 0, 0), position=(0, DEPTH / 2 - T / 2, H / 2 - SHELF_DROP))
    Place(left, rotation=(90 deg, 0, 90 deg), position=(-BX - T / 2, 0, H / 2 - SHELF_DROP - T))
    Place(right, rotation=(90 deg, 0, 90 deg), position=(BX - T / 2, 0, H / 2 - SHELF_DROP - T))
}
