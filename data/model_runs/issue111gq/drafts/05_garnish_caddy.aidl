# Request: a cocktail-party garnish caddy for the bar, cut from 3 mm birch ply. An open
# finger-jointed tray 240 x 90 x 50 mm (outside) in 4 equal compartments along its length, for
# lime, lemon, orange and cherries. A lift-off lid: a 240 x 90 mm top plate with a 38 mm hole over
# the middle of each compartment and the fruit's name engraved (filled, bold) 8 mm in front of
# its hole, glued onto a locating plate that drops inside the walls with 0.3 mm clearance each
# side and has the same holes; the dividers stop 3 mm below the walls' top so the locating plate
# rests on them. Lid corners R6.

import "std/boxes.aidl"

t = 3 mm
thickness t

L = 240 mm
Wd = 90 mm
Ht = 50 mm
n = 4
hole_d = 38 mm
fruits = ["LIME", "LEMON", "ORANGE", "CHERRY"]
inner_l = L - 2 * t
inner_w = Wd - 2 * t
cell = (inner_l - (n - 1) * t) / n
def comp_x(i) = -inner_l / 2 + cell * (i + 0.5) + i * t

def lid_holes() -> hole {
    for i in range(n) {
        c = Circle(center=(comp_x(i), 0), diameter=hole_d)
    }
}

assembly garnish_caddy {
    tray = divider_tray(length=L, width=Wd, height=Ht, rows=1, cols=n, thickness=t,
                        finger=10 mm, clearance=0.3 mm, outside=true,
                        divider_height=Ht - t - t)
    solid lid {
        body = RoundedRectangle(center=(0, 0), width=L, height=Wd, corner_radius=6 mm)
        holes = lid_holes()
        drawing names {
            for i in range(n) {
                w = Text(fruits[i], position=(comp_x(i), -hole_d / 2 - 8 mm), size=6,
                         font="sans:Bold", valign="top", fill=true)
            }
        }
    }
    solid plate {
        body = Rectangle(center=(0, 0), width=inner_l - 2 * 0.3 mm, height=inner_w - 2 * 0.3 mm)
        holes = lid_holes()
    }
    Place(lid, position=(0, 0, Ht), face="up")
    Place(plate, position=(0, 0, Ht - t), face="up")

    # flat layout
    Below(lid, tray, gap=8)
    AlignLeft(lid, tray)
    RightOf(plate, lid, gap=8)
    AlignTop(plate, lid)

    # the request's numbers
    assert lid.body.bb.width == 240 mm and lid.body.bb.height == 90 mm, "lid 240 x 90"
    assert len(lid.holes.c) == 4 and len(fruits) == 4, "four compartments, four holes"
    assert lid.holes.c[0].diameter == 38 mm, "38 mm holes"
    assert inner_l - plate.body.width == 2 * 0.3 mm and inner_w - plate.body.height == 2 * 0.3 mm,
        "0.3 mm clearance each side"
    assert tray.divider_height == 50 mm - 3 mm - 3 mm, "dividers 3 mm below the walls' top"
    assert lid.holes.c[1].center.x - lid.holes.c[0].center.x == cell + t, "holes over the compartments"
    assert lid.holes.c[0].center.x - lid.body.bb.left > hole_d / 2 + t, "end hole clear of the end wall"
    assert lid.holes.c[0].center.y - lid.names.w[0].position.y == 38 mm / 2 + 8 mm, "names 8 mm in front of the holes"
    assert distance(lid.names, lid.holes) >= 6 mm, "names clear of the holes"
    assert lid.names.bb.bottom - lid.body.bb.bottom >= 4 mm, "names on the lid"
}
