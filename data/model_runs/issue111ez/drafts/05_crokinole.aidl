# Request: a travel crokinole board in 6 mm birch ply, four layers glued up.
# - base: a 380 mm disc;
# - playing surface: a 320 mm disc glued in the middle of the base. A 35 mm "20 hole" through
#   its centre (the base under it is the cup's floor). Engraved: the 15 ring (168 mm across),
#   the 10 ring (252 mm) and the outer shooting line (310 mm), four quadrant lines at 45, 135,
#   225 and 315 degrees from the 15 ring out to the shooting line, and the zone values "15",
#   "10", "5" (8 mm, single stroke) on the vertical axis at 55, 105 and 137 mm from the centre.
#   Eight 6 mm holes for dowel pegs centred on the 15 ring, at 22.5 degrees and every 45 from it.
# - rail: two identical rings, 380 mm outside and 360 mm inside, stacked on the base's rim:
#   a 20 mm ditch round the surface, the rail standing 6 mm above the playing surface.

thickness 6 mm

board_d = 380 mm
surface_d = 320 mm
ring15_r = 84 mm

def rail_ring() -> solid {
    outer = Circle(center=(0, 0), diameter=board_d)
    hole inside {
        c = Circle(center=(0, 0), diameter=360)
    }
}

assembly crokinole {
    solid base {
        disc = Circle(center=(0, 0), diameter=board_d)
    }

    solid surface {
        disc = Circle(center=(0, 0), diameter=surface_d)
        hole twenty {
            c = Circle(center=(0, 0), diameter=35)
        }
        hole pegs {
            for k in range(8) {
                p = Circle(center=(ring15_r * cos(22.5 deg + k * 45 deg), ring15_r * sin(22.5 deg + k * 45 deg)), diameter=6)
            }
        }
        drawing lines {
            r15 = Circle(center=(0, 0), diameter=168)
            r10 = Circle(center=(0, 0), diameter=252)
            shoot = Circle(center=(0, 0), diameter=310)
            for k in range(4) {
                q = Line((ring15_r * cos(45 deg + k * 90 deg), ring15_r * sin(45 deg + k * 90 deg)),
                         (155 * cos(45 deg + k * 90 deg), 155 * sin(45 deg + k * 90 deg)))
            }
            v15 = Text("15", position=(0, 55), size=8, valign="middle")
            v10 = Text("10", position=(0, 105), size=8, valign="middle")
            v5 = Text("5", position=(0, 137), size=8, valign="middle")
        }
        # FIX after the first valid program: both warnings were false alarms for this design.
        # W0505: the 15 ring runs through the peg holes on purpose (the pegs stand on it).
        AllowOverlap(lines.r15, self)
        # W0513: the quadrant lines start on the 15 ring and cross the 10 ring on purpose.
        AllowOverlap(lines.q, lines.r10)
    }

    rail_low = rail_ring()
    rail_high = rail_ring()

    # on the sheet: side by side
    RightOf(surface, base, gap=10)
    AlignCenterY(surface, base)
    Below(rail_low, base, gap=10)
    AlignLeft(rail_low, base)
    RightOf(rail_high, rail_low, gap=10)
    AlignTop(rail_high, rail_low)

    # assembled: all concentric, stacked
    Place(base, position=(0, 0, 0), face="up")
    Place(surface, position=(0, 0, 6), face="up")
    Place(rail_low, position=(0, 0, 6), face="up")
    Place(rail_high, position=(0, 0, 12), face="up")

    assert base.disc.diameter == 380 mm, "base 380"
    assert surface.disc.diameter == 320 mm, "surface 320"
    assert surface.twenty.c.diameter == 35 mm, "20 hole 35"
    assert len(surface.pegs.p) == 8, "eight pegs"
    assert abs(distance(surface.pegs.p[0].center, surface.disc.center) - 168 mm / 2) < 0.001 mm, "pegs on the 15 ring"
    assert (rail_low.inside.c.diameter - surface.disc.diameter) / 2 == 20 mm, "20 mm ditch"
    assert rail_low.outer.diameter == 380 mm and rail_low.inside.c.diameter == 360 mm, "rail 380 / 360"
    assert 2 * 6 mm - 6 mm == 6 mm, "rail 6 above the surface (two rings on the base, one surface layer)"
    assert distance(surface.lines.v15, surface.pegs) >= 2 mm, "15 clear of the pegs"
    assert distance(surface.lines.v15, surface.twenty) >= 2 mm, "15 clear of the 20 hole"
}
