# Request: a wall rack for cable ties in the workshop, cut from 6 mm plywood. A back plate
# 240 x 160 mm with R6 corners hangs on two keyholes (8 mm head, 4 mm slot, 10 mm long) 180 mm
# apart, their heads 25 mm below the top edge; "CABLE TIES" is engraved on it (filled bold
# letters, 14 mm) above the shelf. A shelf 240 mm wide stands out 60 mm from the back's rear face,
# its underside 60 mm above the back's bottom edge, on three glued 20 mm tenons through the back;
# it has four round holes of 22, 18, 14 and 10 mm at 50 mm pitch, centred on the rack, for
# bundles of 370, 300, 200 and 100 mm ties, each length engraved in front of its hole; its front
# corners are R6. Two right-angled gussets 50 x 50 mm under the shelf, their middles 105 mm either
# side of the rack's middle, each on a glued 15 mm tenon into the back and one into the shelf.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

T = 6 mm
W = 240 mm
H = 160 mm
DEPTH = 60 mm
SHELF_Y = -H / 2 + 60 mm        # the shelf's underside, in the back's frame
GUSSET = 50 mm
GX = 105 mm
DIAS = [22 mm, 18 mm, 14 mm, 10 mm]
LENGTHS = [370, 300, 200, 100]

# a gusset drawn with its back edge on x = 0 and its shelf edge on y = 0 (the tenons' tips)
def gusset() -> solid {
    plate = Polygon([(0, 0), (GUSSET, 0), (0, -GUSSET)])
    to_back = tab_and_slot(part="tab", length=GUSSET, thickness=T, tabs=1, tab=15 mm, screw=0,
                           rotation=90 deg, cx=0 mm, cy=-GUSSET / 2)
    to_shelf = tab_and_slot(part="tab", length=GUSSET, thickness=T, tabs=1, tab=15 mm, screw=0,
                            cx=GUSSET / 2, cy=0 mm)
}

assembly rack {
    solid back {
        board = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=6 mm)
        hang_l = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                         cx=-90 mm, cy=H / 2 - 25 mm)
        hang_r = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                         cx=90 mm, cy=H / 2 - 25 mm)
        shelf_mortise = tab_and_slot(part="slot", length=W, thickness=T, tabs=3, tab=20 mm,
                                     screw=0, cx=0 mm, cy=SHELF_Y + T / 2)
        gusset_mortise_l = tab_and_slot(part="slot", length=GUSSET, thickness=T, tabs=1,
                                        tab=15 mm, screw=0, rotation=90 deg,
                                        cx=-GX, cy=SHELF_Y + T - GUSSET / 2)
        gusset_mortise_r = tab_and_slot(part="slot", length=GUSSET, thickness=T, tabs=1,
                                        tab=15 mm, screw=0, rotation=90 deg,
                                        cx=GX, cy=SHELF_Y + T - GUSSET / 2)
        drawing title {
            t = Text("CABLE TIES", position=(0, 18 mm), size=14 mm, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    # the shelf drawn with its back edge (the tenons' tips, the back's rear face) on y = 0
    solid shelf {
        board = RoundedRectangle(center=(0, -DEPTH / 2), width=W, height=DEPTH,
                                 corner_radii=[0, 0, 6 mm, 6 mm])
        tenons = tab_and_slot(part="tab", length=W, thickness=T, tabs=3, tab=20 mm, screw=0,
                              cx=0 mm, cy=0 mm)
        gusset_mortise_l = tab_and_slot(part="slot", length=GUSSET, thickness=T, tabs=1,
                                        tab=15 mm, screw=0, rotation=90 deg,
                                        cx=-GX, cy=-GUSSET / 2)
        gusset_mortise_r = tab_and_slot(part="slot", length=GUSSET, thickness=T, tabs=1,
                                        tab=15 mm, screw=0, rotation=90 deg,
                                        cx=GX, cy=-GUSSET / 2)
        hole bundles {
            for i in range(4) {
                c = Circle(center=(-75 mm + i * 50 mm, -33 mm), diameter=DIAS[i])
            }
        }
        drawing labels {
            for i in range(4) {
                t = Text(str(LENGTHS[i]), position=(-75 mm + i * 50 mm, -52 mm), size=5 mm,
                         valign="middle")
            }
        }
    }

    g_left = gusset()
    g_right = gusset()

    # flat on the sheet
    Below(shelf, back, gap=10 mm)
    AlignLeft(shelf, back)
    RightOf(g_left, back, gap=10 mm)
    AlignTop(g_left, back)
    Below(g_right, g_left, gap=10 mm)
    AlignLeft(g_right, g_left)

    # in 3D: the back's rear face on y = 0, the shelf through it, the gussets under the shelf
    Place(back, position=(0, 0, 0), face="front", up="up")
    Place(shelf, position=(0, 0, SHELF_Y), face="up", up="back")
    Place(g_left, position=(-GX + T / 2, 0, SHELF_Y + T), face="left", up="up")
    Place(g_right, position=(GX + T / 2, 0, SHELF_Y + T), face="left", up="up")

    # the request's numbers
    assert back.board.bb.width == 240 mm and back.board.bb.height == 160 mm, "back 240 x 160"
    assert back.hang_r.head_hole.center.x - back.hang_l.head_hole.center.x == 180 mm,
        "keyholes 180 apart"
    assert back.board.bb.top - back.hang_l.head_hole.center.y == 25 mm, "keyholes 25 below the top"
    assert back.shelf_mortise.slot[0].bb.bottom - back.board.bb.bottom == 60 mm,
        "shelf underside 60 above the bottom"
    assert shelf.board.bb.height == 60 mm and shelf.board.bb.width == 240 mm, "shelf 240 x 60"
    assert len(shelf.bundles.c) == 4, "four holes"
    assert shelf.bundles.c[0].diameter == 22 mm and shelf.bundles.c[1].diameter == 18 mm and
        shelf.bundles.c[2].diameter == 14 mm and shelf.bundles.c[3].diameter == 10 mm, "hole sizes"
    assert shelf.bundles.c[1].center.x - shelf.bundles.c[0].center.x == 50 mm, "50 mm pitch"
    assert (shelf.bundles.c[0].center.x + shelf.bundles.c[3].center.x) / 2 == shelf.board.bb.center_x,
        "holes centred"
    assert back.gusset_mortise_r.slot[0].bb.center_x - back.board.bb.center_x == 105 mm and
        back.board.bb.center_x - back.gusset_mortise_l.slot[0].bb.center_x == 105 mm,
        "gussets 105 either side"
    assert g_left.plate.bb.width == 50 mm and g_left.plate.bb.height == 50 mm, "gussets 50 x 50"
    assert distance(shelf.labels, shelf.bundles) >= 2 mm, "labels clear of the holes"
    assert distance(back.title, back.hang_l) >= 3 mm and distance(back.title, back.hang_r) >= 3 mm,
        "title clear of the keyholes"
    assert distance(back.title, back.shelf_mortise) >= 3 mm, "title clear of the mortises"
}
