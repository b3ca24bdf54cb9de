# Request: a pretend campfire for the kids' indoor tent. A 120 x 120 x 45 mm finger-jointed box
# (3 mm ply, 10 mm fingers, closed) hides a battery LED tealight; its lid has a 38 mm hole in
# the middle for the light and four 10.2 x 3.2 mm slots, 35 mm from the centre on both axes,
# for the flames' tabs. Two flames of 3 mm orange acrylic stand crossed on the lid: flame A
# (100 wide, a centre tip 130 high, tongues at the sides) and flame B (twin tips, 125 high,
# a dip in the middle 90 high), each with two 10 x 3 mm tabs at +-35 under its 90 mm base,
# cross-halved at the centre: A slotted 45 mm up from its base, B 45 mm down from its dip,
# slots 3.2 wide. "CAMP ROSIE" engraved filled, 10 mm bold letters, on the box's front.

units mm
thickness 3 mm

import "std/joints.aidl"

assembly campfire {
    box = finger_box(length=120 mm, depth=120 mm, height=45 mm, thickness=3 mm, finger=10 mm,
                     closed=true)

    hole lid_cuts {
        light = Circle(center=(0, 0), diameter=38)
        sa1 = Rectangle(center=(-35, 0), width=10.2, height=3.2)
        sa2 = Rectangle(center=(35, 0), width=10.2, height=3.2)
        sb1 = Rectangle(center=(0, -35), width=3.2, height=10.2)
        sb2 = Rectangle(center=(0, 35), width=3.2, height=10.2)
    }
    CenterInside(lid_cuts, box.lid)
    CutInto(lid_cuts, box.lid)

    drawing name {
        t = Text("CAMP ROSIE", position=(0, 0), size=10, font="sans:Bold", valign="middle",
                 fill=true)
    }
    CenterInside(name, box.front)
    CutInto(name, box.front)

    solid flame_a {
        body = Spline([(-45, 0), (45, 0), (48, 30), (38, 60), (42, 85), (25, 75), (14, 105),
                       (6, 130), (-8, 100), (-22, 112), (-26, 80), (-44, 55), (-48, 25)],
                      closed=true, corners=[0, 1, 4, 7, 9])
        solid tabs {
            t1 = Rectangle(center=(-35, -1.5), width=10, height=3)
            t2 = Rectangle(center=(35, -1.5), width=10, height=3)
        }
        slot = cross_halving(depth=45 mm, thickness=3 mm, clearance=0.2 mm, rotation=180 deg,
                             cx=0 mm, cy=0 mm)
    }

    solid flame_b {
        body = Spline([(-45, 0), (45, 0), (47, 30), (40, 65), (30, 125), (16, 95), (0, 90),
                       (-16, 100), (-28, 125), (-40, 70), (-47, 30)],
                      closed=true, corners=[0, 1, 4, 6, 8])
        solid tabs {
            t1 = Rectangle(center=(-35, -1.5), width=10, height=3)
            t2 = Rectangle(center=(35, -1.5), width=10, height=3)
        }
        slot = cross_halving(depth=45 mm, thickness=3 mm, clearance=0.2 mm, cx=0 mm, cy=90 mm)
    }

    # flat for cutting: the flames beside the box's net
    RightOf(flame_a, box, gap=10)
    AlignTop(flame_a, box)
    Below(flame_b, flame_a, gap=10)
    AlignLeft(flame_b, flame_a)

    # assembled: the flames stand crossed on the lid (its top at z = 45), tabs in the slots
    Place(flame_a, position=(0, 1.5 mm, 45 mm), face="front", up="up")
    Place(flame_b, position=(-1.5 mm, 0, 45 mm), face="right", up="up")

    assert box.lid.bb.width == 120 mm, "box 120 wide"
    assert lid_cuts.light.diameter == 38 mm, "38 mm light hole"
    assert lid_cuts.sa2.center.x - lid_cuts.sa1.center.x == 70 mm, "flame A slots at +-35"
    assert lid_cuts.sb2.center.y - lid_cuts.sb1.center.y == 70 mm, "flame B slots at +-35"
    assert flame_a.tabs.t2.center.x - flame_a.tabs.t1.center.x == 70 mm, "A's tabs at +-35"
    assert flame_b.tabs.t2.center.x - flame_b.tabs.t1.center.x == 70 mm, "B's tabs at +-35"
    assert flame_a.body.points[7].y == 130 mm, "A's tip 130 high"
    assert flame_b.body.points[6].y == 90 mm, "B's dip 90 high"
    assert flame_a.slot.cut.bb.height == 45 mm and flame_b.slot.cut.bb.height == 45 mm,
        "45 mm halvings"
    assert flame_a.slot.cut.bb.height + flame_b.slot.cut.bb.height == flame_b.body.points[6].y,
        "halvings add up to B's height at the crossing"
    assert flame_a.body.bb.width <= 114 mm and flame_b.body.bb.width <= 114 mm,
        "flames stand within the lid"
}
