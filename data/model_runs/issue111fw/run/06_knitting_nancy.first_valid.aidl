# REQUEST (crafts): a French knitting spool ("knitting nancy") as a little cage of 6 mm ply:
# two discs 56 mm across, each with a 16 mm centre bore for the cord to drop through; the top
# disc also has four 3 mm holes on a 28 mm circle (at 45, 135, 225, 315 deg) for the brass
# pins the loops go over. Three slats 12 mm wide hold the discs 80 mm apart (between them),
# their flat faces on a 36 mm circle (inner faces 18 mm from the axis), at 90, 210 and 330
# deg, each with an 8 mm tenon at each end glued through an 8 x 6 mm mortise in each disc,
# and "KNITTING NANCY" engraved (5 mm, reading up) on its outer face. Five parts; shown
# assembled.

units mm
import "std/joints.aidl"

t = 6 mm
thickness t
gap = 80 mm                      # between the discs
angles = [90 deg, 210 deg, 330 deg]

def disc(pins=true) -> solid {
    body = Circle(center=(0, 0), diameter=56)
    hole bore {
        c = Circle(center=(0, 0), diameter=16)
    }
    hole pin_holes {
        if pins {
            for k in range(4) {
                p = Circle(center=(14 * cos(45 deg + k * 90 deg), 14 * sin(45 deg + k * 90 deg)),
                           diameter=3)
            }
        }
    }
    for i in range(3) {
        m = tab_and_slot(part="slot", length=12 mm, thickness=t, tabs=1, tab=8 mm, screw=0,
                         rotation=angles[i] + 90 deg, cx=21 * cos(angles[i]),
                         cy=21 * sin(angles[i]))
    }
}

def slat() -> solid {
    # drawn with the bottom tenon's tip on y = 0 and the top tenon's tip on y = t + gap + t
    body = Rectangle(corner=(-6, 0), opposite=(6, t + gap + t))
    bottom_tenon = tab_and_slot(part="tab", length=12 mm, thickness=t, tabs=1, tab=8 mm,
                                screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
    top_tenon = tab_and_slot(part="tab", length=12 mm, thickness=t, tabs=1, tab=8 mm,
                             screw=0, cx=0 mm, cy=t + gap + t)
    drawing name {
        w = Text("KNITTING NANCY", position=(0, t + gap / 2), size=5, rotation=90,
                 valign="middle")
    }
}

assembly nancy {
    top = disc(pins=true)
    bottom = disc(pins=false)
    for i in range(3) {
        s = slat()
        Place(s, position=(18 * cos(angles[i]), 18 * sin(angles[i]), 0),
              face=(cos(angles[i]), sin(angles[i]), 0), up="up")
    }

    # flat, for cutting
    RightOf(bottom, top, gap=8)
    AlignCenterY(bottom, top)
    RightOf(s[0], bottom, gap=8)
    AlignTop(s[0], top)
    RightOf(s[1], s[0], gap=8)
    AlignTop(s[1], s[0])
    RightOf(s[2], s[1], gap=8)
    AlignTop(s[2], s[1])

    # 3D
    Place(bottom, position=(0, 0, 0))
    Place(top, position=(0, 0, t + gap))
}

# the request's numbers
assert nancy.top.body.diameter == 56 mm and nancy.bottom.body.diameter == 56 mm, "discs 56 mm"
assert nancy.top.bore.c.diameter == 16 mm, "16 mm bore"
assert len(nancy.top.pin_holes.p) == 4, "four pins"
assert distance(nancy.top.pin_holes.p[0].center, nancy.top.pin_holes.p[2].center) == 28 mm, "pins on a 28 mm circle"
assert len(nancy.s) == 3, "three slats"
assert nancy.s[0].body.width == 12 mm, "slats 12 mm wide"
assert nancy.s[0].body.height - 2 * t == 80 mm, "discs 80 mm apart"
assert nancy.top.m[0].slot[0].bb.width == 8 mm, "8 mm mortises"
