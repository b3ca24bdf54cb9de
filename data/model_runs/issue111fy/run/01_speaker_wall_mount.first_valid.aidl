# Request: a wall mount for a round smart speaker (a 100 mm sphere, e.g. an Echo Dot), cut
# from 6 mm birch ply. Back plate 120 wide x 160 tall, R10 corners, hung on two keyholes 80 mm
# apart whose heads are 25 mm below the top edge (screw head 9 mm, shank 4.5 mm, 10 mm slot
# up). A shelf 120 wide standing out 110 mm from the back plate's face, its top 70 mm above
# the plate's bottom edge, front corners R10, with a 70 mm round opening the sphere sits in,
# centred 55 mm out from the plate's face; the shelf is glued into the back plate with three
# 20 mm tenons through mortises. Two right-angle gussets under the shelf, 90 mm along the
# shelf and 60 mm down the wall, 50 mm either side of the centre, each glued with one 30 mm
# tenon into the shelf and one into the back plate. "KITCHEN" engraved filled, 7 mm tall,
# centred on the shelf's strip in front of the opening.

thickness 6 mm

import "std/joints.aidl"
import "std/plates.aidl"

T = 6 mm
plate_w = 120 mm
plate_h = 160 mm
shelf_out = 110 mm               # from the plate's front face
shelf_top = 70 mm                # above the plate's bottom edge
shelf_d = shelf_out + T          # drawn depth: the tenons pass through the plate
z_plate = plate_h / 2            # the plate is drawn about its centre
y_mort = shelf_top - T / 2 - z_plate     # mortise line in the plate's drawing
g_along = 90 mm
g_down = 60 mm
g_x = 50 mm

# a gusset drawn with its inner corner at (0, 0): along the shelf toward +x, down the wall
# toward -y; a band on each leg is cut down to its tenon
def gusset() -> solid {
    tri = Polygon([(0, 0), (g_along, 0), (0, -g_down)])
    top_band = Rectangle(corner=(0, 0), opposite=(g_along, T))
    back_band = Rectangle(corner=(-T, -g_down), opposite=(0, 0))
    top_tab = tab_and_slot(part="tab", length=g_along, thickness=T, tabs=1, tab=30 mm,
                           screw=0, cx=g_along / 2, cy=T)
    back_tab = tab_and_slot(part="tab", length=g_down, thickness=T, tabs=1, tab=30 mm,
                            screw=0, rotation=90 deg, cx=-T, cy=-g_down / 2)
}

assembly speaker_mount {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=10)
        k1 = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, cx=-40 mm,
                     cy=plate_h / 2 - 25 mm)
        k2 = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, cx=40 mm,
                     cy=plate_h / 2 - 25 mm)
        mort = tab_and_slot(part="slot", length=plate_w, thickness=T, tabs=3, tab=20 mm,
                            screw=0, cx=0, cy=y_mort)
        gm1 = tab_and_slot(part="slot", length=g_down, thickness=T, tabs=1, tab=30 mm, screw=0,
                           rotation=90 deg, cx=-g_x, cy=shelf_top - T - g_down / 2 - z_plate)
        gm2 = tab_and_slot(part="slot", length=g_down, thickness=T, tabs=1, tab=30 mm, screw=0,
                           rotation=90 deg, cx=g_x, cy=shelf_top - T - g_down / 2 - z_plate)
    }

    solid shelf {
        body = RoundedRectangle(center=(0, 0), width=plate_w, height=shelf_d,
                                corner_radii=[0, 0, 10, 10])
        tenons = tab_and_slot(part="tab", length=plate_w, thickness=T, tabs=3, tab=20 mm,
                              screw=0, cx=0, cy=shelf_d / 2)
        hole opening {
            c = Circle(center=(0, shelf_d / 2 - T - 55 mm), diameter=70)
        }
        gs1 = tab_and_slot(part="slot", length=g_along, thickness=T, tabs=1, tab=30 mm, screw=0,
                           rotation=90 deg, cx=-g_x, cy=shelf_d / 2 - T - g_along / 2)
        gs2 = tab_and_slot(part="slot", length=g_along, thickness=T, tabs=1, tab=30 mm, screw=0,
                           rotation=90 deg, cx=g_x, cy=shelf_d / 2 - T - g_along / 2)
        drawing label {
            word = Text("KITCHEN", position=(0, -shelf_d / 2 + 10 mm), size=7,
                        font="sans:Bold", valign="middle", fill=true)
        }
    }

    g1 = gusset()
    g2 = gusset()

    # flat on the sheet: side by side
    RightOf(shelf, back, gap=8)
    AlignTop(shelf, back)
    RightOf(g1, shelf, gap=8)
    AlignTop(g1, shelf)
    Below(g2, g1, gap=8)
    AlignLeft(g2, g1)

    # in 3D: the wall is the plane y = 0, the room toward -y
    Place(back, position=(0, 0, z_plate), face="front", up="up")
    Place(shelf, position=(0, -shelf_d / 2, shelf_top - T), face="up", up="back")
    Place(g1, position=(-g_x + T / 2, -T, shelf_top - T), face="left", up="up")
    Place(g2, position=(g_x + T / 2, -T, shelf_top - T), face="left", up="up")

    # the request's numbers
    assert back.body.bb.width == 120 mm and back.body.bb.height == 160 mm, "back plate 120 x 160"
    assert back.k2.head_hole.center.x - back.k1.head_hole.center.x == 80 mm, "keyholes 80 apart"
    assert back.body.bb.top - back.k1.head_hole.center.y == 25 mm, "keyhole heads 25 below the top"
    assert back.k1.head_hole.diameter == 9 mm, "screw head 9 mm"
    assert shelf.body.bb.height - 6 mm == 110 mm, "shelf stands out 110 mm from the plate's face"
    assert back.mort.slot[0].bb.center_y + 6 mm / 2 - back.body.bb.bottom == 70 mm,
        "shelf top 70 above the plate's bottom"
    assert len(back.mort.slot) == 3 and len(shelf.tenons.gap) == 4, "three tenons"
    assert shelf.opening.c.diameter == 70 mm, "70 mm opening"
    assert (shelf.body.bb.top - 6 mm) - shelf.opening.c.center.y == 55 mm,
        "opening centred 55 out from the plate's face"
    assert g1.tri.bb.width == 90 mm and g1.tri.bb.height == 60 mm, "gussets 90 x 60"
    assert back.gm2.slot[0].bb.center_x - back.gm1.slot[0].bb.center_x == 2 * 50 mm,
        "gussets 50 either side of the centre"
    assert shelf.gs2.slot[0].bb.center_x - shelf.gs1.slot[0].bb.center_x == 2 * 50 mm,
        "gusset mortises in the shelf 50 either side"
    assert shelf.label.word.size == 7 mm, "label 7 mm tall"
    assert distance(shelf.label, shelf.opening) >= 2 mm, "label clear of the opening"
    assert shelf.label.bb.bottom - shelf.body.bb.bottom >= 2 mm, "label on the shelf"
}
