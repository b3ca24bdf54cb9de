# Request: a wall rack that holds six fishing rods upright by their blanks, 6 mm plywood. A back
# plate 400 x 130 mm screwed to the wall with four 5 mm holes countersunk 10 mm (120 mm either
# side of the middle, 20 mm from the bottom and from the top). A shelf 400 mm wide standing out
# 90 mm from the back, its top 76 mm above the back plate's bottom edge, glued into the back
# with three 40 mm tabs; six notches for the blanks in its front edge, 16 mm wide with round
# ends, open at the front and running 55 mm in, on a 60 mm pitch, their mouths rounded (3 mm).
# Under the shelf, 185 mm either side of the middle, two triangular brackets (86 mm deep at the
# top, 72 mm tall), each with a 30 mm tab into the shelf and one into the back. "TIGHT LINES"
# engraved filled in 20 mm bold letters on the back above the shelf.

units mm
thickness 6 mm
import "std/joints.aidl"

T = 6 mm
BACK_W = 400 mm
BACK_H = 130 mm
SHELF_Z = 70 mm          # the shelf's underside above the back plate's bottom edge
DEPTH = 90 mm
RODS = 6
PITCH = 60 mm
NOTCH_W = 16 mm
NOTCH_IN = 55 mm
BRACKET_X = 185 mm
TOP_LEN = 86 mm          # the bracket's top edge, from its front tip to the back face
BR_H = 72 mm             # the bracket's back edge, from its foot to the shelf's top

# a triangular bracket drawn with its back face on x = 0 (tabs out to x = T) and the shelf's
# underside on y = SHELF_Z (tabs up to SHELF_Z + T)
def bracket() -> solid {
    web = Polygon([(-TOP_LEN, SHELF_Z + T), (T, SHELF_Z + T), (T, SHELF_Z + T - BR_H),
                   (-14, SHELF_Z + T - BR_H)])
    top = tab_and_slot(part="tab", length=TOP_LEN + T, thickness=T, tabs=1, tab=30 mm,
                       screw=0, cx=(T - TOP_LEN) / 2, cy=SHELF_Z + T)
    back = tab_and_slot(part="tab", length=BR_H, thickness=T, tabs=1, tab=30 mm, screw=0,
                        rotation=-90 deg, cx=T, cy=SHELF_Z + T - BR_H / 2)
}

assembly rod_rack {
    # the back, drawn about its centre; stood up against the wall (its face toward -y)
    solid back {
        plate = Rectangle(center=(0, 0), width=BACK_W, height=BACK_H)
        shelf_slots = tab_and_slot(part="slot", length=BACK_W, thickness=T, tabs=3, tab=40 mm,
                                   screw=0, cx=0, cy=SHELF_Z + T / 2 - BACK_H / 2)
        for s in [-1, 1] {
            br_slot = tab_and_slot(part="slot", length=BR_H, thickness=T, tabs=1, tab=30 mm,
                                   screw=0, rotation=90 deg, cx=s * BRACKET_X,
                                   cy=SHELF_Z + T - BR_H / 2 - BACK_H / 2)
        }
        hole screws {
            for i in range(4) {
                c = Circle(center=((120 if i % 2 == 1 else -120),
                                   (BACK_H / 2 - 20 if i >= 2 else -BACK_H / 2 + 20)),
                           diameter=5)
            }
        }
        Countersink(screws, diameter=10 mm)
        drawing motto {
            t = Text("TIGHT LINES", position=(0, 38), size=20, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    # the shelf, drawn with its back face on y = DEPTH / 2 and its tabs out to DEPTH / 2 + T
    solid shelf {
        board = Rectangle(center=(0, T / 2), width=BACK_W, height=DEPTH + T)
        tabs = tab_and_slot(part="tab", length=BACK_W, thickness=T, tabs=3, tab=40 mm, screw=0,
                            cx=0, cy=DEPTH / 2 + T)
        for i in range(RODS) {
            hole notch {
                s = Slot(start=((i - (RODS - 1) / 2) * PITCH, -DEPTH / 2 - 10),
                         end=((i - (RODS - 1) / 2) * PITCH, -DEPTH / 2 + NOTCH_IN - NOTCH_W / 2),
                         width=NOTCH_W)
            }
        }
        Fillet([[board, notch[i].s] for i in range(RODS)], 3)
        for s in [-1, 1] {
            br_slot = tab_and_slot(part="slot", length=TOP_LEN + T, thickness=T, tabs=1,
                                   tab=30 mm, screw=0, rotation=90 deg, cx=s * BRACKET_X,
                                   cy=DEPTH / 2 + T - (TOP_LEN + T) / 2)
        }
    }

    bracket_l = bracket()
    bracket_r = bracket()

    # flat on the sheet
    Above(shelf, back, gap=10)
    AlignCenterX(shelf, back)
    Above(bracket_l, shelf, gap=10)
    RightOf(bracket_r, bracket_l, gap=10)
    AlignBottom(bracket_r, bracket_l)
    AlignLeft(bracket_l, shelf)

    # in 3D: the wall is the plane y = 0, the room toward -y, the back's bottom edge at z = 0
    Place(back, rotation=(90 deg, 0, 0), position=(0, 0, BACK_H / 2))
    Place(shelf, position=(0, -DEPTH / 2 - T, SHELF_Z))
    # a bracket's (x, y, z) -> (z, x, y): its back face on the back's front face (y = -T)
    Place(bracket_r, rotation=(90 deg, 0, 90 deg), position=(BRACKET_X - T / 2, -T, 0))
    Place(bracket_l, rotation=(90 deg, 0, 90 deg), position=(-BRACKET_X - T / 2, -T, 0))

    assert back.plate.width == 400 mm and back.plate.height == 130 mm, "back 400 x 130"
    assert len(shelf.notch) == 6, "six rods"
    assert shelf.notch[1].s.start.x - shelf.notch[0].s.start.x == 60 mm, "60 mm pitch"
    assert shelf.notch[0].s.width == 16 mm, "16 mm notches"
    assert shelf.notch[0].s.end.y + NOTCH_W / 2 - shelf.board.bb.bottom == 55 mm,
        "notches run 55 mm in"
    assert shelf.board.height - T == 90 mm, "shelf stands out 90 mm"
    assert SHELF_Z + T == 76 mm, "shelf top 76 mm up"
    assert back.screws.c[1].center.x - back.plate.center.x == 120 mm, "screws 120 mm out"
    assert back.screws.c[0].center.y - back.plate.bb.bottom == 20 mm and
        back.plate.bb.top - back.screws.c[3].center.y == 20 mm, "screws 20 mm in"
    assert back.screws.c[0].diameter == 5 mm, "5 mm screw holes"
    assert len(shelf.tabs.slot) == 3, "three shelf tabs"
    # the outer notch must keep clear of the bracket's slot
    assert BRACKET_X - T / 2 - (shelf.notch[5].s.start.x + NOTCH_W / 2) >= 10 mm,
        "notches clear the brackets"
}
