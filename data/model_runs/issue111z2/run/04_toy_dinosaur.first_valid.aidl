# Toys: a cross-halved toy dinosaur (a long-necked sauropod), 3 mm plywood, three parts.
# Coordinates of the body as it stands: ground at y = 0, body centre at x = 0.
# Body (side profile): an oval 100 x 44 mm centred 45 mm up, with a flat belly 60 mm long at
# 23 mm above the ground (the hull of the oval and the belly line); a neck 14 mm wide (round
# ends) from (-35, 55) to (-68, 98); a head, an oval 24 x 14 mm centred at (-72, 102), with a
# 4 mm eye hole at (-76, 104); a tail tapering from the body's back (x = 35, y 34..52) to a tip
# at (100, 30), the tip rounded R3. Two cross-halving slots up into the belly, 6 mm deep,
# 25 mm each side of the centre. Two identical leg pieces (front view): 60 wide x 35 tall,
# two legs 15 wide with an arch 30 wide x 20 high between them (top corners R8), and a 6 mm
# deep cross-halving slot down from the middle of the top edge; 6 + 6 = the 12 mm the legs
# reach into the body. Slots 3 mm + 0.1 mm clearance. Parts laid side by side, 8 mm apart.

units mm
thickness 3 mm

import "std/joints.aidl"

def legs() -> solid {
    block = Rectangle(center=(0, 17.5), width=60, height=35)
    hole arch {
        a = RoundedRectangle(center=(0, 9), width=30, height=20, corner_radii=[8, 8, 0, 0],
                             overrun=true)
    }
    slot = cross_halving(depth=6 mm, thickness=3 mm, clearance=0.1 mm, cx=0 mm, cy=35 mm)
}

assembly dino {
    solid body {
        torso = Hull(Ellipse(center=(0, 45), rx=50, ry=22),
                     Rectangle(center=(0, 24), width=60, height=2))
        neck = Slot(start=(-35, 55), end=(-68, 98), width=14)
        head = Ellipse(center=(-72, 102), rx=12, ry=7)
        tail = Polygon([(35, 52), (35, 34), (100, 30)])
        hole eye {
            e = Circle(center=(-76, 104), diameter=4)
        }
        front_slot = cross_halving(depth=6 mm, thickness=3 mm, clearance=0.1 mm,
                                   rotation=180 deg, cx=-25 mm, cy=23 mm)
        back_slot = cross_halving(depth=6 mm, thickness=3 mm, clearance=0.1 mm,
                                  rotation=180 deg, cx=25 mm, cy=23 mm)
        Fillet(tail.points[2], 3)
    }
    front = legs()
    back = legs()
    RightOf(front, body, gap=8)
    AlignBottom(front, body)
    RightOf(back, front, gap=8)
    AlignBottom(back, front)

    assert body.torso.bb.bottom == 23 mm, "belly 23 mm above the ground"
    assert body.front_slot.depth + front.slot.depth == 12 mm, "slots add up to the 12 mm overlap"
    assert front.block.bb.width == 60 mm and front.block.bb.height == 35 mm, "leg piece 60 x 35"
    assert body.back_slot.cx - body.front_slot.cx == 50 mm, "slots 25 mm each side of the centre"
    assert body.tail.points[2].x == 100 mm, "tail tip at x = 100"
}
