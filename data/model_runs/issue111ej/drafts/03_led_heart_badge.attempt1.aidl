# Request (electronics): a wearable LED heart badge, three layers of 3 mm ply glued into a
# 9 mm sandwich. The heart: two R15 lobes whose centres are 26 mm apart and 8 mm above the
# heart's middle, coming to a point 32 mm below it (56 wide, 55 tall). Front: 13 holes of
# 3.1 mm for 3 mm LEDs, 7 mm in from the edge: 5 round each lobe (at 30, 75, 120, 165, 210 deg
# about its centre, mirrored for the right one), one above the point, one midway down each
# side; the name "ADA" engraved filled in the middle (sans bold, 7 mm caps). Middle layer: a
# frame with a 4 mm wall, hollow for a CR2032 holder (a 22 mm round space in the middle)
# and the LED legs, with a 6 x 5 mm notch through the right-hand wall, 8 mm above the middle,
# for a slide switch. Back: two 2.4 mm holes 24 mm apart, 5 mm above the middle, for a brooch
# pin's rivets. The three cut side by side 5 mm apart, tops level; stacked in the 3D view.

units mm
thickness 3 mm

lobe_r = 15 mm
lobe_x = 13 mm
lobe_y = 8 mm
tip_y = -32 mm
inset = 7 mm     # LED centres in from the edge
wall = 4 mm
led_d = 3.1 mm
lobe_angles = [30, 75, 120, 165, 210]

# half the angle of the point: its sides are tangent to the lobes
tip_d = sqrt(lobe_x ** 2 + (lobe_y - tip_y) ** 2)
tip_half = atan2(lobe_x, lobe_y - tip_y) + asin(lobe_r / tip_d)

left_spots = [polar((-lobe_x, lobe_y), lobe_r - inset, a * 1 deg) for a in lobe_angles]
right_spots = [polar((lobe_x, lobe_y), lobe_r - inset, 180 deg - a * 1 deg) for a in lobe_angles]
tip_spot = (0, tip_y + inset / sin(tip_half))
side_y = (lobe_y + (lobe_r - inset) * sin(210 deg) + tip_spot[1]) / 2
side_x = (-lobe_x + (lobe_r - inset) * cos(210 deg)) / 2
spots = left_spots + right_spots + [tip_spot, (side_x, side_y), (-side_x, side_y)]

def heart_plate(r=15 mm) -> solid {
    left = Hull(Circle(center=(-lobe_x, lobe_y), radius=r), Point(0, tip_y))
    right = Hull(Circle(center=(lobe_x, lobe_y), radius=r), Point(0, tip_y))
    Rigid(self)
}

assembly badge {
    solid front {
        plate = heart_plate()
        for i in range(len(spots)) {
            hole led { c = Circle(center=spots[i], diameter=led_d) }
        }
        drawing name {
            t = Text("ADA", position=(0, -1), size=7, font="sans:Bold", valign="middle",
                     fill=true)
        }
        Rigid(self)
    }

    solid spacer {
        plate = heart_plate()
        hole cavity {
            left = Hull(Circle(center=(-lobe_x, lobe_y), radius=lobe_r - wall),
                        Point(0, tip_y + wall / sin(tip_half)))
            right = Hull(Circle(center=(lobe_x, lobe_y), radius=lobe_r - wall),
                         Point(0, tip_y + wall / sin(tip_half)))
            cell = Circle(center=(0, -2), diameter=22)
        }
        hole switch {
            r = Rectangle(center=(lobe_x + lobe_r - 2, lobe_y), width=6, height=5)
        }
        Rigid(self)
    }

    solid back {
        plate = heart_plate()
        for k in range(2) {
            hole pin { c = Circle(center=(-12 + 24 * k, 5), diameter=2.4) }
        }
        Rigid(self)
    }

    RightOf(spacer, front, gap=5)
    AlignTop(spacer, front)
    RightOf(back, spacer, gap=5)
    AlignTop(back, spacer)

    Place(back, position=(0, 0, 0), face="up")
    Place(spacer, position=(0, 0, 3), face="up")
    Place(front, position=(0, 0, 6), face="up")

    # the request's numbers
    assert len(front.led) == 13, "13 LEDs"
    assert abs(front.bb.width - 56 mm) < 0.01 mm and abs(front.bb.height - 55 mm) < 0.01 mm, "heart 56 x 55"
    assert abs(front.led[0].c.diameter - 3.1 mm) < 0.001 mm, "3.1 mm LED holes"
    assert distance(front.led[0], front.led[1]) >= 2 mm, "LEDs on a lobe 2 mm apart at least"
    assert distance(front.led[4], front.led[11]) >= 2 mm, "side LED clear of the lobe's last"
    assert distance(front.led[10], front.led[11]) >= 2 mm, "side LED clear of the point's"
    assert distance(front.name, front.led) >= 1.5 mm, "name clear of the LEDs"
    assert abs(back.pin[1].c.center.x - back.pin[0].c.center.x - 24 mm) < 0.001 mm, "pin holes 24 apart"
    assert abs(spacer.cavity.cell.diameter - 22 mm) < 0.001 mm, "22 mm cell space"
    assert abs(spacer.bb.left - front.bb.right - 5 mm) < 0.01 mm, "cut 5 mm apart"
}
