# Garden: a wall bracket that holds one 12 cm flower pot on a fence post, 6 mm exterior ply,
# four parts:
# - a back plate 110 mm wide x 200 mm tall, screwed to the post by two 4.5 mm holes
#   countersunk for 9 mm heads, 170 mm apart on its centre line; "BASIL" engraved
#   8 mm tall below the gussets;
# - a ring shelf: a 100 mm wide back edge that enters the back plate with two 20 mm tabs
#   screwed by M3 captive nuts, and a ring 150 mm outside diameter with a 110 mm hole
#   (the pot hangs in it by its rim), the hole's centre 85 mm out from the back plate;
#   the shelf's top 60 mm above the back plate's centre;
# - two gussets 45 mm deep x 90 mm tall under the shelf, 80 mm apart (centre to centre),
#   each glued by two 12 mm tabs into the back plate and two into the shelf.

units mm
thickness 6 mm

import "std/joints.aidl"

t = 6 mm
back_w = 110 mm
back_h = 200 mm
shelf_back = 100 mm
ring_od = 150 mm
ring_id = 110 mm
ring_out = 85 mm       # hole centre from the back plate's front face
shelf_mid = 57 mm      # shelf mid-plane above the back plate's centre (its top at 60)
gus_depth = 45 mm
gus_h = 90 mm
gus_x = 40 mm          # each gusset's mid-plane from the centre line

def gusset() -> solid {
    # x = 0: the back plate's front face; y = 0: the shelf's underside
    web = Polygon([(-t, -gus_h), (0, -gus_h), (gus_depth, 0), (gus_depth, t), (0, t), (0, 0),
                   (-t, 0)])
    top_tabs = tab_and_slot(part="tab", length=gus_depth, thickness=t, tabs=2, tab=12 mm,
                            screw=0, rotation=0 deg, cx=gus_depth / 2, cy=t)
    back_tabs = tab_and_slot(part="tab", length=gus_h, thickness=t, tabs=2, tab=12 mm,
                             screw=0, rotation=90 deg, cx=-t, cy=-gus_h / 2)
}

assembly pot_bracket {
    solid back {
        plate = Rectangle(center=(0, 0), width=back_w, height=back_h)
        shelf_slots = tab_and_slot(part="slot", length=shelf_back, thickness=t, tabs=2,
                                   tab=20 mm, screw=3, cx=0, cy=shelf_mid)
        left_slots = tab_and_slot(part="slot", length=gus_h, thickness=t, tabs=2, tab=12 mm,
                                  screw=0, rotation=90 deg, cx=-gus_x,
                                  cy=shelf_mid - t / 2 - gus_h / 2)
        right_slots = tab_and_slot(part="slot", length=gus_h, thickness=t, tabs=2, tab=12 mm,
                                   screw=0, rotation=90 deg, cx=gus_x,
                                   cy=shelf_mid - t / 2 - gus_h / 2)
        hole screws {
            upper = Circle(center=(0, 85), diameter=4.5)
            lower = Circle(center=(0, -85), diameter=4.5)
        }
        Countersink(screws, diameter=9)
        drawing label {
            name = Text("BASIL", position=(0, -55), size=8, valign="middle")
        }
        Fillet(plate, 5)
    }

    solid shelf {
        # y = 0: the back plate's back face (the tabs' tips); the back plate's front face at y = t
        neck = Rectangle(corner=(-shelf_back / 2, 0), opposite=(shelf_back / 2, t + 40))
        ring = Circle(center=(0, t + ring_out), diameter=ring_od)
        hole pot {
            c = Circle(center=(0, t + ring_out), diameter=ring_id)
        }
        tabs = tab_and_slot(part="tab", length=shelf_back, thickness=t, tabs=2, tab=20 mm,
                            screw=3, rotation=180 deg, cx=0, cy=0)
        left_slots = tab_and_slot(part="slot", length=gus_depth, thickness=t, tabs=2, tab=12 mm,
                                  screw=0, rotation=90 deg, cx=-gus_x, cy=t + gus_depth / 2)
        right_slots = tab_and_slot(part="slot", length=gus_depth, thickness=t, tabs=2, tab=12 mm,
                                   screw=0, rotation=90 deg, cx=gus_x, cy=t + gus_depth / 2)
        Fillet([[neck.left, ring], [neck.right, ring]], 8)
    }

    left_gusset = gusset()
    right_gusset = gusset()

    RightOf(shelf, back, gap=10)
    AlignBottom(shelf, back)
    RightOf(left_gusset, shelf, gap=10)
    AlignTop(left_gusset, back)
    RightOf(right_gusset, left_gusset, gap=10)
    AlignTop(right_gusset, left_gusset)

    assert back.plate.width == 110 mm and back.plate.height == 200 mm, "back 110 x 200"
    assert back.screws.upper.center.y - back.screws.lower.center.y == 170 mm, "screws 170 apart"
    assert shelf.ring.diameter == 150 mm and shelf.pot.c.diameter == 110 mm, "ring 150 / 110"
    assert shelf.pot.c.center.y - shelf.neck.bb.bottom - 6 mm == 85 mm, "hole 85 mm out"
    assert shelf.neck.width == 100 mm, "100 mm back edge"
    assert back.shelf_slots.cy + 6 mm / 2 - back.plate.center.y == 60 mm, "shelf top 60 mm up"
    assert back.right_slots.cx - back.left_slots.cx == 80 mm, "gussets 80 mm apart"
    assert left_gusset.web.bb.width - 6 mm == 45 mm, "gusset 45 deep"
    assert left_gusset.web.bb.height - 6 mm == 90 mm, "gusset 90 tall"
    assert back.label.name.size == 8 mm, "8 mm letters"
}
