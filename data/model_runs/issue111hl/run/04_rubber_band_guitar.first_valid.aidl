# Request (toys): a rubber-band guitar for my 6-year-old, 3 mm ply. A closed finger-jointed
# box 240 x 140 x 60 mm (outside, 10 mm fingers); its lid is the soundboard: a 60 mm sound
# hole in the middle with two engraved rosette rings (68 and 72 mm), and "MAYA" filled bold,
# 10 mm high, centred 55 mm below the middle. Six bands run along the length, 16 mm apart,
# each stretched between two 6 mm dowel pegs: 12 peg holes of 6 mm, 105 mm either side of
# the middle. Two bridges (100 mm long, standing 20 mm above the lid) cross the bands 80 mm
# either side of the middle, each with six 2 x 3 mm notches on top under the bands and two
# 15 mm tabs glued into slots in the lid.

units mm
thickness 3 mm

import "std/joints.aidl"

t = 3 mm
pitch = 16 mm
bands = 6
peg_x = 105 mm
bridge_x = 80 mm
bridge_h = 20 mm

def bridge() -> solid {
    body = Rectangle(bottom_left=(-50, 0), width=100, height=bridge_h + t)
    j = tab_and_slot(part="tab", length=100 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                     rotation=180 deg, cx=0 mm, cy=0 mm)
    hole notches {
        for k in range(bands) {
            n = Rectangle(center=((k - (bands - 1) / 2) * pitch, bridge_h + t - 1.5), width=2, height=3)
        }
    }
}

assembly guitar {
    box = finger_box(length=240 mm, depth=140 mm, height=60 mm, thickness=t, finger=10 mm)

    hole lid_cuts {
        sound = Circle(center=(0, 0), diameter=60)
        sa = tab_and_slot(part="slot", length=100 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                          rotation=90 deg, cx=-bridge_x, cy=0 mm)
        sb = tab_and_slot(part="slot", length=100 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                          rotation=90 deg, cx=bridge_x, cy=0 mm)
        for k in range(bands) {
            peg_l = Circle(center=(-peg_x, (k - (bands - 1) / 2) * pitch), diameter=6)
            peg_r = Circle(center=(peg_x, (k - (bands - 1) / 2) * pitch), diameter=6)
        }
    }
    CenterInside(lid_cuts, box.lid)
    CutInto(lid_cuts, box.lid)

    drawing lid_art {
        r1 = Circle(center=(0, 0), diameter=68)
        r2 = Circle(center=(0, 0), diameter=72)
        name = Text("MAYA", (0, -55), size=10, font="sans:Bold", valign="middle", fill=true)
    }
    Concentric(lid_art.r1, lid_cuts.sound)
    CutInto(lid_art, box.lid)

    bridge_a = bridge()
    bridge_b = bridge()
    RightOf(bridge_a, box, gap=10)
    AlignBottom(bridge_a, box)
    Above(bridge_b, bridge_a, gap=5)
    AlignLeft(bridge_b, bridge_a)
    # the lid lies at (0, 210) in the net (bottom at 0, back 75..135, lid 140..280)
    Place(bridge_a, on=box.lid, position=(-bridge_x + t / 2, 210, 0), face="left", up="up")
    Place(bridge_b, on=box.lid, position=(bridge_x - t / 2, 210, 0), face="right", up="up")

    # the request's numbers
    assert box.length == 240 mm and box.depth == 140 mm and box.height == 60 mm, "box 240 x 140 x 60"
    assert lid_cuts.sound.diameter == 60 mm, "60 mm sound hole"
    assert len(lid_cuts.peg_l) == 6 and len(lid_cuts.peg_r) == 6, "12 peg holes"
    assert lid_cuts.peg_l[1].center.y - lid_cuts.peg_l[0].center.y == 16 mm, "bands 16 mm apart"
    assert lid_cuts.peg_r[0].center.x - lid_cuts.sound.center.x == 105 mm, "pegs 105 mm from the middle"
    assert lid_cuts.sound.center.x - lid_cuts.peg_l[0].center.x == 105 mm, "pegs 105 mm from the middle"
    assert lid_cuts.sb.slot[0].bb.center_x - lid_cuts.sound.center.x == 80 mm, "bridge 80 mm from the middle"
    assert lid_art.name.position.y - lid_cuts.sound.center.y == -55 mm, "name 55 mm below the middle"
    assert bridge_a.body.height - t == 20 mm, "bridge stands 20 mm"
    assert len(bridge_a.notches.n) == 6, "six notches"
    assert bridge_a.notches.n[1].center.x - bridge_a.notches.n[0].center.x == 16 mm, "notches under the bands"
    assert distance(lid_art.name, lid_cuts) >= 3 mm, "name clear of pegs and slots"
    assert distance(lid_art.r2, lid_cuts) >= 3 mm, "rosette clear of the slots"
}
