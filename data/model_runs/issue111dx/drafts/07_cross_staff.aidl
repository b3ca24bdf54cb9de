# Request (science): a cross-staff (Jacob's staff) for measuring angles in the sky,
# 6 mm birch ply, three parts.
# - Staff 520 x 24 mm. At its left end an eyepiece is glued on; a transom slides along it.
#   An angle scale engraved along the top edge of the staff's face: a tick where the
#   transom's eye-side face stands when its two tips, 200 mm apart, subtend the angle a
#   at the peep hole: x = 100 mm / tan(a / 2) from the staff's left end, for a = 25 to 90
#   deg every 5 deg; 10 mm ticks at the tens, 6 mm at the fives; the tens labelled (5 mm
#   strokes) with their middles 5 mm below the staff's centre line. "JACOB'S STAFF" in
#   5 mm strokes between 455 and 505 mm along; a 5 mm lanyard hole 10 mm from the right end.
# - Transom: two arms to sharp tips at +-100 mm (20 mm deep at their middle, tapering over
#   the last 15 mm), a 40 x 30 mm hub under them with the 24.4 x 6.4 mm hole for the staff,
#   its centre 15 mm below the tips' line.
# - Eyepiece: 40 x 44 mm, R6 corners, a 2 mm peep hole 15 mm above the staff hole's centre,
#   the same 24.4 x 6.4 mm staff hole.
# Assembled: the staff flat, the transom at the 40 deg tick.

thickness 6 mm

t = 6 mm
staff_l = 520 mm
staff_w = 24 mm
half = 100 mm
rise = 15 mm                  # sights above the staff's centre line
def d_of(a) = half / tan(a * 1 deg / 2)
angles = [25 + 5 * i for i in range(14)]      # 25 .. 90
tens = [30 + 10 * i for i in range(7)]        # 30 .. 90

assembly cross_staff {
    solid staff {
        bar = Rectangle(bottom_left=(0, -staff_w / 2), width=staff_l, height=staff_w)
        hole lanyard { c = Circle(center=(staff_l - 10, 0), diameter=5) }
        drawing scale {
            for a in angles {
                tick = Line((d_of(a), staff_w / 2), (d_of(a), staff_w / 2 - (10 mm if a % 10 == 0 else 6 mm)))
            }
            for a in tens {
                num = Text(str(a), position=(d_of(a), -5), size=5, valign="middle")
            }
            name = Text("JACOB'S STAFF", position=(480, -1), size=5, valign="middle", max_width=50 mm)
        }
        Fixed(bar)
        Fixed(scale)
    }
    Place(staff, position=(0, 0, 0), face="up")

    solid transom {
        arms = Polygon([(-half, 0), (-half + 15, 10), (half - 15, 10), (half, 0), (half - 15, -10),
                        (-half + 15, -10)])
        hub = Rectangle(center=(0, -rise - 3), width=40, height=30)
        hole staff_hole { r = Rectangle(center=(0, -rise), width=24.4, height=6.4) }
        Fixed(arms)
        Fixed(hub)
    }
    Place(transom, position=(d_of(40), 0, t / 2 + rise), face="right", up="up")

    solid eyepiece {
        plate = RoundedRectangle(center=(0, -10), width=40, height=44, corner_radius=6)
        hole peep { c = Circle(center=(0, 0), diameter=2) }
        hole staff_hole { r = Rectangle(center=(0, -rise), width=24.4, height=6.4) }
        Fixed(plate)
    }
    Place(eyepiece, position=(0, 0, t / 2 + rise), face="right", up="up")

    Below(transom, staff, gap=8)
    AlignLeft(transom, staff)
    RightOf(eyepiece, transom, gap=8)
    AlignTop(eyepiece, transom)

    assert staff.bar.bb.width == 520 mm and staff.bar.bb.height == 24 mm, "staff 520 x 24"
    assert len(staff.scale.tick) == 14, "25 to 90 deg every 5"
    assert abs(staff.scale.tick[13].start.x - 100 mm) < 0.01 mm, "90 deg at 100 mm"
    assert staff.scale.tick[0].start.x <= 455 mm - 2 mm, "the scale ends before the name"
    assert staff.scale.name.bb.left >= 455 mm and staff.scale.name.bb.right <= 505 mm, "name placed"
    assert distance(staff.scale.name, staff.lanyard) >= 2 mm, "name clear of the lanyard hole"
    assert transom.arms.bb.width == 200 mm, "tips 200 mm apart"
    assert transom.staff_hole.r.center.y - transom.arms.center.y == -15 mm, "hole 15 below the tips"
    assert eyepiece.peep.c.center.y - eyepiece.staff_hole.r.center.y == 15 mm, "peep 15 above"
}
