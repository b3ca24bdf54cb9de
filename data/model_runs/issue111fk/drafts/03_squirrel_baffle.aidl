# Request: a cone-shaped squirrel baffle for the bird-feeder pole in my garden, cut flat
# from 1 mm polypropylene sheet and rolled into a cone. Rolled, the cone is 380 mm across
# at the rim and 140 mm high, with a 34 mm hole at the apex for the 32 mm pole. The seam
# overlaps by a flap 25 mm wide (from 40 mm out from the apex to the rim, its free corners
# rounded R5) held by four M4 bolts, 12.5 mm in from the seam, at 70, 120, 170 and 220 mm
# from the apex; the matching holes sit 12.5 mm in from the other edge, and an engraved line
# 25 mm in from that edge shows where the flap's edge lands. "KEEP OFF, SQUIRRELS" engraved
# round the top, 12 mm letters.

units mm
thickness 1 mm

import "std/fasteners.aidl"

RB = 380 mm / 2                     # rim radius when rolled
H = 140 mm                          # cone height
L = sqrt(RB * RB + H * H)           # slant: the flat pattern's outer radius
# FIX after the first valid program: `360 deg * RB / L` came out a bare 5.058 (its radians),
# which `270 deg + ...` then read as 5.058 degrees: the pattern was a 5 degree sliver
SPAN = radians(360 * RB / L)        # the flat pattern's angle
R_IN = (34 mm / 2) * L / RB         # the apex hole's radius on the flat pattern
A0 = 270 deg + (360 deg - SPAN) / 2 - 360 deg   # start edge (the gap points down)
A1 = A0 + SPAN                      # end edge
FLAP = 25 mm
INSET = 12.5 mm
BOLTS = [70 mm, 120 mm, 170 mm, 220 mm]

solid baffle {
    cone = Sector(center=(0, 0), radius=L, start_angle=A0, end_angle=A1, inner_radius=R_IN)
    flap = Polygon([(40 * cos(A0), 40 * sin(A0)),
                    (L * cos(A0), L * sin(A0)),
                    (L * cos(A0) + FLAP * sin(A0), L * sin(A0) - FLAP * cos(A0)),
                    (40 * cos(A0) + FLAP * sin(A0), 40 * sin(A0) - FLAP * cos(A0))])
    Fillet([flap.points[2], flap.points[3]], 5)

    for s in BOLTS {
        flap_bolt = clearance_hole(size=4, cx=s * cos(A0) + INSET * sin(A0),
                                   cy=s * sin(A0) - INSET * cos(A0))
        seam_bolt = clearance_hole(size=4, cx=s * cos(A1) + INSET * sin(A1),
                                   cy=s * sin(A1) - INSET * cos(A1))
    }

    drawing marks {
        # FIX after the first valid program: the line ends 3 mm inside the rim (it overshot it)
        lap = Line((40 * cos(A1) + FLAP * sin(A1), 40 * sin(A1) - FLAP * cos(A1)),
                   ((L - 3) * cos(A1) + FLAP * sin(A1), (L - 3) * sin(A1) - FLAP * cos(A1)))
        ring = Circle(center=(0, 0), radius=L - 40, construction=true)
        words = Text("KEEP OFF, SQUIRRELS", along=ring, size=12)
    }

    assert abs(2 * R_IN * RB / L - 34 mm) < 0.01 mm, "34 mm apex hole once rolled"
    assert abs(sqrt(L * L - RB * RB) - 140 mm) < 0.01 mm, "140 mm high"
    assert abs(L * SPAN / 1 rad - pi * 380 mm) < 0.01 mm, "the outer arc rolls to a 380 mm rim"
    assert len(flap_bolt) == 4 and len(seam_bolt) == 4, "four M4 bolts"
    assert flap_bolt[0].c.diameter > 4 mm, "M4 clearance"
    assert abs(distance(flap_bolt[3].c.center, (0, 0)) - sqrt(220 * 220 + 12.5 * 12.5)) < 0.01 mm,
        "last bolt 220 from the apex"
}
