# Request: a "clean / dirty" dial for the dishwasher door, 3 mm ply. Two 80 mm discs
# on an M3 Chicago screw through the middle (3.4 mm holes). The back disc carries
# "CLEAN" over the top and "DIRTY" under the bottom, both 8 mm bold, filled engraving,
# their middles on a 28 mm radius, DIRTY readable the right way up; a 20 mm magnet is
# glued on its back. The front disc turns over it: a curved window 12 mm wide on the
# 28 mm radius, its end caps' centres at 50 and 130 degrees, shows one word at a time;
# 24 grip notches (4 mm round) round its rim, centred on the edge.

import "std/fasteners.aidl"

thickness 3 mm

assembly dish_dial {
    solid back {
        disc = Circle(center=(0, 0), diameter=80)
        pivot = clearance_hole(size=3)
        drawing words {
            ring = Circle(center=(0, 0), radius=28, construction=true)
            clean = Text("CLEAN", along=ring, size=8, valign="middle", font="sans:Bold", fill=true)
            dirty = Text("DIRTY", along=ring, size=8, valign="middle", flip=true, font="sans:Bold",
                         fill=true)
        }
        Concentric(pivot.c, disc)
        Concentric(words.ring, disc)
    }

    solid front {
        disc = Circle(center=(0, 0), diameter=80)
        pivot = clearance_hole(size=3)
        hole window {
            w = ArcSlot(center=(0, 0), radius=28, start_angle=50 deg, end_angle=130 deg, width=12)
        }
        hole notch {
            n = Circle(center=(40, 0), diameter=4)
        }
        grip = CircularPattern(notch, 24, disc.center)
        Concentric(pivot.c, disc)
        Concentric(window.w, disc)
        Coincident(notch.n.center, disc.right)
    }

    RightOf(front, back, gap=6)
    AlignCenterY(front, back)

    Place(back, position=(0, 0, 0), face="up")
    Place(front, position=(0, 0, 3), face="up")

    assert back.disc.diameter == 80 mm and front.disc.diameter == 80 mm, "80 mm discs"
    assert back.pivot.c.diameter == 3.4 mm, "3.4 mm pivot"
    assert back.words.clean.size == 8 mm, "8 mm words"
    assert front.window.w.width == 12 mm, "12 mm window"
    assert front.window.w.radius == 28 mm and back.words.ring.radius == 28 mm, "on the 28 mm radius"
    assert len(grip) == 24, "24 notches"
    assert distance(front.window, front.notch) >= 2 mm, "window clear of the notches"
}
