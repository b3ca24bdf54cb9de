# Request (science): a layered plant-cell model for a classroom, all 3 mm ply, glued up.
# A 280 x 180 mm base (R8) with the cell drawn on its left: the membrane engraved as a line
# 2 mm inside the cell wall; on the right a key: "PLANT CELL" (6 mm) over six numbered lines
# (3.5 mm): 1 CELL WALL, 2 MEMBRANE, 3 NUCLEUS, 4 VACUOLE, 5 CHLOROPLAST, 6 MITOCHONDRION.
# Glued on the base: the cell wall, a ring 200 x 140 mm outside (R20), 7 mm wide, "1" engraved
# on its top band; a 48 x 38 mm oval nucleus with a filled 10 mm nucleolus and "3"; a rounded
# vacuole blob about 90 x 72 mm with "4"; three chloroplasts, 26 x 14 mm ovals with two grana
# lines each; two mitochondria, 24 x 10 mm capsules with a zigzag of cristae. The numbers 2, 5
# and 6 are engraved on the base beside the membrane, a chloroplast and a mitochondrion.
# Organelles at least 3 mm from each other and inside the membrane.

units mm
thickness 3 mm

cx = -30 mm     # the cell's centre on the base

assembly plant_cell {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=280, height=180, corner_radius=8)
        drawing marks {
            membrane = RoundedRectangle(center=(cx, 0), width=182, height=122, corner_radius=11)
            n2 = Text("2", position=(-116, 0), size=3, valign="middle")
            n5 = Text("5", position=(15, -58), size=3, valign="middle")
            n6 = Text("6", position=(59, -38), size=3, valign="middle")
            title = Text("PLANT CELL", position=(80, 70), size=6, anchor="start", valign="middle")
            names = ["1 CELL WALL", "2 MEMBRANE", "3 NUCLEUS", "4 VACUOLE", "5 CHLOROPLAST", "6 MITOCHONDRION"]
            for i in range(6) {
                key = Text(names[i], position=(80, 50 - i * 12), size=3.5, anchor="start",
                           valign="middle", max_width=56)
            }
        }
    }
    solid wall {
        outer = RoundedRectangle(center=(cx, 0), width=200, height=140, corner_radius=20)
        hole inside { r = RoundedRectangle(center=(cx, 0), width=186, height=126, corner_radius=13) }
        drawing mark { n1 = Text("1", position=(cx, 66.5), size=4, valign="middle") }
    }
    solid nucleus {
        e = Ellipse(center=(25, 30), rx=24, ry=19)
        drawing mark {
            nucleolus = Circle(center=(31, 35), radius=5, fill=true)
            n3 = Text("3", position=(17, 24), size=5, valign="middle")
        }
    }
    solid vacuole {
        s = Spline([(-95, 10), (-80, 38), (-45, 41), (-12, 30), (-5, 0), (-20, -28), (-55, -31),
                    (-88, -20)], closed=true)
        drawing mark { n4 = Text("4", position=(-50, 5), size=6, valign="middle") }
    }
    chloro_at = [(-103, 47, 20), (-103, -42, -20), (15, -45, 10)]
    for i in range(3) {
        p = chloro_at[i]
        solid chloro {
            e = Ellipse(center=(p[0], p[1]), rx=13, ry=7, rotation=p[2] * 1 deg)
            drawing grana {
                g1 = Line(polar((p[0], p[1]), 5, (p[2] + 60) * 1 deg), polar((p[0], p[1]), 5, (p[2] + 120) * 1 deg))
                g2 = Line(polar((p[0], p[1]), 5, (p[2] - 60) * 1 deg), polar((p[0], p[1]), 5, (p[2] - 120) * 1 deg))
            }
        }
    }
    mito_at = [(50, -20, 70), (-60, -52, 0)]
    for i in range(2) {
        q = mito_at[i]
        solid mito {
            s = Slot(center=(q[0], q[1]), length=24, width=10, rotation=q[2] * 1 deg)
            drawing cristae {
                z = Polyline([polar((q[0], q[1]), 8, q[2] * 1 deg + 180 deg),
                              polar(polar((q[0], q[1]), 4, q[2] * 1 deg + 180 deg), 2.5, q[2] * 1 deg + 90 deg),
                              (q[0], q[1]),
                              polar(polar((q[0], q[1]), 4, q[2] * 1 deg), 2.5, q[2] * 1 deg - 90 deg),
                              polar((q[0], q[1]), 8, q[2] * 1 deg)])
            }
        }
    }
    # the flat picture is the model as glued: the pieces lie on the base
    AllowOverlap(base, wall, nucleus, vacuole, chloro, mito)
    Place(base, position=(0, 0, 0), face="up")
    Place(wall, position=(0, 0, 3), face="up")
    Place(nucleus, position=(0, 0, 3), face="up")
    Place(vacuole, position=(0, 0, 3), face="up")
    for i in range(3) { Place(chloro[i], position=(0, 0, 3), face="up") }
    for i in range(2) { Place(mito[i], position=(0, 0, 3), face="up") }

    assert base.body.bb.width == 280 mm and base.body.bb.height == 180 mm, "base 280 x 180"
    assert wall.outer.bb.width == 200 mm and wall.outer.bb.height == 140 mm, "wall 200 x 140"
    assert wall.outer.bb.right - wall.inside.r.bb.right == 7 mm, "wall 7 mm wide"
    assert wall.inside.r.bb.right - base.marks.membrane.bb.right == 2 mm, "membrane 2 mm inside"
    assert nucleus.e.bb.width == 48 mm and nucleus.e.bb.height == 38 mm, "nucleus 48 x 38"
    assert len(chloro) == 3 and len(mito) == 2, "three chloroplasts, two mitochondria"
    assert len(base.marks.key) == 6, "six key lines"
    assert distance(nucleus, vacuole) >= 3 mm, "nucleus clear of the vacuole"
    assert distance(chloro[0], vacuole) >= 3 mm and distance(chloro[1], vacuole) >= 3 mm and distance(chloro[2], vacuole) >= 3 mm, "chloroplasts clear of the vacuole"
    assert distance(mito[0], nucleus) >= 3 mm and distance(mito[1], vacuole) >= 3 mm and distance(mito[0], chloro[2]) >= 3 mm, "mitochondria clear"
    assert distance(mito[1], chloro[1]) >= 3 mm and distance(chloro[2], mito[1]) >= 3 mm, "mitochondria clear of chloroplasts"
    assert vacuole.s.bb.left >= base.marks.membrane.bb.left + 3 mm and chloro[0].e.bb.left >= base.marks.membrane.bb.left + 3 mm and chloro[1].e.bb.left >= base.marks.membrane.bb.left + 3 mm, "inside the membrane (left)"
    assert chloro[0].e.bb.top <= base.marks.membrane.bb.top - 3 mm and nucleus.e.bb.top <= base.marks.membrane.bb.top - 3 mm, "inside the membrane (top)"
    assert mito[1].s.bb.bottom >= base.marks.membrane.bb.bottom + 3 mm and chloro[1].e.bb.bottom >= base.marks.membrane.bb.bottom + 3 mm, "inside the membrane (bottom)"
    assert mito[0].s.bb.right <= base.marks.membrane.bb.right - 3 mm and nucleus.e.bb.right <= base.marks.membrane.bb.right - 3 mm, "inside the membrane (right)"
    assert base.marks.key[5].bb.right <= base.body.bb.right - 3 mm, "key on the base"
}
