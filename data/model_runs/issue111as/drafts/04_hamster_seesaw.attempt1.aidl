# Request (pets): a seesaw for a hamster cage, 4 mm birch ply, glued. A plank 200 x 60 mm with
# 10 mm rounded corners, with nine engraved grip lines across it (50 mm long, 20 mm apart,
# centred). Under the plank's middle a keel 60 mm long is glued in by two 12 mm tabs; it hangs
# a 6.4 mm axle hole (for a 6 mm dowel) 15 mm below the plank. The pivot: two supports 50 mm
# long at the foot, rounded over the axle (8 mm radius about it), the axle 22 mm above the
# base, each glued into the base by two 12 mm tabs; they stand either side of the keel with
# 3 mm between each support and the keel. The base is 140 x 70 mm with 5 mm rounded corners and
# the hamster's name "NIBBLES" engraved as filled bold letters 10 mm tall, centred 25 mm in
# front of its middle. Assembled in 3D; the plank must tip no more than 25 degrees before its
# end touches the base.

import "std/joints.aidl"

thickness 4 mm

mat = 4 mm
param axle_h = 22 mm, min = 15 mm, max = 40 mm
param drop = 15 mm, min = 10 mm, max = 25 mm
axle_d = 6.4 mm
side_gap = 3 mm
support_y = mat / 2 + side_gap + mat / 2    # the supports' middles either side of the keel

assembly seesaw {
    solid plank {
        deck = RoundedRectangle(center=(0, 0), width=200, height=60, corner_radius=10)
        m = tab_and_slot(part="slot", length=60 mm, thickness=mat, tabs=2, tab=12 mm, screw=0,
                         clearance=0.2 mm, cx=0 mm, cy=0 mm)
        drawing grip {
            for i in range(9) {
                l = Line(((i - 4) * 20 mm, -25 mm), ((i - 4) * 20 mm, 25 mm))
            }
        }
    }

    # the keel in its own frame: y = 0 is the plank's underside, its tabs reach y = mat
    solid keel {
        body = Hull(Circle(center=(0, -drop), radius=8), Rectangle(center=(0, mat / 2), width=60, height=mat))
        t = tab_and_slot(part="tab", length=60 mm, thickness=mat, tabs=2, tab=12 mm, screw=0,
                         cx=0 mm, cy=mat)
        hole axle {
            c = Circle(center=(0, -drop), diameter=axle_d)
        }
    }

    # a support in its own frame: y = 0 is the base's top, its tabs reach down to y = -mat
    def support() -> solid {
        body = Hull(Circle(center=(0, axle_h), radius=8), Rectangle(center=(0, -mat / 2), width=50, height=mat))
        t = tab_and_slot(part="tab", length=50 mm, thickness=mat, tabs=2, tab=12 mm, screw=0,
                         rotation=180 deg, cx=0 mm, cy=-mat)
        hole axle {
            c = Circle(center=(0, axle_h), diameter=axle_d)
        }
    }
    left = support()
    right = support()

    solid base {
        plate = RoundedRectangle(center=(0, 0), width=140, height=70, corner_radius=5)
        ma = tab_and_slot(part="slot", length=50 mm, thickness=mat, tabs=2, tab=12 mm, screw=0,
                          clearance=0.2 mm, cx=0 mm, cy=support_y)
        mb = tab_and_slot(part="slot", length=50 mm, thickness=mat, tabs=2, tab=12 mm, screw=0,
                          clearance=0.2 mm, cx=0 mm, cy=-support_y)
        drawing name {
            n = Text("NIBBLES", position=(0, -25), size=10, font="sans:Bold", valign="middle", fill=true)
        }
    }

    # on the sheet
    Below(base, plank, gap=8)
    AlignLeft(base, plank)
    RightOf(keel, base, gap=8)
    AlignTop(keel, base)
    RightOf(left, keel, gap=8)
    AlignTop(left, keel)
    Below(right, left, gap=8)
    AlignLeft(right, left)

    # assembled: base on z = 0, supports and keel stood up ((x, y, z) -> (x, -z, y))
    Place(base, position=(0, 0, 0))
    Place(left, rotation=(90 deg, 0, 0), position=(0, support_y + mat / 2, mat))
    Place(right, rotation=(90 deg, 0, 0), position=(0, -support_y + mat / 2, mat))
    Place(keel, rotation=(90 deg, 0, 0), position=(0, mat / 2, mat + axle_h + drop))
    Place(plank, position=(0, 0, mat + axle_h + drop))

    # the request's numbers
    assert plank.deck.bb.width == 200 mm and plank.deck.bb.height == 60 mm, "plank 200 x 60"
    assert len(plank.grip.l) == 9, "nine grip lines"
    assert plank.grip.l[1].start.x - plank.grip.l[0].start.x == 20 mm, "grip lines 20 mm apart"
    assert plank.grip.l[0].length == 50 mm, "grip lines 50 mm long"
    assert keel.body.bb.width == 60 mm, "keel 60 mm long"
    assert keel.t.bb.top - keel.axle.c.center.y == 15 mm + mat, "axle 15 mm below the plank"
    assert left.axle.c.center.y - (left.t.bb.bottom + mat) == 22 mm, "axle 22 mm above the base"
    assert left.body.bb.width == 50 mm, "supports 50 mm at the foot"
    assert left.body.bb.top - left.axle.c.center.y == 8 mm, "rounded 8 mm over the axle"
    assert support_y - mat == 3 mm, "3 mm between support and keel"
    assert base.plate.bb.width == 140 mm and base.plate.bb.height == 70 mm, "base 140 x 70"
    assert abs(base.name.n.position.y - base.plate.bb.center_y + 25 mm) < 0.01 mm, "name 25 mm in front"
    assert asin((axle_h + drop) / (plank.deck.bb.width / 2)) <= 25 deg, "tips at most 25 degrees"
}
