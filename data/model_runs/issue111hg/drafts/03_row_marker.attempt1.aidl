# Request (garden): a row marker to draw seed furrows in a veg bed, from 6 mm exterior ply.
# A head 400 mm long and 60 mm tall with five teeth below it at an 80 mm pitch (centred),
# each tooth 50 mm long, 20 mm wide at the head and 6 mm at its tip. A handle that stands
# square to the head, joined to it by a cross halving 30 mm into each part (0.1 mm
# clearance): its foot is 100 x 60 mm, centred on the head, and its shaft, 32 mm wide,
# rises backwards at 45 degrees from the middle of the foot for 424 mm to a ring grip 70 mm
# across with a 40 mm hole. "ROWS" and "80 mm" engraved on the head, either side of the
# halving.

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
head_l = 400 mm
head_h = 60 mm
teeth = 5
pitch = 80 mm
tooth_l = 50 mm
shaft_l = 424 mm
shaft_angle = 45 deg
halving = 30 mm

assembly marker {
    solid head {
        body = Rectangle(center=(0, head_h / 2), width=head_l, height=head_h)
        solid tooth {
            tr = Trapezoid(center=(-(teeth - 1) * pitch / 2, -tooth_l / 2), bottom_width=6,
                           top_width=20, height=tooth_l)
        }
        row = LinearPattern(tooth, teeth, (pitch, 0))
        slot = cross_halving(depth=halving, thickness=t, clearance=0.1 mm, cx=0 mm, cy=head_h)
        drawing words {
            a = Text("ROWS", (-pitch / 2 - 20 mm, head_h / 2), size=10, valign="middle")
            b = Text("80 mm", (pitch / 2 + 20 mm, head_h / 2), size=10, valign="middle")
        }
        assert distance(words, slot) >= 10 mm, "words clear of the halving"
    }

    solid handle {
        foot = Rectangle(center=(0, head_h / 2), width=100, height=head_h)
        shaft_end = polar(Point(0, head_h / 2), shaft_l, shaft_angle)
        shaft = Rectangle(start=(0, head_h / 2), end=shaft_end, width=32)
        ring = Circle(center=shaft_end, diameter=70)
        hole grip {
            c = Circle(center=shaft_end, diameter=40)
        }
        slot = cross_halving(depth=halving, thickness=t, clearance=0.1 mm, rotation=180 deg,
                             cx=0 mm, cy=0 mm)
    }

    Below(handle, head, gap=20)
    AlignLeft(handle, head)

    Place(head, position=(0, t / 2, 0), face="front", up="up")
    Place(handle, position=(-t / 2, 0, 0), face="right", up="up")

    assert len(head.row) == 5, "five teeth"
    assert head.row[1].tr.center.x - head.row[0].tr.center.x == 80 mm, "80 mm pitch"
    assert head.body.bb.bottom - head.row[0].tr.bb.bottom == 50 mm, "teeth 50 long"
    assert head.body.bb.width == 400 mm and head.body.bb.height == 60 mm, "head size"
    assert head.slot.cut.bb.height + handle.slot.cut.bb.height == 60 mm, "halvings meet"
    assert handle.foot.bb.width == 100 mm, "foot 100"
}
