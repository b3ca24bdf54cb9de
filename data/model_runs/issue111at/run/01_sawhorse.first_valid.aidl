# Request (workshop): a knock-down benchtop sawhorse from 6 mm birch ply, three parts that
# slot together with cross-halving joints, no glue. The beam is 450 x 90 mm with "MAX LOAD
# 80 KG" engraved along it and two halving slots cut up from its bottom edge, 45 mm deep,
# their centre lines 70 mm in from each end. Two identical legs, each an isosceles trapezoid
# 320 mm wide at the floor, 110 mm at the top, 260 mm tall, with a halving slot 45 mm deep down
# from the middle of the top edge and a semicircular arch of radius 80 mm cut out of the middle
# of the bottom edge so it stands on two feet. Slots are 6 mm + 0.2 mm clearance wide.

import "std/joints.aidl"

thickness 6 mm

param ply = 6 mm, min = 3 mm, max = 12 mm
param fit = 0.2 mm, min = 0 mm, max = 0.5 mm

beam_len = 450 mm
beam_h = 90 mm
slot_in = 70 mm

def leg() -> solid {
    body = Trapezoid(center=(0, 0), bottom_width=320, top_width=110, height=260)
    h = cross_halving(depth=45 mm, thickness=ply, clearance=fit, cx=0 mm, cy=130 mm)
    hole arch {
        c = Circle(center=(0, -130), radius=80)
    }
}

assembly sawhorse {
    solid beam {
        body = Rectangle(center=(0, 0), width=beam_len, height=beam_h)
        h1 = cross_halving(depth=45 mm, thickness=ply, clearance=fit, rotation=180 deg,
                           cx=-beam_len / 2 + slot_in, cy=-beam_h / 2)
        h2 = cross_halving(depth=45 mm, thickness=ply, clearance=fit, rotation=180 deg,
                           cx=beam_len / 2 - slot_in, cy=-beam_h / 2)
        drawing label {
            t = Text("MAX LOAD 80 KG", (0, 10), size=12, valign="middle")
        }
    }
    left = leg()
    right = leg()
    Below(left, beam, gap=10)
    AlignLeft(left, beam)
    RightOf(right, left, gap=10)
    AlignTop(right, left)

    # the request's numbers
    assert beam.body.bb.width == 450 mm, "beam 450 long"
    assert beam.body.bb.height == 90 mm, "beam 90 tall"
    assert abs(beam.h1.cut.bb.center_x - beam.body.bb.left - 70 mm) < 0.01 mm, "slot 70 in from the left end"
    assert abs(beam.body.bb.right - beam.h2.cut.bb.center_x - 70 mm) < 0.01 mm, "slot 70 in from the right end"
    assert beam.h1.depth + left.h.depth == 90 mm, "halvings meet: depths add to the beam height"
    assert left.body.bb.height == 260 mm, "leg 260 tall"
    assert left.body.bb.width == 320 mm, "leg 320 at the floor"
    assert left.arch.c.radius == 80 mm, "arch radius 80"
    assert abs(beam.h1.cut.bb.width - 6.2 mm) < 0.001 mm, "slot 6.2 wide"
}
