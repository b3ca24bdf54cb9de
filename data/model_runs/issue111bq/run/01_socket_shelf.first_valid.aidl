# Request: a shelf that hangs from a UK single wall socket so a phone can sit on it while it
# charges. 4 mm birch ply. The back plate (100 wide, 235 tall) goes behind the socket's
# 86 x 86 faceplate: a 56 x 56 opening for the socket's body and two 4 mm holes 60.3 mm apart
# (the faceplate's two screws pass through them). The shelf (100 wide, 90 deep from the back
# plate's face) sits with its top 60 mm below the faceplate's bottom edge, glued into the back
# plate with two 20 mm tabs, and is held by two triangular brackets (80 deep, 60 tall, 35 mm
# either side of the middle), each with one 30 mm tab up into the shelf and one back into the
# back plate. A 20 mm tall front lip stands 6 mm in from the shelf's front edge (two 20 mm
# tabs) and is engraved "PHONE".
units mm
thickness 4 mm
import "std/joints.aidl"

T = 4 mm
FACE = 86 mm        # the faceplate's side
SCREWS = 60.3 mm    # the faceplate's screw centres
DROP = 60 mm        # faceplate bottom edge to the shelf's top
SHELF_TOP = -(FACE / 2 + DROP)   # in the back plate's frame: socket centre at (0, 0)
WIDTH = 100 mm
DEPTH = 90 mm
BR_X = 35 mm
BR_DEPTH = 80 mm
BR_H = 60 mm
LIP_H = 20 mm
LIP_IN = 6 mm

# a bracket in its own frame: x out from the wall (0 = the wall), y up (0 = the shelf's top)
def bracket() -> solid {
    body = Polygon([(0, 0), (BR_DEPTH, 0), (BR_DEPTH, -8), (10, -BR_H), (0, -BR_H)])
    top_tab = tab_and_slot(part="tab", length=BR_DEPTH, thickness=T, tabs=1, tab=30 mm,
                           screw=0, cx=BR_DEPTH / 2, cy=0)
    back_tab = tab_and_slot(part="tab", length=BR_H, thickness=T, tabs=1, tab=30 mm,
                            screw=0, rotation=90 deg, cx=0, cy=-BR_H / 2)
}

assembly socket_shelf {
    # the back plate, socket centre at (0, 0)
    solid back {
        plate = Rectangle(center=(0, -57.5), width=WIDTH, height=235)
        hole socket_body { r = Rectangle(center=(0, 0), width=56, height=56) }
        hole screw_l { c = Circle(center=(-SCREWS / 2, 0), diameter=4) }
        hole screw_r { c = Circle(center=(SCREWS / 2, 0), diameter=4) }
        shelf_slots = tab_and_slot(part="slot", length=WIDTH, thickness=T, tabs=2, tab=20 mm,
                                   screw=0, cx=0, cy=SHELF_TOP - T / 2)
        br_slot_l = tab_and_slot(part="slot", length=BR_H, thickness=T, tabs=1, tab=30 mm,
                                 screw=0, rotation=90 deg, cx=-BR_X, cy=SHELF_TOP - BR_H / 2)
        br_slot_r = tab_and_slot(part="slot", length=BR_H, thickness=T, tabs=1, tab=30 mm,
                                 screw=0, rotation=90 deg, cx=BR_X, cy=SHELF_TOP - BR_H / 2)
    }

    # the shelf: back edge (tab tips) at y = 0, front edge at y = -(DEPTH + T)
    solid shelf {
        board = Rectangle(bottom_left=(-WIDTH / 2, -(DEPTH + T)), width=WIDTH, height=DEPTH + T)
        back_tabs = tab_and_slot(part="tab", length=WIDTH, thickness=T, tabs=2, tab=20 mm,
                                 screw=0, cx=0, cy=0)
        br_slot_l = tab_and_slot(part="slot", length=BR_DEPTH, thickness=T, tabs=1, tab=30 mm,
                                 screw=0, rotation=90 deg, cx=-BR_X, cy=-BR_DEPTH / 2)
        br_slot_r = tab_and_slot(part="slot", length=BR_DEPTH, thickness=T, tabs=1, tab=30 mm,
                                 screw=0, rotation=90 deg, cx=BR_X, cy=-BR_DEPTH / 2)
        lip_slots = tab_and_slot(part="slot", length=WIDTH, thickness=T, tabs=2, tab=20 mm,
                                 screw=0, cx=0, cy=-(DEPTH + T - LIP_IN - T / 2))
    }

    # the lip: tab tips at y = 0 (flush with the shelf's underside)
    solid lip {
        board = Rectangle(bottom_left=(-WIDTH / 2, 0), width=WIDTH, height=LIP_H + T)
        tabs = tab_and_slot(part="tab", length=WIDTH, thickness=T, tabs=2, tab=20 mm,
                            screw=0, rotation=180 deg, cx=0, cy=0)
        drawing label {
            word = Text("PHONE", position=(0, T + LIP_H / 2), size=10, valign="middle")
        }
    }

    b_l = bracket()
    b_r = bracket()

    # on the sheet
    RightOf(shelf, back, gap=8)
    AlignTop(shelf, back)
    RightOf(lip, back, gap=8)
    Below(lip, shelf, gap=8)
    RightOf(b_l, shelf, gap=8)
    AlignTop(b_l, shelf)
    RightOf(b_r, shelf, gap=8)
    Below(b_r, b_l, gap=8)

    # in 3D: x along the wall, y out from the wall, z up (socket centre at z = 0)
    Place(back, rotation=(90 deg, 0, 0), position=(0, T, 0))
    Place(shelf, rotation=(0, 0, 180 deg), position=(0, 0, SHELF_TOP - T))
    Place(lip, rotation=(90 deg, 0, 0), position=(0, DEPTH + T - LIP_IN, SHELF_TOP - T))
    Place(b_l, rotation=(90 deg, 0, 90 deg), position=(-BR_X - T / 2, 0, SHELF_TOP))
    Place(b_r, rotation=(90 deg, 0, 90 deg), position=(BR_X - T / 2, 0, SHELF_TOP))

    # the request's numbers
    assert back.screw_r.c.center.x - back.screw_l.c.center.x == 60.3 mm, "screws 60.3 apart"
    assert back.plate.bb.width == 100 mm and back.plate.bb.height == 235 mm, "back 100 x 235"
    assert back.socket_body.bb.width == 56 mm, "socket opening 56"
    assert (back.screw_l.c.center.y - 86 mm / 2) - (back.shelf_slots.bb.center_y + T / 2) == 60 mm,
        "shelf top 60 below the faceplate"
    assert shelf.board.bb.height - T == 90 mm, "shelf 90 deep from the plate's face"
    assert lip.board.bb.height - T == 20 mm, "lip 20 tall"
}
