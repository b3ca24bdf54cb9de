# Request: an over-door wreath hanger for a 40 mm thick front door, cut from 3 mm clear acrylic
# and bent with a strip heater. A 25 mm wide strip with round ends:
# - a 38 mm tab down the back of the door, then a 90 deg bend (2 mm inside radius) onto the
#   door top, a 36 mm bridge across it, a second 90 deg bend (2 mm) down the front;
# - the front strip runs 240 mm straight down the door, then a 25 mm lip bent 120 deg outward
#   (3 mm inside radius) is the hook the wreath hangs on;
# - on the front strip, 48 mm below the top of its straight part, a 70 mm medallion with a
#   5-point star 36 mm tip-circle cut through (tip up, its centre 4 mm above the medallion's)
#   and "NOËL" engraved filled below it in bold serif 8 mm high (baseline middle 19 mm below
#   the medallion's centre), inside an engraved ring 2.5 mm in from the medallion's edge.
# Everything on the front must read upright to someone facing the door.

thickness 3 mm

t = 3 mm
door = 40 mm
w = 25 mm
r1 = 2 mm
r3 = 3 mm
b1 = (pi / 2) * (r1 + t / 2)             # a 90 deg bend's length on the flat sheet
b3 = (120 / 180 * pi) * (r3 + t / 2)     # the hook's 120 deg bend
tab = 38 mm
bridge = door - 2 * r1
front = 240 mm
lip = 25 mm
x_bend1 = tab + b1 / 2
x_bend2 = tab + b1 + bridge + b1 / 2
x_front = tab + 2 * b1 + bridge          # the front strip's straight part starts here
x_bend3 = x_front + front + b3 / 2
total = x_front + front + b3 + lip
mx = x_front + 48 mm                     # the medallion's centre (down the door = +x)

assembly wreath_hanger {
    solid hanger {
        strip = RoundedRectangle(bottom_left=(0, -w / 2), width=total, height=w, corner_radius=w / 2)
        medallion = Circle(center=(mx, 0), diameter=70)
        # the star's tip points up the door, which is -x on the flat strip
        hole star { s = Star(center=(mx - 4 mm, 0), points=5, outer_radius=18, inner_radius=7.5,
                             rotation=90 deg) }
        drawing deco {
            ring = Circle(center=(mx, 0), radius=35 - 2.5)
            word = Text("NOËL", position=(mx + 19 mm, 0), size=8, font="serif:Bold", fill=true,
                        valign="middle", rotation=90 deg)
        }
        Fixed(strip)
    }

    # in 3D: the door's top at z = 0, its front face at y = -20, back face at y = +20; the tab
    # hangs down the back (its top face looking back, the strip's +x up), the bends carry the
    # rest over the top and down the front (top face out, front)
    Place(hanger, position=(0, door / 2, -(tab + r1)), face="back", up="right")
    Bend(hanger, at=x_bend1, angle=-90 deg, radius=r1)
    Bend(hanger, at=x_bend2, angle=-90 deg, radius=r1)
    Bend(hanger, at=x_bend3, angle=120 deg, radius=r3)

    assert hanger.strip.bb.height == 25 mm, "25 mm strip"
    assert tab == 38 mm and bridge == 36 mm and front == 240 mm and lip == 25 mm, "the strip's lengths"
    assert hanger.medallion.diameter == 70 mm, "70 mm medallion"
    assert hanger.medallion.center.x - x_front == 48 mm, "48 below the front's top"
    assert hanger.star.s.outer_radius * 2 == 36 mm, "36 mm star"
    assert hanger.medallion.center.x - hanger.star.s.center.x == 4 mm, "star 4 above the centre"
    assert hanger.deco.word.position.x - hanger.medallion.center.x == 19 mm, "NOËL 19 below"
    assert hanger.medallion.radius - hanger.deco.ring.radius == 2.5 mm, "ring 2.5 in"
    # the word stays inside the ring and clear of the star
    assert hanger.deco.word.bb.right <= hanger.medallion.center.x + hanger.deco.ring.radius - 2 mm, "word inside the ring"
    assert hanger.deco.word.bb.left >= hanger.star.bb.right + 2 mm, "word clear of the star"
}
