# Request (science): "A to-scale chart of Earth's history for the classroom wall,
# engraved on a 400 x 170 mm plaque of 3 mm ply with 8 mm rounded corners and two 5 mm
# hanging holes 12 mm in from the top corners. EARTH'S HISTORY engraved filled (bold,
# 10 mm) at the top. A bar 360 mm long and 20 mm tall is the whole 4600 million years
# (left: 4600 Ma, right: today), split into the eons at 4000, 2500 and 538.8 Ma:
# HADEAN, ARCHEAN, PROTEROZOIC outlined with their names inside (5 mm), the
# PHANEROZOIC engraved filled. Above the bar a tick every 100 Ma (3 mm; 6 mm every
# 500 Ma with its number, 4 mm text). Below it, a second bar 360 x 20 mm blows up the
# Phanerozoic (538.8 Ma to now): PALEOZOIC to 251.9, MESOZOIC to 66, CENOZOIC, with
# the boundary ages under it (3.5 mm) and two lines joining the Phanerozoic's ends on
# the top bar to the second bar's ends. MILLION YEARS AGO (4 mm) under everything."

thickness 3 mm

def xm(ma) = 180 mm - ma * (360 mm / 4600)     # top bar: whole history
def xi(ma) = 180 mm - ma * (360 mm / 538.8)    # second bar: Phanerozoic
eon_ages = [4600, 4000, 2500, 538.8]
eon_names = ["HADEAN", "ARCHEAN", "PROTEROZOIC"]
era_ages = [538.8, 251.9, 66, 0]
era_names = ["PALEOZOIC", "MESOZOIC", "CENOZOIC"]

solid plaque {
    body = RoundedRectangle(center=(0, 0), width=400, height=170, corner_radius=8)
    hole hang {
        l = Circle(center=(-188, 73), diameter=5)
        r = Circle(center=(188, 73), diameter=5)
    }
    drawing title {
        t = Text("EARTH'S HISTORY", position=(0, 68), size=10, font="sans:Bold",
                 valign="middle", fill=true)
    }
    # FIX after the first valid program (W0513): adjacent eon/era boxes burned their shared
    # side twice; now one outline per bar (up to the filled Phanerozoic) and a divider line
    # per boundary
    drawing eons {
        bar = Polyline([(xm(538.8), 10), (xm(4600), 10), (xm(4600), 30), (xm(538.8), 30)])
        for i in range(1, 3) {
            d = Line((xm(eon_ages[i]), 10), (xm(eon_ages[i]), 30))
        }
        for i in range(3) {
            n = Text(eon_names[i], position=((xm(eon_ages[i]) + xm(eon_ages[i + 1])) / 2, 20),
                     size=5, valign="middle")
        }
        phan = Rectangle(corner=(xm(538.8), 10), opposite=(xm(0), 30), fill=true)
    }
    drawing scale {
        for k in range(47) {
            tick = Line((xm(k * 100), 30), (xm(k * 100), 30 + (6 if k % 5 == 0 else 3)))
        }
        for k in range(10) {
            num = Text(str(k * 500), position=(xm(k * 500), 38), size=4)
        }
    }
    drawing zoom {
        bar = Rectangle(corner=(xi(538.8), -50), opposite=(xi(0), -30))
        for i in range(1, 3) {
            d = Line((xi(era_ages[i]), -50), (xi(era_ages[i]), -30))
        }
        for i in range(3) {
            n = Text(era_names[i], position=((xi(era_ages[i]) + xi(era_ages[i + 1])) / 2, -40),
                     size=5, valign="middle")
        }
        for i in range(4) {
            age = Text(str(era_ages[i]), position=(xi(era_ages[i]), -54), size=3.5, valign="top")
        }
        left_link = Line((xm(538.8), 10), (xi(538.8), -30))
        right_link = Line((xm(0), 10), (xi(0), -30))
        caption = Text("MILLION YEARS AGO", position=(0, -72), size=4, valign="middle")
    }

    assert body.bb.width == 400 mm and body.bb.height == 170 mm, "plaque 400 x 170"
    assert hang.l.center.x - body.bb.left == 12 mm and body.bb.top - hang.l.center.y == 12 mm, "holes 12 in"
    assert eons.phan.bb.right - eons.bar.bb.left == 360 mm, "top bar 360 long"
    assert eons.bar.bb.height == 20 mm, "bars 20 tall"
    assert abs(eons.phan.bb.width - 538.8 / 4600 * 360 mm) < 0.001 mm, "Phanerozoic to scale"
    assert abs(eons.d[1].start.x - eons.d[0].start.x - 1500 / 4600 * 360 mm) < 0.001 mm, "Archean to scale"
    assert zoom.bar.bb.width == 360 mm, "second bar 360 long"
    assert abs(zoom.d[1].start.x - zoom.d[0].start.x - (251.9 - 66) / 538.8 * 360 mm) < 0.001 mm, "Mesozoic to scale"
    assert len(scale.tick) == 47 and len(scale.num) == 10, "47 ticks, 10 numbers"
}
