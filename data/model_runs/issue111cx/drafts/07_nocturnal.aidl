# Request: a nocturnal (star clock) for the astronomy club, 3 mm ply, three parts riveted
# on a 6 mm hollow eyelet (6.2 mm hole through all, which is also the sighting hole for
# Polaris).
# - Main plate: a 130 mm disc with a handle below it (30 wide, 60 long from the disc's
#   bottom, round end, 5 mm lanyard hole 12 mm from the end, "NOCTURNAL" engraved 4 mm high
#   along it). Round the rim a date scale: 12 months (JAN at the top, running clockwise),
#   a long tick at each month's start and short ticks at days 10 and 20; month names
#   3.5 mm high, those in the lower half turned to read from outside the bottom.
# - Hour disc 88 mm across with 24 rounded teeth (to count hours by touch), a pointer tooth
#   at midnight reaching 57 mm from the centre onto the date scale, and the hours 12, 1 ... 11
#   twice round it, 3.5 mm high, increasing clockwise.
# - Index arm: reaches 150 mm from the centre, 12 mm wide at a 28 mm hub, tapering to 2 mm,
#   "POINTERS" engraved 3 mm high along it.
thickness 3 mm

eyelet = 6.2 mm
plate_d = 130 mm
hour_d = 88 mm
arm_reach = 150 mm
months = ["JAN", "FEB", "MAR", "APR", "MAY", "JUN", "JUL", "AUG", "SEP", "OCT", "NOV", "DEC"]

assembly nocturnal {
    solid main {
        disc = Circle(center=(0, 0), diameter=plate_d)
        # FIX after the first valid program: W0504, the handle only touched the disc at its
        # lowest point; it now runs 20 mm up into the disc (still 60 mm below its bottom)
        handle = RoundedRectangle(center=(0, -plate_d / 2 - 20 mm), width=30, height=80,
                                  corner_radii=[0, 0, 15, 15])
        hole sight { c = Circle(center=(0, 0), diameter=eyelet) }
        hole lanyard { c = Circle(center=(0, -plate_d / 2 - 60 mm + 12 mm), diameter=5) }
        drawing scale {
            for m in range(12) {
                for d in range(3) {
                    a = 90 deg - (m * 30 + d * 10) * 1 deg
                    r0 = 57 mm if d == 0 else 60.5 mm
                    tick = Line((r0 * cos(a), r0 * sin(a)), (64 * cos(a), 64 * sin(a)))
                }
            }
            up_ring = Circle(center=(0, 0), radius=51, construction=true)
            down_ring = Circle(center=(0, 0), radius=54.5, construction=true)
            for m in range(12) {
                am = 90 deg - (m * 30 + 15) * 1 deg
                if sin(am) > 0 {
                    name = Text(months[m], along=up_ring, angle=am, size=3.5)
                } else {
                    name = Text(months[m], along=down_ring, angle=am, size=3.5, flip=true)
                }
            }
            # FIX after the first valid program: the word ended 0.75 mm from the lanyard hole
            title = Text("NOCTURNAL", position=(0, -plate_d / 2 - 22 mm), size=4,
                         rotation=90 deg, valign="middle")
        }
    }

    solid hours {
        body = Circle(center=(0, 0), radius=hour_d / 2)
        for k in range(1, 24) {
            a = 90 deg - k * 15 deg
            tooth = Circle(center=(hour_d / 2 * cos(a), hour_d / 2 * sin(a)), radius=2.5)
        }
        pointer = Polygon([(-4, hour_d / 2 - 4 mm), (4, hour_d / 2 - 4 mm), (0, 57)])
        hole sight { c = Circle(center=(0, 0), diameter=eyelet) }
        drawing numbers {
            ring = Circle(center=(0, 0), radius=36, construction=true)
            for k in range(24) {
                n = Text(str((k + 11) % 12 + 1), along=ring, angle=90 deg - k * 15 deg, size=3.5)
            }
        }
    }

    solid arm {
        hub = Circle(center=(0, 0), diameter=28)
        blade = Polygon([(-6, 10), (6, 10), (1, arm_reach), (-1, arm_reach)])
        hole sight { c = Circle(center=(0, 0), diameter=eyelet) }
        drawing word {
            w = Text("POINTERS", position=(0, 75), size=3, rotation=90 deg, valign="middle")
        }
    }

    # flat on the sheet
    RightOf(hours, main, gap=10)
    AlignTop(hours, main)
    RightOf(arm, hours, gap=10)
    AlignTop(arm, hours)

    # 3D: stacked on the eyelet, the hour disc set to a date, the arm swung to an hour
    Place(main, position=(0, 0, 0), face="up")
    Place(hours, position=(0, 0, 3), rotation=(0, 0, -100 deg))
    Place(arm, position=(0, 0, 6), rotation=(0, 0, -35 deg))

    # the request's numbers
    assert main.disc.diameter == 130 mm, "130 mm plate"
    assert main.disc.bb.bottom - main.handle.bb.bottom == 60 mm and main.handle.width == 30 mm,
        "handle 30 x 60"
    assert main.lanyard.c.center.y - main.handle.bb.bottom == 12 mm, "lanyard 12 mm from the end"
    assert main.scale.title.bb.bottom - main.lanyard.c.bb.top >= 3 mm, "word clear of the lanyard hole"
    assert len(main.scale.tick) == 12 and len(main.scale.tick[0]) == 3, "12 months x 3 ticks"
    assert hours.body.diameter == 88 mm, "hour disc 88 mm"
    assert len(hours.tooth) + 1 == 24, "24 teeth with the pointer"
    assert hours.pointer.bb.top == 57 mm, "pointer reaches 57 mm"
    assert arm.blade.bb.top - arm.hub.center.y == 150 mm, "arm reaches 150 mm"
    assert main.sight.c.diameter == 6.2 mm and hours.sight.c.diameter == 6.2 mm and
        arm.sight.c.diameter == 6.2 mm, "6.2 mm eyelet hole in all three"
}
