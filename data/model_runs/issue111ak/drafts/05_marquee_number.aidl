# Parties: a free-standing marquee "30" for a 30th birthday table, 6 mm ply, three parts:
# - the digits "3" and "0", each 300 mm tall, drawn as bands 60 mm wide: the "0" an
#   elliptical ring 200 mm wide (outer semi-axes 100 x 150, inner 40 x 90), the "3" two
#   round-ended bowls (centre-line radii 48 mm and 54 mm) meeting in the middle;
#   12 mm holes along the bands' centre lines for a string of fairy-light bulbs:
#   16 in the "0", 17 in the "3"; each digit stands on a 60 mm wide flat shoulder with
#   one 40 mm tenon glued into the base;
# - a base plank 480 x 100 mm with the two mortises, the digits 230 mm apart centre to
#   centre, and "HAPPY BIRTHDAY" engraved 14 mm tall along its front half.

units mm
thickness 6 mm

import "std/joints.aidl"

t = 6 mm
band = 60 mm
digit_h = 300 mm
bulb = 12 mm
pitch = 230 mm     # digit centre to digit centre
up_c = 72 mm       # the 3's upper bowl centre above the digit's middle
up_r = 48 mm
lo_c = -66 mm
lo_r = 54 mm

def shoulder_and_tenon() -> solid {
    block = Rectangle(corner=(-30, -digit_h / 2 - t), opposite=(30, -digit_h / 2 + 15))
    tenon = tab_and_slot(part="tab", length=60 mm, thickness=t, tabs=1, tab=40 mm, screw=0,
                         rotation=180 deg,
                         cx=0, cy=-digit_h / 2 - t)
}

assembly marquee {
    solid three {
        upper = Stroke(Arc(center=(0, up_c), radius=up_r, start_angle=-90 deg,
                           end_angle=150 deg), width=band, cap="round")
        lower = Stroke(Arc(center=(0, lo_c), radius=lo_r, start_angle=-150 deg,
                           end_angle=90 deg), width=band, cap="round")
        # FIX after the first valid program: the two round caps met at the 3's middle with a
        # notch between them (a lumpy tongue); a hull of the two caps gives it one straight,
        # round-ended tongue.
        tongue = Hull(Circle(center=(0, up_c - up_r), radius=band / 2),
                      Circle(center=(0, lo_c + lo_r), radius=band / 2))
        foot = shoulder_and_tenon()
        hole bulbs {
            for i in range(8) {
                u = Circle(center=polar((0, up_c), up_r, 150 deg - i * 30 deg), diameter=bulb)
                l = Circle(center=polar((0, lo_c), lo_r, 60 deg - i * 30 deg), diameter=bulb)
            }
            m = Circle(center=(-4, 6), diameter=bulb)
        }
    }

    solid zero {
        ring = Ellipse(center=(0, 0), rx=100, ry=150)
        hole counter { e = Ellipse(center=(0, 0), rx=40, ry=90) }
        foot = shoulder_and_tenon()
        hole bulbs {
            for i in range(16) {
                b = Circle(center=(70 * cos(i * 22.5 deg), 120 * sin(i * 22.5 deg)),
                           diameter=bulb)
            }
        }
    }

    solid base {
        plank = Rectangle(center=(0, 0), width=480, height=100)
        left_mortise = tab_and_slot(part="slot", length=60 mm, thickness=t, tabs=1, tab=40 mm,
                                    screw=0, cx=-pitch / 2, cy=15)
        right_mortise = tab_and_slot(part="slot", length=60 mm, thickness=t, tabs=1,
                                     tab=40 mm, screw=0, cx=pitch / 2, cy=15)
        drawing wish {
            w = Text("HAPPY BIRTHDAY", position=(0, -25), size=14, valign="middle")
        }
        Fillet(plank, 6)
    }

    RightOf(zero, three, gap=pitch - 100 - 84)
    AlignBottom(zero, three)
    Below(base, three, gap=15)
    base.plank.center.x == (three.foot.block.center.x + zero.foot.block.center.x) / 2

    assert three.bb.height - 6 mm == 300 mm and zero.bb.height - 6 mm == 300 mm,
        "digits 300 mm tall"
    assert zero.ring.bb.width == 200 mm, "0 is 200 mm wide"
    assert zero.ring.rx - zero.counter.e.rx == 60 mm and zero.ring.ry - zero.counter.e.ry == 60 mm,
        "bands 60 mm"
    assert len(zero.bulbs.b) == 16, "16 bulbs in the 0"
    assert len(three.bulbs.u) + len(three.bulbs.l) + 1 == 17, "17 bulbs in the 3"
    assert zero.foot.block.center.x - three.foot.block.center.x == 230 mm, "230 mm apart"
    assert base.right_mortise.cx - base.left_mortise.cx == 230 mm, "mortises 230 mm apart"
    assert base.plank.width == 480 mm and base.plank.height == 100 mm, "base 480 x 100"
    assert zero.foot.block.width == 60 mm, "60 mm shoulder"
}
