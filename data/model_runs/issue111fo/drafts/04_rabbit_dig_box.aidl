# Request: a dig box for two house rabbits, in 9 mm ply. An open-top finger-jointed box,
# outside 450 mm long x 300 mm deep x 250 mm tall, 30 mm fingers. In the front, a 160 mm
# round entrance, its centre 100 mm left of the middle and its lowest point 50 mm above the
# bottom edge (so the soil stays in); right of it "DIG" engraved filled (bold sans, 60 mm)
# with "BUNNY BURROW" (16 mm) under it. A loose lid 470 x 320 (R15 corners, overhanging
# 10 mm all round) with a 3 x 7 grid of 12 mm air holes at 50 mm pitch in the middle and two
# 100 x 28 mm hand slots running front to back, centred 200 mm either side of the middle.
# Under the lid, two cleats 400 x 30 glued just inside the front and back walls (centred
# 125 mm from the middle) keep it from sliding off.

import "std/joints.aidl"

thickness 9 mm

T = 9 mm
L = 450 mm
D = 300 mm
H = 250 mm

assembly dig_box {
    box = finger_box(length=L, depth=D, height=H, thickness=T, finger=30 mm, closed=false)

    hole door {
        c = Circle(center=(0, 0), diameter=160)
    }
    door.c.center.x == box.front.bb.center_x - 100 mm
    door.c.bb.bottom == box.front.bb.bottom + 50 mm
    CutInto(door, box.front)

    drawing sign {
        word = Text("DIG", position=(0, 0), size=60, font="sans:Bold", valign="middle", fill=true)
        sub = Text("BUNNY BURROW", position=(0, -55), size=16, font="sans:Bold", valign="middle",
                   fill=true)
    }
    sign.word.position.x == box.front.bb.center_x + 100 mm
    sign.word.position.y == door.c.center.y + 15 mm
    CutInto(sign, box.front)

    solid lid {
        board = RoundedRectangle(center=(0, 0), width=L + 20 mm, height=D + 20 mm, corner_radius=15)
        hole air {
            a = Circle(center=(-150, -50), diameter=12)
        }
        vents = GridPattern(air, 3, 7, 50)
        hole hands {
            left = Slot(center=(-200, 0), length=100, width=28, rotation=90 deg)
            right = Slot(center=(200, 0), length=100, width=28, rotation=90 deg)
        }
    }

    solid cleat_front { r = Rectangle(center=(0, 0), width=400, height=30) }
    solid cleat_back { r = Rectangle(center=(0, 0), width=400, height=30) }

    # flat on the sheet: the lid and cleats right of the box's net
    RightOf(lid, box, gap=20)
    AlignTop(lid, box)
    Below(cleat_front, lid, gap=10)
    AlignLeft(cleat_front, lid)
    Below(cleat_back, cleat_front, gap=10)
    AlignLeft(cleat_back, lid)

    # in 3D: the lid on the walls' tops, the cleats under it inside the front and back walls
    Place(lid, position=(0, 0, H), face="up")
    Place(cleat_front, position=(0, -125, H - T), face="up")
    Place(cleat_back, position=(0, 125, H - T), face="up")

    assert door.c.diameter == 160 mm, "160 mm entrance"
    assert door.c.bb.bottom - box.front.bb.bottom == 50 mm, "50 mm sill"
    assert box.front.bb.center_x - door.c.center.x == 100 mm, "entrance 100 left of the middle"
    assert distance(sign, door) >= 10 mm, "the words clear the entrance"
    assert sign.bb.right <= box.front.bb.right - 15 mm, "the words on the front"
    assert lid.board.width == 470 mm and lid.board.height == 320 mm, "lid 470 x 320"
    assert len(vents) == 21, "3 x 7 air holes"
    assert vents[1].a.center.x - vents[0].a.center.x == 50 mm, "50 mm pitch"
    assert lid.hands.right.center.x - lid.board.center.x == 200 mm, "hand slots 200 from the middle"
    assert distance(lid.hands, vents[6]) >= 15 mm, "hand slots clear of the air holes"
}
