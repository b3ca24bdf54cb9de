# Request: a wall rack for my shop-vac accessories, cut from 6 mm birch ply.
# - Back plate 400 mm wide x 200 mm tall, hung on two wall screws by keyholes
#   (10 mm head, 5 mm slot, 12 mm long, upward) 150 mm either side of the middle, 170 mm up.
#   "SHOP VAC" engraved (bold, 20 mm) across it above the shelf.
# - Shelf 400 mm wide sticking out 120 mm from the plate's face, its underside 100 mm up the
#   plate; glued into the plate by 3 tabs 40 mm wide through mortises.
# - 4 holes of 37 mm (the tools' 35 mm cuffs drop through) on a 90 mm pitch, centred
#   65 mm out from the plate's face; each labelled below (CREVICE, BRUSH, NOZZLE, WAND), 6 mm.
# - Two right-triangle gussets, 90 mm legs, under the shelf 180 mm either side of the middle,
#   each glued by one 30 mm tenon into the shelf and one into the plate.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

T = 6 mm
names = ["CREVICE", "BRUSH", "NOZZLE", "WAND"]

def gusset() -> solid {
    # right angle at (0, 0): shelf underside along +x, plate face along -y;
    # the tenons' tips stand T beyond each edge, the corner square left empty
    web = Polygon([(-T, -90), (-T, 0), (0, 0), (0, T), (90, T)])
    top_tenon = tab_and_slot(part="tab", length=90 mm, thickness=T, tabs=1, tab=30 mm,
                             screw=0, cx=45 mm, cy=T)
    back_tenon = tab_and_slot(part="tab", length=90 mm, thickness=T, tabs=1, tab=30 mm,
                              screw=0, rotation=90 deg, cx=-T, cy=-45 mm)
}

assembly rack {
    solid plate {
        body = RoundedRectangle(center=(0, 100), width=400, height=200, corner_radius=6)
        hang_l = keyhole(head=10 mm, slot_width=5 mm, length=12 mm, direction=90 deg,
                         cx=-150 mm, cy=170 mm)
        hang_r = keyhole(head=10 mm, slot_width=5 mm, length=12 mm, direction=90 deg,
                         cx=150 mm, cy=170 mm)
        # mortises: the shelf's middle plane is 100 + T/2 up
        shelf_mortise = tab_and_slot(part="slot", length=400 mm, thickness=T, tabs=3,
                                     tab=40 mm, screw=0, cx=0 mm, cy=100 mm + T / 2)
        gusset_mortise_l = tab_and_slot(part="slot", length=90 mm, thickness=T, tabs=1,
                                        tab=30 mm, screw=0, rotation=90 deg,
                                        cx=-180 mm, cy=55 mm)
        gusset_mortise_r = tab_and_slot(part="slot", length=90 mm, thickness=T, tabs=1,
                                        tab=30 mm, screw=0, rotation=90 deg,
                                        cx=180 mm, cy=55 mm)
        drawing label {
            t = Text("SHOP VAC", position=(0, 135), size=20, font="sans:Bold", fill=true)
        }
    }

    solid shelf {
        # the back edge (tenon tips) on y = 0, the shelf toward -y
        body = Rectangle(center=(0, -(120 + T) / 2), width=400, height=120 + T)
        tenons = tab_and_slot(part="tab", length=400 mm, thickness=T, tabs=3, tab=40 mm,
                              screw=0, cx=0 mm, cy=0 mm)
        hole tool {
            c = Circle(center=(-135, -T - 65), diameter=37)
        }
        tools = LinearPattern(tool, 4, (90, 0))
        gusset_mortise_l = tab_and_slot(part="slot", length=90 mm, thickness=T, tabs=1,
                                        tab=30 mm, screw=0, rotation=90 deg,
                                        cx=-180 mm, cy=-T - 45 mm)
        gusset_mortise_r = tab_and_slot(part="slot", length=90 mm, thickness=T, tabs=1,
                                        tab=30 mm, screw=0, rotation=90 deg,
                                        cx=180 mm, cy=-T - 45 mm)
        drawing labels {
            for i in range(4) {
                t = Text(names[i], position=(-135 + i * 90, -T - 65 - 18.5 - 10), size=6,
                         font="sans", fill=true)
            }
        }
    }

    g_left = gusset()
    g_right = gusset()

    # lay the flat parts out apart on the sheet
    Below(shelf, plate, gap=10)
    AlignLeft(shelf, plate)
    Below(g_left, shelf, gap=10)
    AlignLeft(g_left, shelf)
    RightOf(g_right, g_left, gap=10)
    AlignTop(g_right, g_left)

    # 3D: plate standing, its engraved face to the front; shelf flat, tips at the plate's back
    Place(plate, position=(0, 0, 0), face="front", up="up")
    Place(shelf, position=(0, 0, 100), face="up", up="back")
    Place(g_left, position=(-177, -T, 100), face="left", up="up")
    Place(g_right, position=(183, -T, 100), face="left", up="up")

    # the request's numbers
    assert plate.body.bb.width == 400 mm, "plate 400 wide"
    assert plate.body.bb.height == 200 mm, "plate 200 tall"
    assert shelf.body.bb.height - T == 120 mm, "shelf sticks out 120 from the plate's face"
    assert len(shelf.tools) == 4, "4 tool holes"
    assert shelf.tools[1].c.center.x - shelf.tools[0].c.center.x == 90 mm, "90 mm pitch"
    assert shelf.tools[0].c.diameter == 37 mm, "37 mm holes"
    assert shelf.tools[0].c.center.y == -T - 65 mm, "65 mm out from the plate's face"
    assert plate.hang_r.head_hole.center.x - plate.hang_l.head_hole.center.x == 300 mm,
        "keyholes 150 either side"
}
