# Request (holidays): a Ramadan lantern (fanous) for an LED tealight, 3 mm plywood.
# A square lantern 100 x 100 outside, 200 tall between a base and a top plate, each plate
# 130 x 130 with R10 corners. Four walls (front and back 100 wide, the two sides 94 wide
# between them) stand on the base and carry the top, each with two 20 mm tenons at the bottom
# into the base and two at the top into the top plate (the top lifts off for the tealight).
# Each wall has a pointed (equilateral) arch window 60 wide, its sill 25 mm up, the arch
# springing at 100 mm, to be backed with tracing paper; above it a crescent (outer R15, inner
# R13 offset 6 mm, opening to the right) with a 5-point star (R5 / R2) in its mouth, centred
# 175 mm up. The top plate has an 8-point star vent (R25 / R15) in the middle and two 4 mm
# cord holes 32 mm either side of it. RAMADAN KAREEM engraved filled, 7 mm tall, on the base's
# front margin.

import "std/joints.aidl"

thickness 3 mm
t = 3 mm

side = 100 mm
h = 200 mm
plate = 130 mm
win_w = 60 mm
sill = 25 mm
spring = 100 mm
moon_y = 175 mm
r1 = 15 mm
r2 = 13 mm
d = 6 mm
# where the crescent's two circles cross (its tips)
xi = (d ** 2 + r1 ** 2 - r2 ** 2) / (2 * d)
yi = sqrt(r1 ** 2 - xi ** 2)

def wall(w=100 mm) -> solid {
    # frame: y = 0 the base's top face, the tenons' tips at -t and h + t
    body = Rectangle(bottom_left=(-w / 2, -t), width=w, height=h + 2 * t)
    feet = tab_and_slot(part="tab", length=w, thickness=t, tabs=2, tab=20 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=-t)
    heads = tab_and_slot(part="tab", length=w, thickness=t, tabs=2, tab=20 mm, screw=0,
                         cx=0 mm, cy=h + t)
    hole window {
        arch = Intersect(Circle(center=(-win_w / 2, spring), radius=win_w),
                         Circle(center=(win_w / 2, spring), radius=win_w),
                         Rectangle(bottom_left=(-win_w / 2, spring), width=win_w, height=win_w))
        jamb = Rectangle(bottom_left=(-win_w / 2, sill), width=win_w, height=spring - sill)
    }
    hole moon {
        outer = Arc(start=(xi, moon_y + yi), through=(-r1, moon_y), end=(xi, moon_y - yi))
        inner = Arc(start=(xi, moon_y - yi), through=(d - r2, moon_y), end=(xi, moon_y + yi))
        star = Star(center=(9 mm, moon_y), points=5, outer_radius=5, inner_radius=2)
    }
}

def plate_mortises() -> hole {
    front = tab_and_slot(part="slot", length=side, thickness=t, tabs=2, tab=20 mm, screw=0,
                         cx=0 mm, cy=-side / 2 + t / 2)
    back = tab_and_slot(part="slot", length=side, thickness=t, tabs=2, tab=20 mm, screw=0,
                        cx=0 mm, cy=side / 2 - t / 2)
    left = tab_and_slot(part="slot", length=side - 2 * t, thickness=t, tabs=2, tab=20 mm,
                        screw=0, rotation=90 deg, cx=-side / 2 + t / 2, cy=0 mm)
    right = tab_and_slot(part="slot", length=side - 2 * t, thickness=t, tabs=2, tab=20 mm,
                         screw=0, rotation=90 deg, cx=side / 2 - t / 2, cy=0 mm)
}

assembly ramadan_lantern {
    solid base {
        p = RoundedRectangle(center=(0, 0), width=plate, height=plate, corner_radius=10)
        m = plate_mortises()
        drawing greeting {
            g = Text("RAMADAN KAREEM", position=(0, -(plate + side) / 4), size=7, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }
    solid top {
        p = RoundedRectangle(center=(0, 0), width=plate, height=plate, corner_radius=10)
        m = plate_mortises()
        hole vent {
            s = Star(center=(0, 0), points=8, outer_radius=25, inner_radius=15)
            cord_l = Circle(center=(-32, 0), diameter=4)
            cord_r = Circle(center=(32, 0), diameter=4)
        }
    }
    front = wall(w=side)
    back = wall(w=side)
    left = wall(w=side - 2 * t)
    right = wall(w=side - 2 * t)

    # flat on the sheet: the walls in a row, the plates above
    RightOf(back, front, gap=6)
    AlignBottom(back, front)
    RightOf(left, back, gap=6)
    AlignBottom(left, back)
    RightOf(right, left, gap=6)
    AlignBottom(right, left)
    Above(base, front, gap=6)
    AlignLeft(base, front)
    RightOf(top, base, gap=6)
    AlignBottom(top, base)

    # in 3D
    Place(base, position=(0, 0, 0))
    Place(front, position=(0, -side / 2 + t, t), face="front", up="up")
    Place(back, position=(0, side / 2 - t, t), face="back", up="up")
    Place(right, position=(side / 2 - t, 0, t), face="right", up="up")
    Place(left, position=(-side / 2 + t, 0, t), face="left", up="up")
    Place(top, position=(0, 0, t + h))

    assert front.body.bb.width == 100 mm and left.body.bb.width == 94 mm, "walls 100 and 94"
    assert front.body.bb.height - 2 * 3 mm == 200 mm, "200 between the plates"
    assert base.p.bb.width == 130 mm and base.p.bb.height == 130 mm, "plates 130 x 130"
    assert front.window.bb.width == 60 mm, "window 60 wide"
    assert front.window.jamb.bb.bottom - (front.body.bb.bottom + 3 mm) == 25 mm, "sill 25 up"
    assert abs(front.window.bb.top - (front.body.bb.bottom + 3 mm) - (100 mm + 60 mm * sqrt(3) / 2))
           < 0.01 mm, "equilateral arch springing at 100"
    assert front.window.bb.top <= front.moon.bb.bottom - 5 mm, "crescent clear of the arch"
    assert front.moon.bb.top <= front.body.bb.top - 3 mm - 8 mm, "crescent clear of the top"
    assert distance(front.moon.star, front.moon.outer) >= 2 mm and
        distance(front.moon.star, front.moon.inner) >= 2 mm, "star clear of the crescent"
    assert len(base.m.front.slot) == 2 and base.m.front.slot[0].bb.width == 20 mm,
        "two 20 mm tenons"
    assert top.vent.s.outer_radius == 25 mm and top.vent.cord_r.center.x == 32 mm, "vent, cords"
    assert base.greeting.bb.top <= base.m.front.slot[0].bb.bottom - 2 mm, "greeting in the margin"
}
