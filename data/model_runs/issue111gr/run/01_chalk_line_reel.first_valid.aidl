# Request: a refillable chalk-line reel for my workshop, cut from 6 mm birch ply and glued
# up as a stack, bolted through with four M4 bolts. The case is a teardrop: an 84 mm circle
# round the spool hulled with a 24 mm nose circle whose centre is 60 mm ahead (to the right).
# Stack, bottom to top: a left side plate (6.5 mm axle hole, engraved "CHALK LINE" and
# "30 m"), two spacer frames (a 60 mm spool chamber and a 3 mm line channel out through the
# tip of the nose), a right side plate (6.5 mm axle hole and a 12 mm chalk filler hole,
# 22 mm from the axle, straight up). The four M4 holes go through all four layers at 36 mm
# from the axle, at 45, 135, 225 and 315 deg. Inside, a spool of 3 mm ply on a 6 mm dowel:
# two 54 mm flanges and a 30 mm hub between them (6 mm holes, glued). Outside, a 6 mm crank
# arm: 18 mm boss and 14 mm knob 45 mm apart, a 6 mm hole in each (dowel and handle peg).

import "std/fasteners.aidl"

t = 6 mm
thickness t

def case_plate(label=false, fill=false) -> solid {
    disc = Circle(center=(0, 0), diameter=84)
    nose = Circle(center=(60, 0), diameter=24)
    body = Hull(disc, nose)
    hole axle { c = Circle(center=(0, 0), diameter=6.5) }
    for i in range(4) {
        bolt = clearance_hole(size=4, cx=36 * cos(45 deg + i * 90 deg),
                              cy=36 * sin(45 deg + i * 90 deg))
    }
    if fill {
        hole filler { c = Circle(center=(0, 22), diameter=12) }
    }
    if label {
        drawing words {
            name = Text("CHALK LINE", position=(0, 12), size=6)
            length = Text("30 m", position=(0, -22), size=5)
        }
    }
}

def spacer_frame() -> solid {
    disc = Circle(center=(0, 0), diameter=84)
    nose = Circle(center=(60, 0), diameter=24)
    body = Hull(disc, nose)
    hole chamber {
        c = Circle(center=(0, 0), diameter=60)
        channel = Rectangle(bottom_left=(25, -1.5), width=52, height=3, overrun=true)
    }
    for i in range(4) {
        bolt = clearance_hole(size=4, cx=36 * cos(45 deg + i * 90 deg),
                              cy=36 * sin(45 deg + i * 90 deg))
    }
}

def spool_disc(d=54 mm) -> solid {
    thickness 3 mm
    disc = Circle(center=(0, 0), diameter=d)
    hole bore { c = Circle(center=(0, 0), diameter=6) }
}

def crank_arm() -> solid {
    boss = Circle(center=(0, 0), diameter=18)
    knob = Circle(center=(45, 0), diameter=14)
    arm = Hull(boss, knob)
    hole dowel { c = Circle(center=(0, 0), diameter=6) }
    hole peg { c = Circle(center=(45, 0), diameter=6) }
}

assembly reel {
    left = case_plate(label=true)
    spacer_a = spacer_frame()
    spacer_b = spacer_frame()
    right = case_plate(fill=true)
    flange_a = spool_disc(d=54 mm)
    hub = spool_disc(d=30 mm)
    flange_b = spool_disc(d=54 mm)
    crank = crank_arm()

    # flat on the sheet: case layers in two rows, spool and crank in a column at the right
    RightOf(right, left, gap=4)
    AlignCenterY(right, left)
    Below(spacer_a, left, gap=4)
    AlignLeft(spacer_a, left)
    RightOf(spacer_b, spacer_a, gap=4)
    AlignCenterY(spacer_b, spacer_a)
    RightOf(flange_a, right, gap=4)
    AlignTop(flange_a, right)
    Below(flange_b, flange_a, gap=4)
    AlignLeft(flange_b, flange_a)
    RightOf(hub, flange_a, gap=4)
    AlignTop(hub, flange_a)
    Below(crank, hub, gap=4)
    AlignLeft(crank, hub)

    # glued up: left plate face down (engraving outside), nose kept toward +x
    Place(left, position=(0, 0, t), face="down", up="front")
    Place(spacer_a, position=(0, 0, t))
    Place(spacer_b, position=(0, 0, 2 * t))
    Place(right, position=(0, 0, 3 * t))
    Place(flange_a, position=(0, 0, t + 1.5 mm))
    Place(hub, position=(0, 0, t + 4.5 mm))
    Place(flange_b, position=(0, 0, t + 7.5 mm))
    Place(crank, position=(0, 0, 4 * t))

    # the request's numbers
    assert abs(left.disc.diameter - 84 mm) < 0.01 mm, "case circle 84 mm"
    assert abs(left.nose.diameter - 24 mm) < 0.01 mm, "nose circle 24 mm"
    assert abs(distance(left.disc.center, left.nose.center) - 60 mm) < 0.01 mm, "nose 60 mm ahead"
    assert abs(spacer_a.chamber.c.diameter - 60 mm) < 0.01 mm, "chamber 60 mm"
    assert abs(flange_a.disc.diameter - 54 mm) < 0.01 mm and abs(hub.disc.diameter - 30 mm) < 0.01 mm, "spool 54 / 30 mm"
    assert (60 mm - 54 mm) / 2 >= 2 mm, "flanges clear the chamber wall by 2 mm or more"
    assert 3 * 3 mm + 2 mm <= 2 * 6 mm, "spool (three 3 mm discs) fits the two 6 mm spacers with 1 mm each side"
    assert 36 mm - 4.5 mm / 2 - 60 mm / 2 >= 3 mm, "bolt holes leave 3 mm to the chamber"
    assert 84 mm / 2 - 36 mm - 4.5 mm / 2 >= 3 mm, "bolt holes leave 3 mm to the rim"
    assert len(right.bolt) == 4 and len(spacer_b.bolt) == 4, "four M4 bolts"
    assert abs(distance(right.filler.c.center, right.axle.c.center) - 22 mm) < 0.01 mm, "filler 22 mm from the axle"
    assert abs(distance(crank.dowel.c.center, crank.peg.c.center) - 45 mm) < 0.01 mm, "crank 45 mm"
}
