# Request: a flat-pack toy carousel (merry-go-round) in 3 mm ply, no glue. A 200 mm base
# disc and a canopy (a 200 mm disc with 16 scallops of R12 round its edge, "CAROUSEL"
# engraved over the top) held 150 mm apart by a central post of two 60 mm wide plates
# cross-halved into each other, each with two 12 mm tabs into each disc. Three horses on
# 8 mm wide poles stand tangentially on a 70 mm circle at 30, 150 and 270 deg, each pole with
# a 4 mm tab into the base and into the canopy, galloping counter-clockwise; each horse about
# 70 mm nose to tail with an engraved eye. An engraved ring 8 mm in from the base's edge.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
gap = 150 mm                 # clear height between the discs
post_h = gap + 2 * t         # tab tips flush with the outer faces of both discs
ring_r = 70 mm
angles = [30 deg, 150 deg, 270 deg]

def horse_piece() -> solid {
    pole = Rectangle(center=(0, post_h / 2), width=8, height=post_h)
    top_tab = tab_and_slot(part="tab", length=8 mm, thickness=t, tabs=1, tab=4 mm, screw=0,
                           cx=0 mm, cy=post_h)
    foot_tab = tab_and_slot(part="tab", length=8 mm, thickness=t, tabs=1, tab=4 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=0 mm)
    body = Ellipse(center=(0, 80), rx=24, ry=11)
    neck = Rectangle(center=(22, 93), width=10, height=26, rotation=-30 deg)
    head = Ellipse(center=(31, 105), rx=11, ry=5.5, rotation=-30 deg)
    ear = Triangle(center=(25, 112), base=5, height=7, rotation=10 deg)
    front_leg = Slot(start=(16, 74), end=(27, 60), width=5)
    front_leg2 = Slot(start=(12, 74), end=(15, 57), width=5)
    hind_leg = Slot(start=(-16, 74), end=(-27, 60), width=5)
    hind_leg2 = Slot(start=(-12, 74), end=(-13, 57), width=5)
    tail = Slot(start=(-21, 84), end=(-34, 72), width=5)
    drawing face {
        eye = Circle(center=(33, 107), radius=1.3, fill=true)
    }
}

def post(from_top=true) -> solid {
    plate = Rectangle(center=(0, post_h / 2), width=60, height=post_h)
    top_tabs = tab_and_slot(part="tab", length=60 mm, thickness=t, tabs=2, tab=12 mm, screw=0,
                            cx=0 mm, cy=post_h)
    foot_tabs = tab_and_slot(part="tab", length=60 mm, thickness=t, tabs=2, tab=12 mm, screw=0,
                             rotation=180 deg, cx=0 mm, cy=0 mm)
    if from_top {
        halving = cross_halving(depth=post_h / 2, thickness=t, cx=0 mm, cy=post_h)
    } else {
        halving = cross_halving(depth=post_h / 2, thickness=t, rotation=180 deg, cx=0 mm,
                                cy=0 mm)
    }
}

def disc_mortises() -> hole {
    post_x = tab_and_slot(part="slot", length=60 mm, thickness=t, tabs=2, tab=12 mm, screw=0,
                          cx=0 mm, cy=0 mm)
    post_y = tab_and_slot(part="slot", length=60 mm, thickness=t, tabs=2, tab=12 mm, screw=0,
                          rotation=90 deg, cx=0 mm, cy=0 mm)
    for a in angles {
        pole = tab_and_slot(part="slot", length=8 mm, thickness=t, tabs=1, tab=4 mm, screw=0,
                            rotation=a + 90 deg, cx=ring_r * cos(a), cy=ring_r * sin(a))
    }
}

assembly carousel {
    solid base {
        disc = Circle(center=(0, 0), diameter=200)
        m = disc_mortises()
        drawing trim {
            ring = Circle(center=(0, 0), radius=100 - 8)
        }
        Fixed(disc)
    }

    solid canopy {
        disc = Circle(center=(0, 0), diameter=200)
        bump = Circle(center=(100, 0), radius=12)
        scallops = CircularPattern(bump, 16, (0, 0))
        m = disc_mortises()
        drawing title {
            arc = Circle(center=(0, 0), radius=ring_r, construction=true)
            word = Text("CAROUSEL", along=arc, size=10)
        }
        Fixed(disc)
    }

    post_a = post(from_top=true)
    post_b = post(from_top=false)

    for i in range(3) {
        horse = horse_piece()
        horse.bb.left == base.bb.right + 10 + i * 85
        AlignBottom(horse, base)
        Place(horse, position=((ring_r - t / 2) * cos(angles[i]),
                               (ring_r - t / 2) * sin(angles[i]), 0),
              face=(cos(angles[i]), sin(angles[i]), 0), up="up")
    }

    # flat on the sheet
    RightOf(canopy, horse[2], gap=10)
    AlignBottom(canopy, base)
    LeftOf(post_a, base, gap=10)
    AlignBottom(post_a, base)
    LeftOf(post_b, post_a, gap=10)
    AlignBottom(post_b, base)

    # in 3D
    Place(base, position=(0, 0, 0))
    Place(canopy, position=(0, 0, t + gap))
    Place(post_a, position=(0, t / 2, 0), face="front", up="up")
    Place(post_b, position=(-t / 2, 0, 0), face="right", up="up")

    assert base.disc.diameter == 200 mm and canopy.disc.diameter == 200 mm
    assert len(canopy.scallops) == 16 and canopy.bump.radius == 12 mm
    assert post_a.plate.height - 2 * t == 150 mm, "150 mm between the discs"
    assert post_a.plate.width == 60 mm
    assert len(horse) == 3
    assert horse[0].pole.width == 8 mm
    assert horse[0].bb.width >= 60 mm and horse[0].bb.width <= 80 mm, "about 70 nose to tail"
    assert base.bb.width == 200 mm
}
