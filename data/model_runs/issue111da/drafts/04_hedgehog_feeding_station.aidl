# Request (pets): a hedgehog feeding station that keeps cats out, 6 mm exterior ply,
# finger-jointed (20 mm fingers), with a lift-off lid (a brick goes on top). Outside 400 mm
# long x 300 mm deep x 200 mm tall with the lid on. Entrance in the front wall near the left
# end: 130 mm wide, 130 mm tall, round-topped, its sill 15 mm above the bottom edge, 20 mm from
# the inside of the left wall. Inside, a baffle wall 20 mm right of the entrance runs from the
# front wall back towards the back wall, leaving a 130 mm passage behind it, so a hedgehog
# walks in, goes round the baffle, and reaches the food where a cat's paw cannot. The baffle
# stands on two 30 mm tabs glued into floor slots and one 40 mm tenon into a mortise in the
# front wall, and stops 0.5 mm under the lid's lip. Six 8 mm drain holes in the floor of the
# feeding room, 2 rows of 3 at 60 mm pitch, centred in it. On the lid, "HEDGEHOG CAFÉ"
# engraved filled (sans bold, 24 mm) with "NO CATS" (12 mm) under it.

import "std/boxes.aidl"
import "std/joints.aidl"

thickness 6 mm

t = 6 mm
length = 400 mm
depth = 300 mm
height = 200 mm
wall_h = height - t                 # the walls, the lid on top of them
door_w = 130 mm
door_h = 130 mm
sill = 15 mm
door_x = -length / 2 + t + 20 mm + door_w / 2      # world x of the entrance's middle
baffle_x = door_x + door_w / 2 + 20 mm             # world x of the baffle's left face
passage = 130 mm
baffle_end = depth / 2 - t - passage               # world y where the baffle stops
baffle_len = baffle_end + depth / 2                # from the front's outer face
baffle_h = wall_h - t - 0.5 mm                     # tab tips (z = 0) to under the lip
room_x = (baffle_x + t + length / 2 - t) / 2       # middle of the feeding room

assembly hedgehog_station {
    box = lid_box(length=length, width=depth, height=height, thickness=t, finger=20 mm)

    # the baffle, drawn with the front wall's outer face on x = 0 and its tab tips on y = 0
    solid baffle {
        body = Rectangle(bottom_left=(0, 0), width=baffle_len, height=baffle_h)
        feet = tab_and_slot(part="tab", length=baffle_len, thickness=t, tabs=2, tab=30 mm,
                            screw=0, rotation=180 deg, cx=baffle_len / 2, cy=0 mm)
        tenon = tab_and_slot(part="tab", length=baffle_h, thickness=t, tabs=1, tab=40 mm,
                             screw=0, rotation=90 deg, cx=0 mm, cy=baffle_h / 2)
    }
    RightOf(baffle, box, gap=10)
    Place(baffle, position=(baffle_x, -depth / 2, 0), face="right", up="up")

    # its slots in the floor (the bottom lies centred on (0, 0), as in the world)
    floor_slots = tab_and_slot(part="slot", length=baffle_len, thickness=t, tabs=2, tab=30 mm,
                               screw=0, clearance=0.1 mm, rotation=90 deg,
                               cx=baffle_x + t / 2, cy=-depth / 2 + baffle_len / 2)
    CutInto(floor_slots, box.body.bottom)

    # its mortise in the front wall (upright, reading as seen from the front)
    hole mortise {
        m = tab_and_slot(part="slot", length=baffle_h, thickness=t, tabs=1, tab=40 mm,
                         screw=0, clearance=0.1 mm, rotation=90 deg)
    }
    mortise.bb.center_x == box.body.front.bb.left + (baffle_x + t / 2 + length / 2)
    mortise.bb.center_y == box.body.front.bb.bottom + baffle_h / 2
    CutInto(mortise, box.body.front)

    # the entrance
    hole door {
        r = Rectangle(center=(0, door_h / 4), width=door_w, height=door_h / 2)
        c = Circle(center=(0, door_h / 2), radius=door_w / 2)
    }
    door.bb.center_x == box.body.front.bb.left + (door_x + length / 2)
    door.bb.bottom == box.body.front.bb.bottom + sill
    CutInto(door, box.body.front)

    # drain holes in the feeding room's floor
    hole drain { c = Circle(center=(room_x - 60 mm, -30 mm), diameter=8 mm) }
    drains = GridPattern(drain, 2, 3, (60 mm, 60 mm))
    CutInto(drain, box.body.bottom)

    # the sign on the lid
    drawing sign {
        name = Text("HEDGEHOG CAFÉ", position=(0, 8 mm), size=24 mm, font="sans:Bold",
                    valign="middle", fill=true)
        note = Text("NO CATS", position=(0, -22 mm), size=12 mm, font="sans:Bold",
                    valign="middle", fill=true)
    }
    Rigid(sign.name, sign.note)
    AlignCenterX(sign.name, box.lid)
    sign.name.position.y - 8 mm == box.lid.bb.center_y
    CutInto(sign, box.lid)

    # the request's numbers
    assert box.body.bottom.bb.width == 400 mm, "400 mm long outside"
    assert box.body.front.bb.height + 6 mm == 200 mm, "200 mm tall with the lid on"
    assert door.bb.width == 130 mm and door.bb.height == 130 mm, "entrance 130 x 130"
    assert door.bb.bottom - box.body.front.bb.bottom == 15 mm, "sill 15 mm up"
    assert (door_x - door_w / 2) - (-length / 2 + t) == 20 mm, "entrance 20 mm from the left wall"
    assert baffle_x - (door_x + door_w / 2) == 20 mm, "baffle 20 mm right of the entrance"
    assert (depth / 2 - t) - baffle_end == 130 mm, "130 mm passage behind the baffle"
    assert len(drains) == 6, "six drain holes"
    assert sign.name.size == 24 mm and sign.note.size == 12 mm, "letter sizes"
}
