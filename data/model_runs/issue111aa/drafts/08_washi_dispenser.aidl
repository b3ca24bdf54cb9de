# Request (crafts): a washi tape dispenser from 3 mm plywood, glued, four parts:
# - two side plates 90 mm deep x 80 mm tall (their bottom edge at the base's underside),
#   top corners R30, an 8 mm hole for a dowel axle 40 mm above the underside, centred in
#   the depth; two 20 mm tabs along the bottom into the base; a 3 x 6 mm mortise for the
#   cutter bar's tenon, its centre 8 mm in from the front edge and 56 mm above the underside.
#   "WASHI" engraved in serif, 8 mm high, on the left side plate, 15 mm above the underside.
# - base 120 x 90 mm, corners R5, mortises for the sides, whose middles stand 6 mm in from
#   the base's ends (105 mm clear between the sides).
# - cutter bar: 105 mm between the sides, 12 mm tall, with a 3 x 6 mm tenon through each
#   side, and a serrated top edge: teeth 3 mm pitch, 2 mm high, across the full 105 mm.
# Rolls up to 60 mm across must clear the base and the cutter bar by at least 5 mm.

units mm
thickness 3 mm
import "std/joints.aidl"

t = 3 mm
depth = 90 mm
side_h = 80 mm
base_w = 120 mm
side_in = 6 mm
clear = base_w - 2 * side_in - t
axle_y = 40 mm
bar_h = 12 mm
pitch = 3 mm
teeth = 35
roll_d = 60 mm

def side_plate() -> solid {
    body = RoundedRectangle(center=(0, side_h / 2), width=depth, height=side_h,
                            corner_radii=[30, 30, 0, 0])
    tabs = tab_and_slot(part="tab", length=depth, thickness=t, tabs=2, tab=20 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    hole axle {
        c = Circle(center=(0, axle_y), diameter=8)
    }
    hole mortise {
        r = Rectangle(center=(depth / 2 - 8, 56), width=t, height=6)
    }
}

assembly dispenser {
    side_l = side_plate()
    side_r = side_plate()

    solid base {
        body = RoundedRectangle(center=(0, 0), width=base_w, height=depth, corner_radius=5)
        left = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=20 mm, screw=0,
                            rotation=90 deg, cx=-base_w / 2 + side_in, cy=0 mm)
        right = tab_and_slot(part="slot", length=depth, thickness=t, tabs=2, tab=20 mm, screw=0,
                             rotation=90 deg, cx=base_w / 2 - side_in, cy=0 mm)
    }

    solid cutter {
        bar = Rectangle(center=(0, 0), width=clear, height=bar_h)
        tenon_l = Rectangle(center=(-clear / 2 - t / 2, 0), width=t, height=6)
        tenon_r = Rectangle(center=(clear / 2 + t / 2, 0), width=t, height=6)
        for i in range(teeth) {
            tooth = Triangle(center=(-clear / 2 + pitch / 2 + i * pitch, bar_h / 2 + 0.75),
                             base=pitch, height=2.5)
        }
    }

    drawing brand {
        word = Text("WASHI", position=(0, 15), size=8, font="serif", valign="middle")
    }
    CutInto(brand, side_l)
    AlignCenterX(brand, side_l.body)
    brand.word.position.y == side_l.body.bb.bottom + 15

    RightOf(side_r, side_l, gap=10)
    AlignBottom(side_r, side_l)
    Below(base, side_l, gap=10)
    AlignLeft(base, side_l)
    Below(cutter, base, gap=10)
    AlignLeft(cutter, base)

    # the request's numbers
    assert side_l.body.width == 90 mm and side_l.body.height == 80 mm, "sides 90 x 80"
    assert side_l.axle.c.diameter == 8 mm, "8 mm axle"
    assert side_l.axle.c.center.y - side_l.body.bb.bottom == 40 mm, "axle 40 mm up"
    assert side_l.body.bb.right - side_l.mortise.r.center.x == 8 mm, "mortise 8 mm in from the front"
    assert side_l.mortise.r.center.y - side_l.body.bb.bottom == 56 mm, "mortise 56 mm up"
    assert base.body.width == 120 mm and base.body.height == 90 mm, "base 120 x 90"
    assert base.right.slot[0].center.x - base.left.slot[0].center.x - 3 mm == 105 mm, "105 mm between the sides"
    assert cutter.bar.width == 105 mm, "cutter 105 mm between the sides"
    assert len(cutter.tooth) * 3 mm == 105 mm, "teeth across the full 105 mm at 3 mm pitch"
    assert cutter.tooth[0].bb.top - cutter.bar.bb.top == 2 mm, "teeth 2 mm high"
    assert axle_y - roll_d / 2 - 3 mm >= 5 mm, "roll clears the base"
    assert (side_l.mortise.r.center.x - t / 2) - (side_l.axle.c.center.x + 60 mm / 2) >= 5 mm, "roll clears the cutter"
}
