# Request (camping): a flat-pack fire pit to have laser-cut from 3 mm mild steel. Four side
# panels 420 x 300 mm that cross-halve into a square: two have slots from the top, two from
# the bottom, 40 mm in from each end, 150 mm deep, 3.5 mm wide (0.5 mm clearance). Each
# panel: a shallow arch cut from the bottom edge (220 mm wide, 25 mm high) so it stands on
# two feet, a row of four pine-tree cut-outs (each 60 mm wide, 110 mm tall, 70 mm apart)
# across the middle and three 5-pointed stars (20 mm across) above them. The two top-slotted
# panels also get two 11 mm holes, 220 mm apart and 60 mm above the ground, for two 10 mm
# rods that carry a 320 x 320 mm grate with 35 air slots (40 x 8 mm, 7 rows x 5 columns).

units mm
thickness 3 mm

import "std/joints.aidl"

t = 3 mm
pw = 420 mm
ph = 300 mm
slot_in = 40 mm
clear = 0.5 mm
rod_h = 60 mm
rod_x = 110 mm

def tree(x0=0 mm) -> hole {
    tier1 = Triangle(center=(x0, -15), base=60, height=40)
    tier2 = Triangle(center=(x0, 12), base=48, height=36)
    tier3 = Triangle(center=(x0, 38), base=34, height=30)
    trunk = Rectangle(center=(x0, -45), width=10, height=20)
}

def panel(top=true) -> solid {
    body = Rectangle(center=(0, 0), width=pw, height=ph)
    if top {
        hl = cross_halving(depth=ph / 2, thickness=t, clearance=clear, cx=-pw / 2 + slot_in, cy=ph / 2)
        hr = cross_halving(depth=ph / 2, thickness=t, clearance=clear, cx=pw / 2 - slot_in, cy=ph / 2)
        hole rods {
            l = Circle(center=(-rod_x, -ph / 2 + rod_h), diameter=11)
            r = Circle(center=(rod_x, -ph / 2 + rod_h), diameter=11)
        }
    } else {
        hl = cross_halving(depth=ph / 2, thickness=t, clearance=clear, rotation=180 deg,
                           cx=-pw / 2 + slot_in, cy=-ph / 2)
        hr = cross_halving(depth=ph / 2, thickness=t, clearance=clear, rotation=180 deg,
                           cx=pw / 2 - slot_in, cy=-ph / 2)
    }
    hole arch {
        e = Ellipse(center=(0, -ph / 2), rx=110, ry=25)
    }
    for i in range(4) {
        pine = tree(x0=(i - 1.5) * 70 mm)
    }
    hole sky {
        for k in range(3) {
            s = Star(center=((k - 1) * 70 mm, 95), points=5, outer_radius=10, inner_radius=4)
        }
    }
}

assembly fire_pit {
    front = panel(top=true)
    back = panel(top=true)
    left = panel(top=false)
    right = panel(top=false)
    solid grate {
        plate = Rectangle(center=(0, 0), width=320, height=320)
        hole air {
            a = Slot(center=(-110, -120), length=40, width=8)
        }
        vents = GridPattern(air, 7, 5, col_spacing=55, row_spacing=40)
        Fixed(plate)
    }
    # laid out flat for cutting
    RightOf(back, front, gap=10)
    AlignBottom(back, front)
    Below(left, front, gap=10)
    AlignLeft(left, front)
    RightOf(right, left, gap=10)
    AlignBottom(right, left)
    RightOf(grate, back, gap=10)
    AlignTop(grate, back)

    # assembled: the slot centres make a square of pw - 2 * slot_in
    sq = pw - 2 * slot_in
    Place(front, position=(0, -sq / 2 + t / 2, ph / 2), face="front", up="up")
    Place(back, position=(0, sq / 2 - t / 2, ph / 2), face="back", up="up")
    Place(left, position=(-sq / 2 + t / 2, 0, ph / 2), face="left", up="up")
    Place(right, position=(sq / 2 - t / 2, 0, ph / 2), face="right", up="up")
    Place(grate, position=(0, 0, rod_h + 5 mm))

    # the request's numbers
    assert front.body.width == 420 mm and front.body.height == 300 mm, "panels 420 x 300"
    assert front.hl.cut.bb.height == 150 mm and left.hl.cut.bb.height == 150 mm, "150 mm deep halvings"
    assert front.hl.cut.bb.width == 3.5 mm, "3.5 mm slots"
    assert front.hl.cut.bb.center_x - front.body.bb.left == 40 mm, "40 mm in from the end"
    assert front.body.bb.right - front.hr.cut.bb.center_x == 40 mm, "40 mm in from the end"
    assert front.arch.e.rx * 2 == 220 mm and front.arch.e.ry == 25 mm, "arch 220 x 25"
    assert len(front.pine) == 4, "four trees"
    assert front.pine[0].tier1.base == 60 mm, "trees 60 mm wide"
    assert front.pine[0].tier3.bb.top - front.pine[0].trunk.bb.bottom == 110 mm, "trees 110 mm tall"
    assert front.pine[1].tier1.center.x - front.pine[0].tier1.center.x == 70 mm, "trees 70 mm apart"
    assert front.rods.r.center.x - front.rods.l.center.x == 220 mm, "rods 220 mm apart"
    assert front.rods.l.center.y - front.body.bb.bottom == 60 mm, "rods 60 mm up"
    assert len(grate.vents) == 35, "35 air slots"
    assert grate.plate.width <= sq - t - 2 * clear, "grate fits between the panels"
    for i in range(4) {
        assert distance(front.pine[i], front.hl) >= 10 mm and distance(front.pine[i], front.hr) >= 10 mm,
            "trees clear of the slots"
        assert distance(left.pine[i], left.arch) >= 10 mm, "trees clear of the arch"
    }
    assert distance(front.rods, front.arch) >= 10 mm, "rod holes clear of the arch"
}
