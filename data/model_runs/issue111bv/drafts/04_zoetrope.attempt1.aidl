# Request: a table-top zoetrope cut from 3 mm birch ply (4 parts). The drum wall is one strip
# 110 mm tall that bends round a 180 mm base disc (the strip as long as the wall's middle
# line, pi x 183 mm), made flexible by living-hinge patches (2 mm pitch, 15 mm cuts, 3 mm
# bridges) between twelve viewing slits 3 mm wide and 40 mm long whose top ends stop 10 mm
# below the top edge, evenly spaced; each hinge patch stops 3 mm short of the slits. A
# 180 mm ring 10 mm wide is glued inside the top edge to keep it round. The base disc has an
# 8.5 mm hole for the 8 mm dowel it spins on, "ZOETROPE" engraved filled (bold, 10 mm) round
# a 45 mm radius, and twelve 18 mm engraved frame guides reaching to 2 mm from its rim. A
# 30 mm washer (8.5 mm bore) goes under the disc on the dowel.

import "std/plates.aidl"
import "std/shapes.aidl"

thickness 3 mm

T = 3 mm
DISC_D = 180 mm
WALL_H = 110 mm
L = pi * (DISC_D + T)          # the wall's middle line
N = 12
PITCH = L / N
SLIT_W = 3 mm
SLIT_L = 40 mm
SLIT_TOP = 10 mm                # below the top edge
MARGIN = 3 mm                   # hinge patch to slit
PATCH_W = 2 * floor((PITCH - SLIT_W - 2 * MARGIN) / 2)   # whole 2 mm pitches
END_W = PATCH_W / 2

def patch_x(k) = k * PITCH if (k > 0 and k < N) else (1 mm + END_W / 2 if k == 0 else L - 1 mm - END_W / 2)
def patch_w(k) = PATCH_W if (k > 0 and k < N) else END_W

assembly zoetrope {
    solid strip {
        body = Rectangle(bottom_left=(0, 0), width=L, height=WALL_H)
        hole slits {
            for k in range(N) {
                s = Slot(center=((k + 0.5) * PITCH, WALL_H - SLIT_TOP - SLIT_L / 2),
                         length=SLIT_L, width=SLIT_W, rotation=90 deg)
            }
        }
        for k in range(N + 1) {
            h = living_hinge(width=patch_w(k), height=WALL_H, pitch=2 mm, cut=15 mm, bridge=3 mm,
                             cx=patch_x(k), cy=WALL_H / 2)
        }
        assert len(slits.s) == 12, "twelve slits"
        assert slits.s[0].width == 3 mm and slits.s[0].length == 40 mm, "3 x 40 slits"
        assert body.bb.top - slits.s[0].bb.top == 10 mm, "slits stop 10 mm below the top"
        assert body.bb.height == 110 mm, "110 mm tall"
        # each patch 3 mm (at least) clear of the slits
        assert h[1].bb.right <= slits.s[1].bb.left - 3 mm, "hinge clear of the slit"
        assert h[1].bb.left >= slits.s[0].bb.right + 3 mm, "hinge clear of the slit"
        assert h[0].bb.right <= slits.s[0].bb.left - 3 mm, "end hinge clear of the slit"
    }

    solid disc {
        d = Circle(center=(0, 0), diameter=DISC_D)
        hole axle { c = Circle(center=(0, 0), diameter=8.5 mm) }
        drawing art {
            path = Circle(center=(0, 0), radius=45 mm, construction=true)
            title = Text("ZOETROPE", along=path, size=10, font="sans:Bold", fill=true)
            for k in range(N) {
                g = Line(start=polar((0, 0), DISC_D / 2 - 2 mm - 18 mm, k * 360 deg / N),
                         length=18 mm, angle=k * 360 deg / N)
            }
        }
        assert d.diameter == 180 mm, "180 mm disc"
    }

    solid top_ring {
        r = Circle(center=(0, 0), diameter=DISC_D)
        hole bore { c = Circle(center=(0, 0), diameter=DISC_D - 2 * 10 mm) }
    }

    spacer = washer(outer=30 mm, inner=8.5 mm)

    # flat on the sheet: the strip along the top, the round parts in a row below it
    Below(disc, strip, gap=6)
    AlignLeft(disc, strip)
    RightOf(top_ring, disc, gap=6)
    AlignCenterY(top_ring, disc)
    RightOf(spacer, top_ring, gap=6)
    AlignCenterY(spacer, disc)

    # assembled: disc at the bottom, strip standing round it (its top face inward), ring
    # inside the top edge, washer under the disc
    Place(disc, position=(0, 0, 0))
    Place(strip, position=(0, DISC_D / 2 + T, 0), rotation=(90 deg, 0, 0))
    Bend(strip, at=L / 2, angle=360 deg, radius=DISC_D / 2)
    Place(top_ring, position=(0, 0, WALL_H - T))
    Place(spacer, position=(0, 0, -T))

    assert abs(L - pi * 183 mm) < 0.01 mm, "strip as long as the wall's middle line"
}
