# Request: party favours for a six-year-old's fairy party, cut from 3 mm poplar ply: three
# fairy wands, each 300 mm long: a five-point star 80 mm across its tips (inner radius 18,
# tips rounded r3) with a heart-shaped window in its middle, on a 12 mm wide stick with a
# rounded end; two 3 mm holes just under the star to tie ribbons; the guest's name (AVA, MIA,
# LILY) engraved along the stick 7 mm tall, 140 mm below the star's centre. And a little
# stand to show them on the party table: a 240 x 50 top with three wand slots (stick + 0.4
# clearance) 75 mm apart (the stars are 67 wide), on two trapezoid legs (70 wide at the floor, 50 at the top, top
# 60 mm up), each leg one 30 mm tenon in a mortise of the top.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
names = ["AVA", "MIA", "LILY"]
pitch = 75 mm
stand_h = 60 mm

def wand(name="AVA") -> solid {
    star = Star(center=(0, 0), points=5, outer_radius=40, inner_radius=18, tip_radius=3)
    stick = RoundedRectangle(bottom_left=(-6, -260), width=12, height=245,
                             corner_radii=[0, 0, 6, 6])
    # 300 overall from the rounded top tip to the stick's end
    star.bb.top - stick.bb.bottom == 300 mm
    AlignCenterX(stick, star)
    hole heart {
        lobe_l = Hull(Circle(center=(-4, 2.5), radius=4.5), Point(0, -8))
        lobe_r = Hull(Circle(center=(4, 2.5), radius=4.5), Point(0, -8))
    }
    hole ribbon {
        l = Circle(center=(-10, -17), diameter=3)
        r = Circle(center=(10, -17), diameter=3)
    }
    drawing label {
        n = Text(name, position=(0, -140), size=7, rotation=90, valign="middle")
    }
}

def leg() -> solid {
    # x across the stand's depth, y up from the floor
    body = Trapezoid(center=(0, (stand_h + t) / 2), bottom_width=70, top_width=50,
                     height=stand_h + t)
    tenon = tab_and_slot(part="tab", length=50, thickness=t, tabs=1, tab=30 mm, screw=0,
                         rotation=0 deg, cx=0, cy=stand_h + t)
}

assembly fairy_wands {
    for i in range(len(names)) {
        w = wand(name=names[i])
        w.star.center.x == i * 90 mm
        w.star.center.y == 0
        Place(w, position=((i - 1) * pitch, t / 2, 260), rotation=(90 deg, 0, 0))
    }

    solid top {
        body = Rectangle(center=(0, 0), width=240, height=50)
        hole holders {
            for i in range(len(names)) {
                s = Rectangle(center=((i - 1) * pitch, 0), width=12.4, height=3.4)
            }
        }
        m_left = tab_and_slot(part="slot", length=50, thickness=t, tabs=1, tab=30 mm,
                              screw=0, rotation=90 deg, cx=-105, cy=0)
        m_right = tab_and_slot(part="slot", length=50, thickness=t, tabs=1, tab=30 mm,
                               screw=0, rotation=90 deg, cx=105, cy=0)
        Fixed(body)
        assert body.width == 240 mm and body.height == 50 mm, "top 240 x 50"
        assert holders.s[1].center.x - holders.s[0].center.x == 75 mm, "slots 75 apart"
    }
    left = leg()
    right = leg()

    # flat on the sheet
    RightOf(top, w[2], gap=10)
    AlignTop(top, w[2])
    Below(left, top, gap=10)
    AlignLeft(left, top)
    RightOf(right, left, gap=10)
    AlignTop(right, left)

    # in 3D: the stand's top at z = 60, the wands standing on the table through its slots
    Place(top, position=(0, 0, stand_h))
    Place(left, position=(-105 - t / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(right, position=(105 - t / 2, 0, 0), rotation=(90 deg, 0, 90 deg))

    assert len(w) == 3, "three wands"
    assert w[0].star.bb.top - w[0].stick.bb.bottom == 300 mm, "wand 300 long"
    assert w[0].star.outer_radius == 40 mm, "star 80 across its tips"
    assert w[0].stick.width == 12 mm, "stick 12 wide"
    assert w[0].star.center.y - w[0].label.n.position.y == 140 mm, "name 140 below the star"
    assert left.body.bottom_width == 70 mm and left.body.top_width == 50 mm, "legs 70 / 50"
}
