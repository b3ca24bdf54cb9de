# Request (science): a ray-optics set for a school ray box, cut from 6 mm clear acrylic, with
# a 6 mm ply storage tray. Pieces, each 80 mm tall where it is a lens:
#  - a biconvex lens 80 mm tall, 18 mm thick in the middle (two equal circular faces);
#  - a biconcave lens 80 x 18 mm, 6 mm thick in the middle (two equal circular faces);
#  - an equilateral prism of 60 mm sides;
#  - a semicircular block of radius 40 mm;
#  - a rectangular block 80 x 40 mm.
# The tray: a 300 x 150 mm base (corners r6) with an inlay of the same outline glued on it;
# the inlay has a pocket for each piece, 0.5 mm clear all round (the concave lens in a plain
# 19 x 81 rectangle), a 16 mm thumb hole on each pocket's edge, and each piece's name
# engraved under its pocket (5 mm letters).

thickness 6 mm
gap = 0.5 mm
h = 80 mm
t_vex = 18 mm
s_vex = t_vex / 2
r_vex = (s_vex ** 2 + (h / 2) ** 2) / (2 * s_vex)   # radius of a face through the lens' tips
side = 60 mm

# pocket centres on the tray
vex_at = (-120, 5)
cave_at = (-70, 5)
prism_at = (0, 0)
semi_at = (90, 15)
block_at = (90, -35)

assembly kit {
    solid convex {
        lens = Intersect(Circle(center=(r_vex - s_vex, 0), radius=r_vex),
                         Circle(center=(-(r_vex - s_vex), 0), radius=r_vex))
    }
    solid concave {
        top = Line((-9, 40), (9, 40))
        right = Arc(start=(9, 40), through=(3, 0), end=(9, -40))
        bottom = Line((9, -40), (-9, -40))
        left = Arc(start=(-9, -40), through=(-3, 0), end=(-9, 40))
    }
    solid prism {
        p = RegularPolygon(center=(0, 0), side=side, sides=3, rotation=90 deg)
    }
    solid semi {
        s = Sector(center=(0, 0), radius=40, start_angle=0 deg, end_angle=180 deg)
    }
    solid block {
        r = Rectangle(center=(0, 0), width=80, height=40)
    }

    solid base {
        body = RoundedRectangle(center=(0, 0), width=300, height=150, corner_radius=6)
    }
    solid inlay {
        body = RoundedRectangle(center=(0, 0), width=300, height=150, corner_radius=6)
        hole pockets {
            vex = Offset(Intersect(Circle(center=(vex_at[0] + r_vex - s_vex, vex_at[1]), radius=r_vex),
                                   Circle(center=(vex_at[0] - r_vex + s_vex, vex_at[1]), radius=r_vex)),
                         gap)
            cave = Rectangle(center=cave_at, width=18 + 2 * gap, height=80 + 2 * gap)
            pri = Offset(RegularPolygon(center=prism_at, side=side, sides=3, rotation=90 deg), gap)
            sem = Offset(Sector(center=semi_at, radius=40, start_angle=0 deg, end_angle=180 deg), gap)
            blk = Rectangle(center=block_at, width=80 + 2 * gap, height=40 + 2 * gap)
            th_vex = Circle(center=(vex_at[0] + s_vex, vex_at[1]), diameter=16)
            th_cave = Circle(center=(cave_at[0] + 9, cave_at[1]), diameter=16)
            th_pri = Circle(center=(prism_at[0], prism_at[1] - side / (2 * sqrt(3))), diameter=16)
            th_sem = Circle(center=semi_at, diameter=16)
            th_blk = Circle(center=(block_at[0] + 40, block_at[1]), diameter=16)
        }
        drawing names {
            n1 = Text("CONVEX", (vex_at[0], -50), size=5, valign="middle")
            n2 = Text("CONCAVE", (cave_at[0], -50), size=5, valign="middle")
            n3 = Text("PRISM", (prism_at[0], -30), size=5, valign="middle")
            # FIX after the first valid program: the label ran into the semicircle's thumb hole
            # (W0505); moved down into the free band between the semicircle and the block
            n4 = Text("SEMICIRCLE", (semi_at[0], 0), size=5, valign="middle")
            n5 = Text("BLOCK", (block_at[0], -65), size=5, valign="middle")
        }
    }

    # 3D: the tray, and each piece lying in its pocket
    Place(base, position=(0, 0, 0))
    Place(inlay, position=(0, 0, 6))
    Place(convex, position=(vex_at[0], vex_at[1], 6))
    Place(concave, position=(cave_at[0], cave_at[1], 6))
    Place(prism, position=(prism_at[0], prism_at[1], 6))
    Place(semi, position=(semi_at[0], semi_at[1], 6))
    Place(block, position=(block_at[0], block_at[1], 6))

    # on the sheet: tray parts one above the other, the acrylic pieces in a row beside them
    Above(inlay, base, gap=6)
    AlignLeft(inlay, base)
    RightOf(convex, base, gap=6)
    AlignBottom(convex, base)
    RightOf(concave, convex, gap=6)
    AlignBottom(concave, convex)
    RightOf(prism, concave, gap=6)
    AlignBottom(prism, concave)
    Above(semi, convex, gap=6)
    AlignLeft(semi, convex)
    Above(block, semi, gap=6)
    AlignLeft(block, semi)

    assert convex.lens.bb.width == 18 mm and convex.lens.bb.height == 80 mm, "convex 80 tall, 18 thick"
    assert concave.right.through.x - concave.left.through.x == 6 mm, "concave 6 thick in the middle"
    assert concave.bottom.length == 18 mm, "concave 18 at the edges"
    assert prism.p.bb.width == 60 mm, "prism sides 60"
    assert semi.s.bb.width == 80 mm and semi.s.bb.height == 40 mm, "semicircle r40"
    assert block.r.bb.width == 80 mm and block.r.bb.height == 40 mm, "block 80 x 40"
    assert inlay.pockets.vex.bb.width - convex.lens.bb.width == 1 mm, "0.5 clear each side"
    assert base.body.bb.width == 300 mm and base.body.bb.height == 150 mm, "tray 300 x 150"
}
