# Request (bathroom): a wall-mounted hand-towel ring, 6 mm ply, three parts.
# - wall plate 50 x 110 mm, 8 mm corner radii, two 4.5 mm holes for No.8 countersunk
#   screws (9 mm heads) on its centre line 15 mm from the top and bottom edges, and a
#   30 x 6 mm mortise (vertical) at its centre for the arm;
# - arm, seen from the side: sticks out 70 mm from the wall; 40 mm tall at the wall, its
#   top edge level, its bottom edge rising from 40 mm tall at the wall to 24 mm tall at
#   25 mm from the wall and then level to the tip; a 30 mm tenon, 6 mm long, centred on
#   its wall edge; the two tip corners rounded 4 mm;
# - ring 180 mm outside / 140 mm inside diameter, hung in the arm by a cross halving
#   55 mm from the wall: a 12 mm notch up from the arm's bottom edge and a 12 mm notch down
#   from the ring's top, so the ring's top is flush with the arm's top;
# - joints 0.2 mm loose.

import "std/joints.aidl"

units mm
thickness 6 mm

T = 6 mm
fit = 0.2 mm
reach = 70 mm
arm_tip_h = 24 mm
arm_wall_h = 40 mm
ring_out = 180 mm
ring_in = 140 mm
halving_x = 55 mm
notch = 12 mm

assembly towel_ring {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=50, height=110, corner_radius=8)
        Fixed(body)
        hole screw {
            c = Circle(center=(0, 110 / 2 - 15), diameter=4.5)
        }
        hole screw2 {
            c = Circle(center=(0, -110 / 2 + 15), diameter=4.5)
        }
        Countersink([screw, screw2], diameter=9)
        mortise = tab_and_slot(part="slot", length=arm_wall_h, thickness=T, tabs=1, tab=30 mm,
                               screw=0, clearance=fit, rotation=90 deg, cx=0, cy=0)
    }

    solid arm {
        # x: distance from the wall face (the tenon from -T to 0), y: top edge at arm_tip_h / 2
        shape = Polygon([(-T, arm_tip_h / 2), (reach, arm_tip_h / 2),
                         (reach, -arm_tip_h / 2), (25, -arm_tip_h / 2),
                         (0, arm_tip_h / 2 - arm_wall_h), (-T, arm_tip_h / 2 - arm_wall_h)])
        Fixed(shape)
        Fillet([shape.points[1], shape.points[2]], 4)
        tenon = tab_and_slot(part="tab", length=arm_wall_h, thickness=T, tabs=1, tab=30 mm,
                             screw=0, rotation=90 deg, cx=-T,
                             cy=arm_tip_h / 2 - arm_wall_h / 2)
        hang = cross_halving(depth=notch, thickness=T, clearance=fit, rotation=180 deg,
                             cx=halving_x, cy=-arm_tip_h / 2)
    }

    solid ring {
        rim = Circle(center=(0, 0), diameter=ring_out)
        Fixed(rim)
        hole bore {
            c = Circle(center=(0, 0), diameter=ring_in)
        }
        hang = cross_halving(depth=notch, thickness=T, clearance=fit, rotation=0 deg,
                             cx=0, cy=ring_out / 2)
    }

    Fixed(plate)
    RightOf(arm, plate, gap=10)
    AlignTop(arm, plate)
    RightOf(ring, arm, gap=10)
    AlignTop(ring, plate)

    assert plate.body.bb.width == 50 mm and plate.body.bb.height == 110 mm, "plate 50 x 110"
    assert abs(plate.body.bb.top - plate.screw.c.center.y - 15 mm) < 0.01 mm, "screw 15 from top"
    assert abs(plate.screw2.c.center.y - plate.body.bb.bottom - 15 mm) < 0.01 mm, "screw 15 from bottom"
    assert abs(arm.shape.bb.right - arm.tenon.gap.bb.right - 70 mm) < 0.5 mm, "arm reaches 70 mm"
    assert arm.shape.bb.height == 40 mm, "arm 40 tall at the wall"
    assert ring.rim.diameter == 180 mm and ring.bore.c.diameter == 140 mm, "ring 180 / 140"
    # the halving: arm notch top meets ring notch bottom with the ring's top flush
    assert notch + notch == arm_tip_h, "halving depths add up to the arm's height at the notch"
    assert (ring_out - ring_in) / 2 > notch, "ring band keeps material below its notch"
}
