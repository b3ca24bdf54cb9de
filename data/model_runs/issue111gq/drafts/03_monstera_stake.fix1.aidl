# Request: a climbing support for a monstera in a 25 cm pot, cut from 5 mm clear acrylic. Two
# panels 80 mm wide and 560 mm tall that slot together into an X by a cross-halving (0.2 mm
# clearance): one slotted 280 mm down from its top, the other 280 mm up from its tip. Each
# panel: a round top (R40), a tapered spike at the bottom that pushes into the soil, 120 mm
# long, narrowing from 80 mm to a blunt 20 mm tip; two columns of tie holes for twine, 14 x 5 mm
# upright slots at 24 mm either side of the centre line, every 40 mm from 150 mm to 510 mm up
# (10 per column). Engraved: a soil line across at 120 mm with "SOIL", "MONSTERA" up the
# lower half of the first panel and "DELICIOSA" up the upper half of the second.

import "std/joints.aidl"

t = 5 mm
thickness t

H = 560 mm
Wp = 80 mm
spike = 120 mm
tip = 20 mm
ties = 10

def outline() = Polygon([(-tip / 2, 0), (tip / 2, 0), (Wp / 2, spike), (Wp / 2, H - Wp / 2),
                         (-Wp / 2, H - Wp / 2), (-Wp / 2, spike)])

def panel(from_top=true, word="MONSTERA") -> solid {
    body = outline()
    crown = Circle(center=(0, H - Wp / 2), radius=Wp / 2)
    if from_top {
        x = cross_halving(depth=H / 2, thickness=t, clearance=0.2 mm, cx=0 mm, cy=H)
    } else {
        x = cross_halving(depth=H / 2, thickness=t, clearance=0.2 mm, rotation=180 deg,
                          cx=0 mm, cy=0 mm)
    }
    hole tie {
        for i in range(ties) {
            l = Slot(center=(-24 mm, 150 mm + i * 40 mm), length=14 mm, width=5 mm, rotation=90 deg)
            r = Slot(center=(24 mm, 150 mm + i * 40 mm), length=14 mm, width=5 mm, rotation=90 deg)
        }
    }
    # FIX after the first valid program: the names and "SOIL" sat on the centre line, under
    # the crossing panel (W0532), and the soil line and the "O" ran over panel b's slot
    # (W0505): engrave them on one wing, between the slot and the tie holes, and the soil line
    # on each wing only.
    drawing marks {
        soil_l = Line((-Wp / 2, spike), (-t, spike))
        soil_r = Line((t, spike), (Wp / 2, spike))
        s = Text("SOIL", position=(Wp / 4 + 2 mm, spike + 4 mm), size=5)
        name = Text(word, position=(12 mm, H / 4 + 70 mm if from_top else 3 * H / 4 - 10 mm),
                    size=10, rotation=90 deg, valign="middle")
    }
}

assembly stake {
    a = panel(from_top=true, word="MONSTERA")
    b = panel(from_top=false, word="DELICIOSA")
    Place(a, position=(0, t / 2, 0), face="front", up="up")
    Place(b, position=(-t / 2, 0, 0), face="right", up="up")
    RightOf(b, a, gap=10)
    AlignBottom(b, a)

    assert a.bb.height == 560 mm and a.body.bb.width == 80 mm, "panels 80 x 560"
    assert a.x.depth + b.x.depth == 560 mm and a.x.depth == 280 mm, "halvings 280 + 280"
    assert a.body.points[2].y - a.body.points[1].y == 120 mm, "spike 120 mm long"
    assert a.body.points[1].x - a.body.points[0].x == 20 mm, "blunt 20 mm tip"
    assert len(a.tie.l) == 10 and len(a.tie.r) == 10, "10 tie holes per column"
    assert a.tie.l[0].center.y - a.body.points[0].y == 150 mm and
        a.tie.l[9].center.y - a.body.points[0].y == 510 mm, "tie holes from 150 to 510 mm up"
    assert a.tie.r[0].center.x - a.tie.l[0].center.x == 48 mm, "24 mm either side"
    assert distance(a.marks.name, a.tie) >= 2 mm and distance(b.marks.name, b.tie) >= 2 mm,
        "names clear of the tie holes"
    assert distance(b.marks.name, b.x) >= 2 mm and distance(a.marks.name, a.x) >= 2 mm,
        "names clear of the halving slots"
}
