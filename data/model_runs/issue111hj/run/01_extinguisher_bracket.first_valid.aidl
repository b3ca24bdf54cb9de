# Request (workshop): a wall bracket for the workshop's 2 kg powder fire extinguisher
# (cylinder 110 mm diameter, 350 mm tall), cut from 6 mm birch ply and glued tab-and-slot.
# - back plate 180 mm wide x 480 mm tall, 12 mm corner radii; two keyholes (10 mm head,
#   5 mm shank slot, 12 mm long) 35 mm below the top edge, 100 mm apart; two 5 mm screw
#   holes countersunk to 10 mm, 15 mm above the bottom edge, 80 mm apart;
#   "FIRE" / "EXTINGUISHER" engraved filled in 10 mm bold capitals below the shelf.
# - shelf 180 wide, standing 170 mm out from the wall's face... (170 mm deep including the
#   6 mm tabs), front corners rounded 30 mm, two 40 mm tabs into the back plate, its centre
#   plane 110 mm above the back plate's bottom edge.
# - collar 230 mm above the shelf (centre to centre), same size, a U opening: a 112 mm
#   circle (1 mm clearance round the cylinder) whose centre is 82 mm from the tabs' tips,
#   open to the front; two 4 x 30 mm slots in its arms for a hook-and-loop strap.
# - two gussets under the shelf, 70 mm either side of the centre: right triangles
#   120 mm along the shelf x 80 mm down the wall, one tab into the shelf (50 mm) and one
#   into the back plate (30 mm).
import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

W = 180 mm
H = 480 mm
DEPTH = 170 mm        # shelf and collar, tab tips to front edge
SHELF_Y = -130 mm     # shelf centre plane in the back plate's frame (110 above its bottom)
COLLAR_Y = 100 mm     # 230 above the shelf
T = 6 mm
CYL_D = 110 mm

def gusset() -> solid {
    # right angle at (0, 0): wall edge x = 0 (down), shelf edge y = 0 (out);
    # strips T wide beyond both edges become the tabs
    body = Polygon([(-6, 6), (120, 6), (120, 0), (0, -80), (-6, -80)])
    top_tab = tab_and_slot(part="tab", length=126 mm, thickness=6 mm, tabs=1, tab=50 mm,
                           screw=0, cx=57 mm, cy=6 mm)
    wall_tab = tab_and_slot(part="tab", length=86 mm, thickness=6 mm, tabs=1, tab=30 mm,
                            screw=0, rotation=90 deg, cx=-6 mm, cy=-37 mm)
}

def shelf_plate() -> solid {
    body = RoundedRectangle(center=(0, -DEPTH / 2), width=W, height=DEPTH,
                            corner_radii=[0, 0, 30, 30])
    tabs = tab_and_slot(part="tab", length=W, thickness=6 mm, tabs=2, tab=40 mm, screw=0,
                        cx=0 mm, cy=0 mm)
}

assembly bracket {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=12)
        kh_left = keyhole(head=10 mm, slot_width=5 mm, length=12 mm, cx=-50 mm, cy=205 mm)
        kh_right = keyhole(head=10 mm, slot_width=5 mm, length=12 mm, cx=50 mm, cy=205 mm)
        hole screws {
            a = Circle(center=(-40, -225), diameter=5)
            b = Circle(center=(40, -225), diameter=5)
        }
        Countersink(screws, diameter=10 mm)
        shelf_slot = tab_and_slot(part="slot", length=W, thickness=6 mm, tabs=2, tab=40 mm,
                                  screw=0, clearance=0.1 mm, cx=0 mm, cy=SHELF_Y)
        collar_slot = tab_and_slot(part="slot", length=W, thickness=6 mm, tabs=2, tab=40 mm,
                                   screw=0, clearance=0.1 mm, cx=0 mm, cy=COLLAR_Y)
        g_slot_l = tab_and_slot(part="slot", length=86 mm, thickness=6 mm, tabs=1, tab=30 mm,
                                screw=0, clearance=0.1 mm, rotation=90 deg, cx=-70 mm,
                                cy=-170 mm)
        g_slot_r = tab_and_slot(part="slot", length=86 mm, thickness=6 mm, tabs=1, tab=30 mm,
                                screw=0, clearance=0.1 mm, rotation=90 deg, cx=70 mm,
                                cy=-170 mm)
        drawing label {
            l1 = Text("FIRE", position=(0, -165), size=10, font="sans:Bold", valign="middle",
                      fill=true)
            l2 = Text("EXTINGUISHER", position=(0, -185), size=10, font="sans:Bold",
                      valign="middle", fill=true)
        }
    }

    solid shelf {
        plate = shelf_plate()
        g_slot_l = tab_and_slot(part="slot", length=126 mm, thickness=6 mm, tabs=1, tab=50 mm,
                                screw=0, clearance=0.1 mm, rotation=90 deg, cx=-70 mm,
                                cy=-63 mm)
        g_slot_r = tab_and_slot(part="slot", length=126 mm, thickness=6 mm, tabs=1, tab=50 mm,
                                screw=0, clearance=0.1 mm, rotation=90 deg, cx=70 mm,
                                cy=-63 mm)
    }

    solid collar {
        plate = shelf_plate()
        hole mouth {
            ring = Circle(center=(0, -82), diameter=112)
            throat = Rectangle(center=(0, -82 - 48), width=112, height=96)
        }
        hole strap {
            s1 = Slot(center=(-73, -140), length=30, width=4, rotation=90)
            s2 = Slot(center=(73, -140), length=30, width=4, rotation=90)
        }
    }

    g1 = gusset()
    g2 = gusset()

    # lay the parts out flat beside the back plate
    RightOf(shelf, back, gap=10)
    AlignTop(shelf, back)
    Below(collar, shelf, gap=10)
    AlignLeft(collar, shelf)
    RightOf(g1, shelf, gap=10)
    AlignTop(g1, shelf)
    Below(g2, g1, gap=10)
    AlignLeft(g2, g1)

    # the request's numbers
    assert back.body.bb.width == 180 mm, "back plate 180 wide"
    assert back.body.bb.height == 480 mm, "back plate 480 tall"
    assert back.collar_slot.slot[0].bb.center_y - back.shelf_slot.slot[0].bb.center_y == 230 mm,
        "collar 230 above the shelf"
    assert back.shelf_slot.slot[0].bb.center_y - back.body.bb.bottom == 110 mm,
        "shelf 110 above the bottom edge"
    assert back.body.bb.top - back.kh_left.head_hole.center.y == 35 mm, "keyholes 35 below the top"
    assert back.kh_right.head_hole.center.x - back.kh_left.head_hole.center.x == 100 mm,
        "keyholes 100 apart"
    assert back.screws.a.center.y - back.body.bb.bottom == 15 mm, "screws 15 above the bottom"
    assert collar.mouth.ring.diameter - CYL_D == 2 mm, "1 mm clearance round the cylinder"
    assert collar.plate.body.bb.height == 170 mm, "collar 170 deep"
    assert shelf.plate.body.bb.height == 170 mm, "shelf 170 deep"
    # the cylinder stands wholly on the shelf: its front at 82 + 55 from the tips
    assert 82 mm + CYL_D / 2 <= 170 mm - 10 mm, "the cylinder's foot 10 mm in from the front"
    assert distance(back.label, back.g_slot_l) >= 3 mm, "label clear of the gusset slots"
    assert distance(back.label, back.g_slot_r) >= 3 mm, "label clear of the gusset slots"
}
