# Request (holidays): Swedish angel chimes (änglaspel) for the Christmas table. A base of
# two 3 mm ply discs 150 mm across glued together: the upper one with 4 holes 12.5 mm for
# the little chime candles on a 100 mm circle (at 45, 135, 225, 315 deg) and
# "GOD JUL" over the top and "& GOTT NYTT ÅR" under the bottom engraved filled, 7 mm high,
# round its rim. A post of two 3 mm ply boards 40 mm wide crossed by a halving, standing
# 160 mm above the base, each with two 8 mm tabs through both base discs. A 24 mm cap
# with a 1.2 mm hole for the pivot pin on top of the post. A rotor of 0.5 mm brass, 120 mm
# across, with 8 radial slits from 20 mm out to the rim so the blades can be twisted, a
# centre mark for the dimple, and 1.5 mm holes 52 mm out in the middle of two opposite
# blades; two angels with trumpets, 1.5 mm ply, about 50 mm tall, hanging from those holes.

import "std/joints.aidl"

t = 3 mm
thickness t

base_r = 75 mm
post_w = 40 mm
post_h = 160 mm
rotor_r = 60 mm
hub_r = 20 mm
hang_r = 52 mm
slits = 8

def base_layer(candles=false) -> solid {
    disc = Circle(center=(0, 0), radius=base_r)
    a = tab_and_slot(part="slot", length=post_w, thickness=t, tabs=2, tab=8 mm, screw=0,
                     clearance=0.1 mm, cx=0 mm, cy=0 mm)
    b = tab_and_slot(part="slot", length=post_w, thickness=t, tabs=2, tab=8 mm, screw=0,
                     clearance=0.1 mm, rotation=90 deg, cx=0 mm, cy=0 mm)
    if candles {
        for k in range(4) {
            hole candle {
                c = Circle(center=(50 * cos(45 deg + k * 90 deg), 50 * sin(45 deg + k * 90 deg)),
                           diameter=12.5)
            }
        }
        drawing greeting {
            over = Circle(center=(0, 0), radius=62, construction=true)
            under = Circle(center=(0, 0), radius=69, construction=true)
            top = Text("GOD JUL", along=over, size=7, font="serif", fill=true)
            bottom = Text("& GOTT NYTT ÅR", along=under, flip=true, size=7, font="serif",
                          fill=true)
        }
    }
}

def angel() -> solid {
    thickness 1.5 mm
    body = Trapezoid(center=(0, -20), bottom_width=26, top_width=8, height=34)
    # FIX after the first valid program: the head only touched the body's top (W0515, W0519);
    # it now overlaps it by 1 mm
    head = Circle(center=(0, 2), radius=6)
    lwing = Ellipse(center=(-10, -10), rx=12, ry=6, rotation=30 deg)
    rwing = Ellipse(center=(10, -10), rx=12, ry=6, rotation=-30 deg)
    horn = Rectangle(start=(3, -3), end=(19, 5), width=2.5)
    bell = Polygon([(17, 3), (24, 11), (26, 2)])
    hole eye {
        h = Circle(center=(0, 6), diameter=1.5)
    }
}

assembly chimes {
    bottom = base_layer()
    upper = base_layer(candles=true)

    # FIX after the first valid program: y = 0 is the tabs' tips, not their shoulders (no
    # message named it: assembled, the posts stood on their tips on the base, 6 mm high, and
    # only 154 mm above it); the boards grow by the tabs' 6 mm and stand at z = 0
    solid post_a {
        board = Rectangle(bottom_left=(-post_w / 2, 0), width=post_w, height=post_h + 2 * t)
        feet = tab_and_slot(part="tab", length=post_w, thickness=2 * t, tabs=2, tab=8 mm,
                            screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
        halving = cross_halving(depth=post_h / 2 + t, thickness=t, clearance=0.1 mm,
                                cx=0 mm, cy=post_h + 2 * t)
    }
    solid post_b {
        board = Rectangle(bottom_left=(-post_w / 2, 0), width=post_w, height=post_h + 2 * t)
        feet = tab_and_slot(part="tab", length=post_w, thickness=2 * t, tabs=2, tab=8 mm,
                            screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
        halving = cross_halving(depth=post_h / 2 + t, thickness=t, clearance=0.1 mm,
                                rotation=180 deg, cx=0 mm, cy=0 mm)
    }
    solid cap {
        disc = Circle(center=(0, 0), diameter=24)
        hole pin { p = Circle(center=(0, 0), diameter=1.2) }
    }
    solid rotor {
        thickness 0.5 mm
        disc = Circle(center=(0, 0), radius=rotor_r)
        cut blades {
            for k in range(slits) {
                s = Line(polar((0, 0), hub_r, k * 360 deg / slits),
                         polar((0, 0), rotor_r + 1 mm, k * 360 deg / slits))
            }
        }
        hole hang {
            a = Circle(center=polar((0, 0), hang_r, 180 deg / slits), diameter=1.5)
            b = Circle(center=polar((0, 0), hang_r, 180 deg + 180 deg / slits), diameter=1.5)
        }
        drawing mark {
            h = Line((-3, 0), (3, 0))
            v = Line((0, -3), (0, 3))
        }
    }
    angel1 = angel()
    angel2 = angel()

    # sheet layout
    RightOf(upper, bottom, gap=5)
    AlignBottom(upper, bottom)
    RightOf(post_a, upper, gap=5)
    AlignBottom(post_a, upper)
    RightOf(post_b, post_a, gap=5)
    AlignBottom(post_b, post_a)
    Above(rotor, bottom, gap=5)
    AlignLeft(rotor, bottom)
    RightOf(cap, rotor, gap=5)
    AlignBottom(cap, rotor)
    RightOf(angel1, cap, gap=5)
    AlignBottom(angel1, cap)
    RightOf(angel2, angel1, gap=5)
    AlignBottom(angel2, angel1)

    # assembled
    top_z = 2 * t + post_h
    rotor_z = top_z + t + 10 mm      # on the pin's point, 10 mm above the cap
    Place(bottom, position=(0, 0, 0))
    Place(upper, position=(0, 0, t))
    Place(post_a, position=(0, t / 2, 0), face="front", up="up")
    Place(post_b, position=(-t / 2, 0, 0), face="right", up="up")
    Place(cap, position=(0, 0, top_z))
    Place(rotor, position=(0, 0, rotor_z))
    Place(angel1, position=(hang_r * cos(22.5 deg), hang_r * sin(22.5 deg), rotor_z - 36 mm),
          face="front", up="up")
    Place(angel2, position=(-hang_r * cos(22.5 deg), -hang_r * sin(22.5 deg), rotor_z - 36 mm),
          face="front", up="up")

    assert bottom.disc.radius * 2 == 150 mm
    assert len(upper.candle) == 4 and upper.candle[0].c.diameter == 12.5 mm
    assert abs(distance(upper.candle[0].c.center, upper.disc.center) - 50 mm) < 0.001 mm,
        "candles on a 100 mm circle"
    assert post_a.board.bb.top - post_a.feet.gap[1].bb.top == 160 mm, "160 mm above the base"
    assert post_a.board.width == 40 mm
    assert post_a.halving.depth + post_b.halving.depth == post_a.board.height, "the halvings meet"
    assert rotor.disc.radius * 2 == 120 mm and len(rotor.blades.s) == 8
    assert abs(distance(rotor.hang.a.center, rotor.disc.center) - 52 mm) < 0.001 mm
    assert cap.disc.diameter == 24 mm and cap.pin.p.diameter == 1.2 mm
    assert angel1.bb.height >= 45 mm and angel1.bb.height <= 55 mm, "about 50 mm tall"
    assert distance(upper.greeting, upper.candle[0]) >= 2 mm and
        distance(upper.greeting, upper.candle[1]) >= 2 mm, "words clear of the candles"
}
