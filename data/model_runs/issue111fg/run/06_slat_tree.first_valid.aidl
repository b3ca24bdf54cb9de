# Request: a hanging slat Christmas tree for a small flat's wall, cut from 6 mm oak ply and
# strung on two cords like a rope ladder. Seven slats 40 mm tall with fully rounded ends,
# 600 mm long at the bottom to 150 mm at the top in equal steps (75 mm), 110 mm apart
# centre to centre. Every slat has two 6 mm cord holes 80 mm apart, centred, and 3 mm
# bauble holes 8 mm above its bottom edge at 90, 140, 190 ... mm either side of centre,
# none closer than 25 mm to the slat's end. A five-point star (outer radius 60, inner 26,
# tips rounded R4) hangs 100 mm above the top slat, with the two cord holes (5 mm, 24 mm
# apart, 10 mm below its centre) and a 4 mm hanging hole 35 mm above its centre. A trunk
# block 110 x 70 mm hangs 110 mm below the bottom slat, with the cord holes 20 mm above its
# centre and the year "2026" engraved under them, 16 mm bold.

units mm
thickness 6 mm

param n = 7, min = 4, max = 9
param pitch = 110 mm, min = 90, max = 140
L_bottom = 600 mm
L_top = 150 mm
step = (L_bottom - L_top) / (n - 1)

def slat(L=300 mm, y=0 mm) -> solid {
    body = RoundedRectangle(center=(0, y), width=L, height=40, corner_radius=20)
    hole cords {
        l = Circle(center=(-40, y), diameter=6)
        r = Circle(center=(40, y), diameter=6)
    }
    hole baubles {
        for j in range(max(0, floor((L / 2 - 25 mm - 90 mm) / 50 mm) + 1)) {
            bl = Circle(center=(-(90 mm + j * 50 mm), y - 20 mm + 8 mm), diameter=3)
            br = Circle(center=(90 mm + j * 50 mm, y - 20 mm + 8 mm), diameter=3)
        }
    }
}

assembly tree {
    for i in range(n) {
        s = slat(L=L_bottom - i * step, y=i * pitch)
    }
    solid star {
        shape = Star(center=(0, (n - 1) * pitch + 100 mm), points=5, outer_radius=60,
                     inner_radius=26, tip_radius=4)
        hole cords {
            l = Circle(center=(-12, (n - 1) * pitch + 90 mm), diameter=5)
            r = Circle(center=(12, (n - 1) * pitch + 90 mm), diameter=5)
        }
        hole hang { h = Circle(center=(0, (n - 1) * pitch + 135 mm), diameter=4) }
    }
    solid trunk {
        block = Rectangle(center=(0, -pitch), width=110, height=70)
        hole cords {
            l = Circle(center=(-40, -pitch + 20 mm), diameter=6)
            r = Circle(center=(40, -pitch + 20 mm), diameter=6)
        }
        drawing year {
            t = Text("2026", position=(0, -pitch - 12 mm), size=16, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    assert len(s) == 7, "seven slats"
    assert s[0].body.bb.width == 600 mm and s[6].body.bb.width == 150 mm, "600 to 150"
    assert s[0].body.bb.width - s[1].body.bb.width == 75 mm, "75 mm steps"
    assert s[1].body.center.y - s[0].body.center.y == 110 mm, "110 apart"
    assert s[3].cords.r.center.x - s[3].cords.l.center.x == 80 mm, "cords 80 apart"
    assert s[0].baubles.br[0].center.x == 90 mm, "first bauble hole 90 out"
    assert s[0].body.bb.right - s[0].baubles.br[3].center.x >= 25 mm, "25 from the end"
    assert s[0].baubles.br[0].center.y - s[0].body.bb.bottom == 8 mm, "8 above the edge"
    assert star.shape.center.y - s[6].body.center.y == 100 mm, "star 100 above"
    assert star.cords.r.center.x - star.cords.l.center.x == 24 mm, "star cords 24 apart"
    assert star.hang.h.center.y - star.shape.center.y == 35 mm, "hang hole 35 up"
    assert s[0].body.center.y - trunk.block.center.y == 110 mm, "trunk 110 below"
}
