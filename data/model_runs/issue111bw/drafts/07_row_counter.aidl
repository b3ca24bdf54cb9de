# Request (crafts): "A knitting row counter, 3 mm cherry ply, that counts 0 to 99: a back
# plate and a front plate, each 90 x 42 mm with 10 mm corners, sandwich two 40 mm digit
# wheels (tens on the left, units on the right) turning on M3 screws 42 mm apart (3.2 mm
# holes in the plates, 3.4 mm in the wheels), 9 mm below the plates' centre so that each
# wheel sticks out 8 mm below the plates' bottom edge for the thumb. Each wheel has the digits
# 0 to 9 engraved filled, bold, 6 mm, on a 14 mm radius, each upright when at the top, and
# 20 grip notches (3 mm round) round its rim. The front plate has an 8 x 9 mm window over
# each wheel's top digit and 'ROWS' engraved filled, bold, 5 mm, centred between the windows'
# tops and the plate's top edge; both plates have a 5 mm hole for a lanyard in the top left
# corner, 8 mm from the top and left edges."

thickness 3 mm

pivot_x = 21 mm
digit_r = 14 mm
def digit_angle(i) = 90 deg - i * 36 deg

def wheel() -> solid {
    disc = Circle(center=(0, 0), diameter=40)
    hole pivot { c = Circle(center=(0, 0), diameter=3.4) }
    hole notches {
        for k in range(20) {
            n = Circle(center=(20 * cos(k * 18 deg), 20 * sin(k * 18 deg)), diameter=3)
        }
    }
    drawing digits {
        for i in range(10) {
            t = Text(str(i), position=(digit_r * cos(digit_angle(i)), digit_r * sin(digit_angle(i))),
                     size=6, font="sans:Bold", valign="middle", fill=true,
                     rotation=digit_angle(i) - 90 deg)
        }
    }
}

# both plates in one frame: the pivots at (-21, 0) and (21, 0), the plate's centre 9 mm above
def plate(front=false) -> solid {
    body = RoundedRectangle(center=(0, 9), width=90, height=42, corner_radius=10)
    hole pivots {
        tens = Circle(center=(-pivot_x, 0), diameter=3.2)
        units = Circle(center=(pivot_x, 0), diameter=3.2)
    }
    hole lanyard { c = Circle(center=(-37, 22), diameter=5) }
    if front {
        hole windows {
            tens = Rectangle(center=(-pivot_x, digit_r), width=8, height=9)
            units = Rectangle(center=(pivot_x, digit_r), width=8, height=9)
        }
        drawing label {
            t = Text("ROWS", position=(0, 24), size=5, font="sans:Bold", valign="middle",
                     fill=true)
        }
        # centred between the windows' tops and the plate's top edge
        label.t.position.y == (windows.tens.bb.top + body.bb.top) / 2
    }
}

assembly counter {
    back = plate(front=false)
    front = plate(front=true)
    tens = wheel()
    units = wheel()

    # laid out flat in a row
    RightOf(front, back, gap=6)
    AlignBottom(front, back)
    Below(tens, back, gap=6)
    AlignLeft(tens, back)
    RightOf(units, tens, gap=6)
    AlignTop(units, tens)

    # assembled, as written: back, the wheels on their pivots, front
    Place(back, position=(0, 0, 0))
    Place(tens, position=(-21, 0, 3))
    Place(units, position=(21, 0, 3))
    Place(front, position=(0, 0, 6))

    # the request's numbers
    assert back.body.bb.width == 90 mm and back.body.bb.height == 42 mm, "plates 90 x 42"
    assert front.pivots.units.center.x - front.pivots.tens.center.x == 42 mm, "pivots 42 apart"
    assert front.body.bb.center_y - front.pivots.tens.center.y == 9 mm, "pivots 9 below centre"
    assert front.pivots.tens.diameter == 3.2 mm and tens.pivot.c.diameter == 3.4 mm, "M3 holes"
    assert tens.disc.diameter == 40 mm, "40 mm wheels"
    # the wheel's bottom 8 mm below the plate's (in the assembled frame, as written)
    assert tens.disc.radius - (back.pivots.tens.center.y - back.body.bb.bottom) == 8 mm, "8 mm for the thumb"
    assert len(units.digits.t) == 10, "digits 0 to 9"
    assert abs(distance(units.digits.t[3].position, units.disc.center) - 14 mm) < 0.001 mm, "r 14"
    assert len(tens.notches.n) == 20, "20 notches"
    assert front.windows.units.width == 8 mm and front.windows.units.height == 9 mm, "windows"
    assert abs(front.windows.units.center.y - front.pivots.units.center.y - digit_r) < 0.001 mm, "window over the top digit"
    assert abs(front.label.t.position.y - (front.windows.tens.bb.top + front.body.bb.top) / 2) < 0.001 mm, "ROWS centred above"
    assert front.body.bb.top - front.lanyard.c.center.y == 8 mm, "lanyard 8 from the top"
    assert front.lanyard.c.center.x - front.body.bb.left == 8 mm, "lanyard 8 from the left"
}
