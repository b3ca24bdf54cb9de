# Request (gifts): a birthday constellation plaque for Anna (born under Leo), 3 mm walnut ply.
# A 200 mm disc whose bottom is cut flat 8 mm up, so it stands, cross-halved into a foot
# 140 x 30 mm (top corners r10) with 15 mm slots in each. Leo's nine stars are through holes,
# 4 mm for the brightest (Regulus, Algieba, Denebola), 3 mm for the middling ones (Eta,
# Adhafera, Epsilon, Zosma, Chertan), 2 mm for Rasalas; its ten figure lines are engraved,
# stopping 1.5 mm short of each hole. An engraved ring 10 mm in from the rim (broken round
# the slot); "ANNA · 12 AUGUST 1990" engraved along the top, 6 mm high, just inside the ring;
# "LEO" engraved filled, bold, 12 mm high, centred 45 mm below the disc's centre.

import "std/joints.aidl"

thickness 3 mm

T = 3 mm
R = 100 mm
flat = 8 mm
# x, y, hole diameter (the disc's centre at (0, 0))
stars = [[-35, -15, 4], [-30, 5, 3], [-20, 20, 4], [-25, 38, 3], [-38, 48, 2],
         [-50, 40, 3], [25, 18, 3], [25, -5, 3], [60, 0, 4]]
# Regulus, Eta, Algieba, Adhafera, Rasalas, Epsilon, Zosma, Chertan, Denebola
figure = [[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [2, 6], [6, 8], [8, 7], [7, 0], [6, 7]]

assembly gift {
    solid plaque {
        disc = Circle(center=(0, 0), radius=R)
        hole foot_flat { r = Rectangle(center=(0, -R), width=2 * R, height=2 * flat) }
        slot = cross_halving(depth=15 mm, thickness=T, rotation=180 deg, cx=0 mm, cy=-R + flat)
        for s in stars {
            hole star { c = Circle(center=(s[0], s[1]), diameter=s[2]) }
        }
        drawing lines {
            for e in figure {
                l = Line((stars[e[0]][0], stars[e[0]][1]), (stars[e[1]][0], stars[e[1]][1]))
            }
            hole gaps {
                for s in stars {
                    g = Circle(center=(s[0], s[1]), radius=s[2] / 2 + 1.5 mm)
                }
            }
        }
        drawing border {
            ring = Circle(center=(0, 0), radius=R - 10 mm)
            hole by_slot { r = Rectangle(center=(0, -R + flat + 8 mm), width=T + 3 mm, height=20) }
        }
        drawing words {
            arc = Circle(center=(0, 0), radius=R - 20 mm, construction=true)
            who = Text("ANNA · 12 AUGUST 1990", along=arc, size=6)
            sign = Text("LEO", position=(0, -45), size=12, font="sans:Bold", valign="middle",
                        fill=true)
        }
    }

    solid foot {
        body = RoundedRectangle(center=(0, 0), width=140, height=30, corner_radii=[10, 10, 0, 0])
        slot = cross_halving(depth=15 mm, thickness=T, cx=0 mm, cy=15 mm)
    }
    RightOf(foot, plaque, gap=10)
    AlignBottom(foot, plaque)

    # 3D: the plaque standing on its flat (its y up, its thickness along -y), the foot across
    # it (its x along y, its y up, its thickness along x); the slots interlock
    Place(plaque, rotation=(90 deg, 0, 0), position=(0, T / 2, R - flat))
    Place(foot, rotation=(90 deg, 0, 90 deg), position=(-T / 2, 0, 15))

    assert plaque.disc.diameter == 200 mm, "200 mm disc"
    assert plaque.foot_flat.r.bb.top - plaque.disc.bb.bottom == 8 mm, "flat 8 mm up"
    assert foot.body.bb.width == 140 mm and foot.body.bb.height == 30 mm, "foot 140 x 30"
    assert len(plaque.star) == 9, "nine stars"
    assert len(plaque.lines.l) == 10, "ten figure lines"
    assert plaque.slot.depth == 15 mm and foot.slot.depth == 15 mm, "15 mm slots"
    assert plaque.disc.radius - plaque.border.ring.radius == 10 mm, "ring 10 in"
    assert plaque.disc.center.y - plaque.words.sign.position.y == 45 mm, "LEO 45 below"
}
