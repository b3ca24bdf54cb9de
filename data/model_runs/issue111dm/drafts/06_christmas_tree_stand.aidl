# Request (holidays): a stand for a small real Christmas tree (trunk up to 32 mm), 6 mm
# birch ply. A base disc 260 mm across and a collar disc 120 mm across with a 34 mm hole
# for the trunk, held 100 mm apart (base top to collar bottom) by three fins at 120
# degrees. Each fin runs from 20 mm off the axis out to 120 mm at the base and to 58 mm at
# the collar, its outer edge a curve bowing in (through 80 mm out at 45 mm up), with a
# five-pointed star (28 mm across) cut through it; two 20 mm tabs into radial mortises in
# the base, one 16 mm tab into a mortise in the collar. The base is engraved filled round its
# rim between the fins: MERRY, CHRISTMAS and 2026.

import "std/joints.aidl"

thickness 6 mm
t = 6 mm

fin_h = 100 mm
fin_in = 20 mm
fin_out = 120 mm
fin_top = 58 mm
fin_angles = [90 deg, 210 deg, 330 deg]

def fin() -> solid {
    bottom = Line((fin_in, 0), (fin_out, 0))
    curve = Arc(start=(fin_out, 0), through=(80, 45), end=(fin_top, fin_h))
    top = Line((fin_top, fin_h), (fin_in, fin_h))
    inner = Line((fin_in, fin_h), (fin_in, 0))
    foot = Rectangle(bottom_left=(fin_in, -t), width=fin_out - fin_in, height=t)
    head = Rectangle(bottom_left=(fin_in, fin_h), width=fin_top - fin_in, height=t)
    foot_t = tab_and_slot(part="tab", length=fin_out - fin_in, thickness=t, tabs=2, tab=20,
                          screw=0, rotation=180 deg, cx=(fin_in + fin_out) / 2, cy=-t)
    head_t = tab_and_slot(part="tab", length=fin_top - fin_in, thickness=t, tabs=1, tab=16,
                          screw=0, rotation=0 deg, cx=(fin_in + fin_top) / 2, cy=fin_h + t)
    hole star { s = Star(center=(52, 45), points=5, outer_radius=14, inner_radius=6) }
}

assembly tree_stand {
    solid base {
        disc = Circle(center=(0, 0), diameter=260)
        for a in fin_angles {
            m = tab_and_slot(part="slot", length=fin_out - fin_in, thickness=t, tabs=2, tab=20,
                             screw=0, rotation=a, cx=(fin_in + fin_out) / 2 * cos(a),
                             cy=(fin_in + fin_out) / 2 * sin(a))
        }
        drawing greeting {
            ring = Circle(center=(0, 0), radius=112, construction=true)
            w1 = Text("MERRY", along=ring, angle=150 deg, size=9, font="sans:Bold",
                      valign="middle", fill=true)
            w2 = Text("CHRISTMAS", along=ring, angle=270 deg, size=9, font="sans:Bold",
                      valign="middle", flip=true, fill=true)
            w3 = Text("2026", along=ring, angle=30 deg, size=9, font="sans:Bold",
                      valign="middle", fill=true)
        }
    }

    solid collar {
        disc = Circle(center=(0, 0), diameter=120)
        hole trunk { c = Circle(center=(0, 0), diameter=34) }
        for a in fin_angles {
            m = tab_and_slot(part="slot", length=fin_top - fin_in, thickness=t, tabs=1, tab=16,
                             screw=0, rotation=a, cx=(fin_in + fin_top) / 2 * cos(a),
                             cy=(fin_in + fin_top) / 2 * sin(a))
        }
    }

    f1 = fin()
    f2 = fin()
    f3 = fin()

    # on the sheet
    RightOf(collar, base, gap=10)
    AlignTop(collar, base)
    Below(f1, collar, gap=10)
    AlignLeft(f1, collar)
    RightOf(f2, collar, gap=10)
    AlignTop(f2, collar)
    Below(f3, f2, gap=10)
    AlignLeft(f3, f2)

    # in 3D: fins stand on the base, radial, their mid-planes through the axis
    Place(base, position=(0, 0, 0), face="up", up="back")
    Place(collar, position=(0, 0, t + fin_h), face="up", up="back")
    Place(f1, position=(-sin(90 deg) * t / 2, cos(90 deg) * t / 2, t),
          face=(sin(90 deg), -cos(90 deg), 0), up="up")
    Place(f2, position=(-sin(210 deg) * t / 2, cos(210 deg) * t / 2, t),
          face=(sin(210 deg), -cos(210 deg), 0), up="up")
    Place(f3, position=(-sin(330 deg) * t / 2, cos(330 deg) * t / 2, t),
          face=(sin(330 deg), -cos(330 deg), 0), up="up")

    # the request's numbers
    assert base.disc.diameter == 260 mm and collar.disc.diameter == 120 mm
    assert collar.trunk.c.diameter == 34 mm
    assert f1.inner.length == 100 mm
    assert f1.bottom.end.x - f1.inner.start.x == 120 mm - 20 mm
    assert f1.star.s.bb.width <= 28 mm and f1.star.s.outer_radius * 2 == 28 mm
    assert len(base.m) == 3 and len(base.m[0].slot) == 2 and len(collar.m[0].slot) == 1
}
