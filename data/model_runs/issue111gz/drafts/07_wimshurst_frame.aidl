# Request (science): "The laser-cut parts of a small Wimshurst machine for the school science
# club. Two 300 mm discs of 3 mm acrylic, each with a 12 mm bore for a bronze bush, three M3
# holes on a 30 mm circle to bolt on its pulley, and 24 foil-sector outlines engraved as guides
# (annulus pieces from radius 90 to 140 mm, 8 degrees wide). Two pulleys 60 mm across with the
# same 12 mm bore and M3 holes. The frame in 6 mm acrylic: a base 360 x 160 mm and two
# uprights standing 70 mm apart (centre to centre) on the base's middle, each 70 mm wide at the
# foot narrowing to a round top of R20, with two glued tabs 20 mm wide into mortises in the
# base. Each upright has an 8 mm hole for the disc axle 230 mm above the base and an 8 mm hole
# for the crank shaft 40 mm above the base. The base also has two 4 mm screw holes for the
# Leyden jars, 150 mm either side of the centre, each inside an engraved 36 mm ring marking
# where the jar stands, and 'WIMSHURST' engraved along its front edge."

units mm
thickness 3 mm

import "std/shapes.aidl"
import "std/joints.aidl"

t = 6 mm
disc_d = 300 mm
axle_up = 230 mm
crank_up = 40 mm
base_l = 360 mm
base_w = 160 mm
upright_pitch = 70 mm

def wim_disc() -> solid {
    plate = Circle(center=(0, 0), diameter=disc_d)
    hole hub { c = Circle(center=(0, 0), diameter=12) }
    bolts = bolt_circle(count=3, pcd=30 mm, hole_d=3.4 mm)
    drawing foil {
        s = Sector(center=(0, 0), radius=140, start_angle=-4 deg, end_angle=4 deg,
                   inner_radius=90)
    }
    sectors = CircularPattern(foil, 24, plate.center)
    assert len(sectors) == 24, "24 foil sectors"
    assert plate.diameter == 300 mm, "discs 300 across"
}

def wim_pulley() -> solid {
    rim = Circle(center=(0, 0), diameter=60)
    hole hub { c = Circle(center=(0, 0), diameter=12) }
    bolts = bolt_circle(count=3, pcd=30 mm, hole_d=3.4 mm)
}

def wim_upright() -> solid {
    thickness t
    # flat: the tab tips on y = 0, the shoulders (on the base) at y = t
    body = Hull(Point(-35, 0), Point(35, 0), Circle(center=(0, t + axle_up), radius=20))
    feet = tab_and_slot(part="tab", length=70 mm, thickness=t, tabs=2, tab=20 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    hole axle { c = Circle(center=(0, t + axle_up), diameter=8) }
    hole crank { c = Circle(center=(0, t + crank_up), diameter=8) }
    assert axle.c.center.y - body.bb.bottom - t == 230 mm, "axle 230 above the base"
    assert crank.c.center.y - body.bb.bottom - t == 40 mm, "crank 40 above the base"
    assert body.bb.top - axle.c.center.y == 20 mm, "R20 top round the axle"
}

assembly wimshurst {
    for i in range(2) {
        disc = wim_disc()
        pulley = wim_pulley()
        upright = wim_upright()
    }

    solid base {
        thickness t
        board = Rectangle(center=(0, 0), width=base_l, height=base_w)
        mortise_front = tab_and_slot(part="slot", length=70 mm, thickness=t, tabs=2, tab=20 mm,
                                     screw=0, cx=0 mm, cy=-upright_pitch / 2)
        mortise_back = tab_and_slot(part="slot", length=70 mm, thickness=t, tabs=2, tab=20 mm,
                                    screw=0, cx=0 mm, cy=upright_pitch / 2)
        hole jar_screws {
            l = Circle(center=(-150, 0), diameter=4)
            r = Circle(center=(150, 0), diameter=4)
        }
        drawing jar_marks {
            l = Circle(center=(-150, 0), diameter=36)
            r = Circle(center=(150, 0), diameter=36)
        }
        drawing name {
            n = Text("WIMSHURST", position=(0, -base_w / 2 + 12), size=8, valign="middle")
        }
        assert board.bb.width == 360 mm and board.bb.height == 160 mm, "base 360 x 160"
        assert mortise_back.bb.center_y - mortise_front.bb.center_y == 70 mm, "uprights 70 apart"
        assert jar_screws.r.center.x - jar_screws.l.center.x == 300 mm, "jars 150 each side"
        assert distance(name, mortise_front) >= 3 mm, "name clear of the mortises"
    }

    # the discs clear the crank shaft
    assert axle_up - disc_d / 2 - (crank_up + 4 mm) >= 30 mm, "disc clears the crank"

    RightOf(disc[1], disc[0], gap=10)
    AlignTop(disc[1], disc[0])
    Below(base, disc[0], gap=10)
    AlignLeft(base, disc[0])
    RightOf(upright[0], disc[1], gap=10)
    AlignTop(upright[0], disc[1])
    RightOf(upright[1], upright[0], gap=10)
    AlignTop(upright[1], upright[0])
    Below(pulley[0], upright[0], gap=10)
    AlignLeft(pulley[0], upright[0])
    RightOf(pulley[1], pulley[0], gap=10)
    AlignTop(pulley[1], pulley[0])
}
