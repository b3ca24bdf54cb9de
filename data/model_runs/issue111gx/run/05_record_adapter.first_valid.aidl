# Request: a 45 rpm adapter "puck" for playing 7-inch singles with the big centre hole on my
# turntable, from 3 mm cast acrylic: three discs 38 mm across (the single's hole is 38.2 mm),
# glued into a 9 mm puck that slips over the 7.3 mm spindle (hole 7.3 mm in every disc).
# The top disc is decorated like the old "spider" inserts: three curved windows 5 mm wide on a
# 11 mm radius, each running 70 degrees (end centre to end centre) with the solid spokes
# between them, and engraved 2.5 mm text: "45 RPM" over the top and "ADAPTER" under the
# bottom, both reading the right way up, kept inside the disc's edge.

units mm
thickness 3 mm

param disc_d = 38 mm, min = 37 mm, max = 38.2 mm
param spindle_d = 7.3 mm, min = 7.1 mm, max = 7.6 mm

def layer() -> solid {
    disc = Circle(center=(0, 0), diameter=disc_d)
    hole spindle { c = Circle(center=(0, 0), diameter=spindle_d) }
}

assembly adapter {
    solid top {
        disc = Circle(center=(0, 0), diameter=disc_d)
        hole spindle { c = Circle(center=(0, 0), diameter=spindle_d) }
        hole windows {
            for k in range(3) {
                w = ArcSlot(center=(0, 0), radius=11, start_angle=k * 120 deg + 55 deg,
                            end_angle=k * 120 deg + 125 deg, width=5)
            }
        }
        drawing label {
            ring = Circle(center=(0, 0), radius=15, construction=true)
            over = Text("45 RPM", along=ring, size=2.5)
            ring2 = Circle(center=(0, 0), radius=17.5, construction=true)
            under = Text("ADAPTER", along=ring2, size=2.5, flip=true)
        }
        assert disc.diameter == 38 mm, "38 mm across"
        assert len(windows.w) == 3, "three windows"
        assert windows.w[0].radius == 11 mm and windows.w[0].width == 5 mm, "windows 5 mm wide on 11 mm"
        assert distance(label, windows) >= 1 mm, "text clear of the windows"
        assert label.bb.top <= disc.bb.top - 1 mm, "text inside the edge"
    }
    middle = layer()
    bottom = layer()
    RightOf(middle, top, gap=5)
    AlignTop(middle, top)
    RightOf(bottom, middle, gap=5)
    AlignTop(bottom, middle)
    assert 3 * 3 mm == 9 mm, "three 3 mm discs make the 9 mm puck"
    assert middle.spindle.c.diameter == 7.3 mm and top.spindle.c.diameter == 7.3 mm, "7.3 mm spindle hole"
}
