# Request: a Lunar New Year gift: a Chinese zodiac finder wheel, cut from 3 mm ply, two
# discs 200 mm across turning on a 5 mm Chicago screw through their centres.
# Base disc: 12 sectors of 30 deg, the Rat at the top and the others clockwise (Ox, Tiger,
# Rabbit, Dragon, Snake, Horse, Goat, Monkey, Rooster, Dog, Pig), divided by engraved lines
# from 30 to 98 mm out. In each sector its animal's name (6 mm, max 40 mm long) on the rim
# band 88-94 mm out, and its six years from 1960 to 2031 (Rat: 1960, 1972, ... 2020), 3.5 mm
# tall, stacked outward from 34 mm on an 8.5 mm pitch. Lower-half text is turned to read
# the right way up from below.
# Top disc: a window one sector wide (30 deg) at the top, from 32 to 96 mm out, showing one
# animal and its years; "LUNAR NEW YEAR" 12 mm bold, engraved filled, along the bottom
# (its letters 58-70 mm out), and "TURN THE WINDOW TO YOUR BIRTH YEAR" 4 mm under it.

thickness 3 mm

animals = ["RAT", "OX", "TIGER", "RABBIT", "DRAGON", "SNAKE", "HORSE", "GOAT", "MONKEY",
           "ROOSTER", "DOG", "PIG"]
years_each = 6

def sec(k) = 90 deg - k * 30 deg        # the middle of sector k
def year(k, j) = 1960 + k + 12 * j
def lower(k) = sin(sec(k)) < -0.01
def year_r(j) = 34 mm + j * 8.5 mm

assembly zodiac_wheel {
    solid base {
        disc = Circle(center=(0, 0), diameter=200 mm)
        hole pivot { c = Circle(center=(0, 0), diameter=5 mm) }
        drawing marks {
            name_up = Circle(center=(0, 0), radius=88 mm, construction=true)
            name_down = Circle(center=(0, 0), radius=94 mm, construction=true)
            for j in range(years_each) {
                yr_up = Circle(center=(0, 0), radius=year_r(j), construction=true)
                yr_down = Circle(center=(0, 0), radius=year_r(j) + 3.5 mm, construction=true)
            }
            for k in range(12) {
                div = Line((30 mm * cos(sec(k) + 15 deg), 30 mm * sin(sec(k) + 15 deg)),
                           (98 mm * cos(sec(k) + 15 deg), 98 mm * sin(sec(k) + 15 deg)))
                if lower(k) {
                    name = Text(animals[k], along=name_down, angle=sec(k), flip=true, size=6 mm,
                                max_width=40 mm)
                    for j in range(years_each) {
                        y = Text(str(year(k, j)), along=yr_down[j], angle=sec(k), flip=true,
                                 size=3.5 mm)
                    }
                } else {
                    name = Text(animals[k], along=name_up, angle=sec(k), size=6 mm,
                                max_width=40 mm)
                    for j in range(years_each) {
                        y = Text(str(year(k, j)), along=yr_up[j], angle=sec(k), size=3.5 mm)
                    }
                }
            }
        }
    }

    solid top {
        disc = Circle(center=(0, 0), diameter=200 mm)
        hole pivot { c = Circle(center=(0, 0), diameter=5 mm) }
        hole window {
            w = Sector(center=(0, 0), radius=96 mm, start_angle=75 deg, end_angle=105 deg,
                       inner_radius=32 mm)
        }
        drawing title {
            ring = Circle(center=(0, 0), radius=70 mm, construction=true)
            t = Text("LUNAR NEW YEAR", along=ring, angle=270 deg, flip=true, size=12 mm,
                     font="sans:Bold", fill=true)
            # FIX after the first valid program: at r 52 the flipped line hung above the title
            # (nearer the centre is higher at the bottom of a disc); "under it" is further out
            ring2 = Circle(center=(0, 0), radius=80 mm, construction=true)
            s = Text("TURN THE WINDOW TO YOUR BIRTH YEAR", along=ring2, angle=270 deg, flip=true,
                     size=4 mm)
        }
    }

    RightOf(top, base, gap=5 mm)
    AlignTop(top, base)
    Place(base, position=(0, 0, 0))
    Place(top, position=(0, 0, 3 mm))

    # the request's numbers
    assert len(animals) == 12, "12 animals"
    assert year(0, 0) == 1960 and year(0, 5) == 2020 and year(11, 5) == 2031, "1960 to 2031"
    assert year(7, 5) == 2027, "2027 is a Goat year"
    assert base.disc.diameter == 200 mm and top.disc.diameter == 200 mm, "200 mm discs"
    assert top.window.w.inner_radius == 32 mm and top.window.w.radius == 96 mm, "window 32-96"
    assert year_r(years_each - 1) + 3.5 mm <= top.window.w.radius - 12 mm,
        "the last year shows under the name, in the window"
    assert year_r(0) >= top.window.w.inner_radius + 1 mm, "the first year clears the inner edge"
    assert top.title.ring2.radius - 4 mm - top.title.ring.radius >= 4 mm,
        "the small line hangs under the title (further out at the bottom)"
}
