# Request (toys): a slot-together toy lighthouse for my nephew, 4 mm poplar ply.
# Two profiles cross-halved into each other (slots 4.2 mm wide, one from the top, one
# from the bottom, each half the height). Each profile: a tower tapering from 80 mm wide
# at the bottom to 50 mm at 150 mm up, a gallery deck 70 wide x 8 mm on it, a lantern
# room 40 wide x 27 mm with two 10 x 16 mm window panes, and a domed roof of 20 mm radius:
# 205 mm tall in all. Two 6 x 12 mm windows in each tower (at 45 and 105 mm up, off the
# middle), an arched door 12 wide x 20 high (3 mm above the bottom) in the second profile,
# and engraved lines across the tower at 30, 60, 90 and 120 mm up to paint red stripes
# between. Each profile stands on two 10 mm tabs, 4 mm long, 25 mm either side of the
# middle, in a 120 mm round base with 10.2 x 4.2 mm mortises and "ROCK POINT LIGHT"
# engraved round its rim. A 76 mm gallery disc with a cross-shaped opening (arms 41 x 4.4)
# slides down over the lantern to rest on the deck.

units mm
thickness 4 mm

import "std/joints.aidl"

t = 4 mm
slot_w = 4.2 mm
H = 205 mm

def half_w(y) = 40 mm - y * 0.1

def profile(from_top=true) -> solid {
    tower = Polygon([(-40, 0), (40, 0), (25, 150), (-25, 150)])
    deck = Rectangle(bottom_left=(-35, 150), width=70, height=8)
    lantern = Rectangle(bottom_left=(-20, 158), width=40, height=27)
    dome = Circle(center=(0, 185), radius=20)
    tab_l = Rectangle(bottom_left=(-30, -4), width=10, height=4)
    tab_r = Rectangle(bottom_left=(20, -4), width=10, height=4)
    hole panes {
        l = Rectangle(center=(-11, 171), width=10, height=16)
        r = Rectangle(center=(11, 171), width=10, height=16)
    }
    if from_top {
        halving = cross_halving(depth=H / 2, thickness=4 mm, clearance=0.2 mm, cx=0, cy=H)
        hole windows {
            w1 = Slot(center=(-15, 45), length=12, width=6, rotation=90)
            w2 = Slot(center=(15, 105), length=12, width=6, rotation=90)
        }
    } else {
        halving = cross_halving(depth=H / 2, thickness=4 mm, clearance=0.2 mm,
                                rotation=180 deg, cx=0, cy=0)
        hole windows {
            w1 = Slot(center=(15, 45), length=12, width=6, rotation=90)
            w2 = Slot(center=(-15, 105), length=12, width=6, rotation=90)
        }
        hole door {
            r = Rectangle(bottom_left=(-26, 3), width=12, height=14)
            c = Circle(center=(-20, 17), radius=6)
        }
    }
    drawing stripes {
        for k in range(4) {
            left = Line((-half_w((k + 1) * 30 mm), (k + 1) * 30 mm), (-3, (k + 1) * 30 mm))
            right = Line((3, (k + 1) * 30 mm), (half_w((k + 1) * 30 mm), (k + 1) * 30 mm))
        }
    }
    assert dome.center.y + dome.radius - tower.bb.bottom == 205 mm, "205 mm tall"
    assert tower.bb.width == 80 mm, "80 mm at the bottom"
    assert lantern.width == 40 mm and lantern.height == 27 mm, "lantern 40 x 27"
    assert tab_r.bb.center_x == 25 mm and tab_l.bb.center_x == -25 mm, "tabs 25 mm out"
}

assembly lighthouse {
    front = profile(from_top=true)
    side = profile(from_top=false)

    solid base {
        disc = Circle(center=(0, 0), diameter=120)
        hole mortises {
            a1 = Rectangle(center=(-25, 0), width=10.2, height=4.2)
            a2 = Rectangle(center=(25, 0), width=10.2, height=4.2)
            b1 = Rectangle(center=(0, -25), width=4.2, height=10.2)
            b2 = Rectangle(center=(0, 25), width=4.2, height=10.2)
        }
        drawing name {
            ring = Circle(center=(0, 0), radius=44, construction=true)
            n = Text("ROCK POINT LIGHT", along=ring, size=7)
        }
        Fixed(disc)
        assert disc.diameter == 120 mm, "120 mm base"
    }

    solid gallery {
        disc = Circle(center=(0, 0), diameter=76)
        hole cross {
            a = Rectangle(center=(0, 0), width=41, height=4.4)
            b = Rectangle(center=(0, 0), width=4.4, height=41)
        }
        Fixed(disc)
    }

    RightOf(side, front, gap=10 mm)
    AlignBottom(side, front)
    RightOf(base, side, gap=10 mm)
    AlignBottom(base, front)
    Above(gallery, base, gap=10 mm)
    AlignCenterX(gallery, base)

    assert front.halving.depth + side.halving.depth == 205 mm, "halvings meet"
}
