# Request (science): a "planets to scale" board for my son's classroom wall, in 3 mm ply,
# two layers glued: a 470 x 100 front (5 mm rounded corners) and a backing of the same size
# painted black. The planets are round windows in the front through which the black backing
# shows, their sizes true to scale with Jupiter 60 mm across (Mercury 4879 km, Venus 12104,
# Earth 12742, Mars 6779, Jupiter 139820, Saturn 116460, Uranus 50724, Neptune 49244),
# their centres 5 mm above the board's middle line at 40, 70, 100, 130, 185, 300, 395 and
# 440 mm from the left edge. The Sun (1392700 km at the same scale) shows as its limb on the
# left end: its edge 20 mm in from the left on the middle line, engraved filled.
# Saturn's rings engraved as two ellipses (outer edges of the A ring, 136775 km, and the
# B ring, 117580 km, from the centre; flattened to 0.3, tilted 12 deg clockwise), hidden where
# the planet's window is. Each name engraved under its planet (4 mm capitals, baseline 38 mm
# under the middle line); the title "THE PLANETS - SIZES TO SCALE, NOT DISTANCES" in 5 mm along
# the top, baseline 40 mm above the middle line. The backing has two keyholes (8 mm head,
# 10 mm slot up), 150 mm either side of the middle, 30 mm above the middle line.

import "std/plates.aidl"

units mm
thickness 3 mm

L = 470 mm
H = 100 mm
names = ["MERCURY", "VENUS", "EARTH", "MARS", "JUPITER", "SATURN", "URANUS", "NEPTUNE"]
km = [4879, 12104, 12742, 6779, 139820, 116460, 50724, 49244]
xs = [40, 70, 100, 130, 185, 300, 395, 440]
scale = 60 mm / 139820
ds = [k * scale for k in km]
sun_r = 1392700 * scale / 2
cy = 5 mm

assembly board {
    solid front {
        body = RoundedRectangle(center=(L / 2, 0), width=L, height=H, corner_radius=5)
        hole windows {
            for i in range(8) {
                c = Circle(center=(xs[i], cy), diameter=ds[i])
            }
        }
        drawing sun {
            # FIX after the first valid program: W0505 was real: the fill ran past the
            # board's 5 mm rounded corners; clip it to the same rounded outline
            limb = Intersect(Circle(center=(20 - sun_r, 0), radius=sun_r),
                             RoundedRectangle(center=(L / 2, 0), width=L, height=H,
                                              corner_radius=5), fill=true)
        }
        drawing rings {
            a = Ellipse(center=(xs[5], cy), rx=136775 * scale, ry=0.3 * 136775 * scale,
                        rotation=-12 deg)
            b = Ellipse(center=(xs[5], cy), rx=117580 * scale, ry=0.3 * 117580 * scale,
                        rotation=-12 deg)
            hole planet { c = Circle(center=(xs[5], cy), diameter=ds[5]) }
        }
        drawing labels {
            for i in range(8) {
                t = Text(names[i], position=(xs[i], -38), size=4)
            }
            title = Text("THE PLANETS - SIZES TO SCALE, NOT DISTANCES", position=(L / 2, 40),
                         size=5)
        }
    }

    solid backing {
        body = RoundedRectangle(center=(L / 2, 0), width=L, height=H, corner_radius=5)
        k1 = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                     cx=L / 2 - 150 mm, cy=30 mm)
        k2 = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                     cx=L / 2 + 150 mm, cy=30 mm)
    }

    Below(backing, front, gap=10)
    AlignLeft(backing, front)
    Place(backing, position=(0, 0, 0))
    Place(front, position=(0, 0, 3))

    assert len(front.windows.c) == 8, "eight planets"
    assert front.windows.c[4].diameter == 60 mm, "Jupiter 60 mm"
    assert abs(front.windows.c[2].diameter - 5.47 mm) < 0.01 mm, "Earth about 5.5 mm"
    assert front.body.bb.width == 470 mm and front.body.bb.height == 100 mm, "470 x 100"
    assert front.windows.c[0].center.x - front.body.bb.left == 40 mm, "Mercury 40 mm in"
    assert front.windows.c[7].center.x - front.body.bb.left == 440 mm, "Neptune 440 mm in"
    assert front.sun.bb.right - front.body.bb.left == 20 mm, "the Sun's edge 20 mm in"
    assert distance(front.windows.c[4], front.rings) >= 3 mm, "Jupiter clear of the rings"
    assert distance(front.windows.c[6], front.rings) >= 3 mm, "Uranus clear of the rings"
    assert distance(front.labels.title, front.windows) >= 2 mm, "title clear of the planets"
    for i in range(7) {
        assert distance(front.labels.t[i], front.labels.t[i + 1]) >= 2 mm, "names apart"
    }
    assert distance(front.labels.t[0], front.sun) >= 2 mm, "MERCURY clear of the Sun"
    assert front.labels.bb.bottom >= front.body.bb.bottom + 3 mm, "names on the board"
    assert front.labels.bb.top <= front.body.bb.top - 3 mm, "title on the board"
}
