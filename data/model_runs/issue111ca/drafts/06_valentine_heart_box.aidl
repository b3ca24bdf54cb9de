# Request (holidays): a Valentine's heart-shaped box from 3 mm birch ply, its wall bent round
# on a living hinge. The wall's middle line is a heart: two 72 mm circles whose centres are
# 64 mm apart, and a point 84 mm below the centres, joined by straight lines tangent to the
# circles. The box is 60 mm tall outside: a heart base and lid (the middle-line heart grown
# by half the wall), the wall standing on the base between them, and under the lid and on
# the base a lip (the heart shrunk by half the wall and 0.3 mm of play) glued on, so the lid
# sits in the wall. The wall is one strip as long as the middle line, its ends meeting at
# the heart's point, with a living hinge over both round lobes and the dip between them.
# "BE MINE" engraved filled on the lid (serif bold, at most 90 mm wide).

import "std/plates.aidl"

thickness 3 mm

T = 3 mm
play = 0.3 mm
r0 = 36 mm              # lobes' radius (middle line)
a = 32 mm               # lobes' centres: x = +-a
b = 20 mm               # lobes' centres: y = b
c = 64 mm               # the point: (0, -c), 84 mm below the centres
box_h = 60 mm
wall_h = box_h - 2 * T  # the wall stands on the base, the lid on the wall

# the middle line's length: two tangent lines and two lobe arcs up to the dip
dd = sqrt(a ** 2 + (b + c) ** 2)          # point to a lobe's centre
tl = sqrt(dd ** 2 - r0 ** 2)              # tangent line
phi = atan2(-(b + c), -a)                 # from the right lobe's centre to the point
theta_t = phi + acos(r0 / dd)             # where the tangent line meets the right lobe
theta_d = atan2(sqrt(r0 ** 2 - a ** 2), -a)   # the dip, seen from the right lobe's centre
arc_ang = theta_d - theta_t
arc_len = r0 * degrees(arc_ang) * pi / 180
P0 = 2 * (tl + arc_len)
dip_turn = 180 deg - 2 * theta_d          # the wall's turn at the dip (a right turn)

# the wall's start: at the point, heading up the right tangent line
tx = a + r0 * cos(theta_t)
ty = b + r0 * sin(theta_t)
alpha = atan2(ty + c, tx)

def heart(grow) -> solid {
    left = Offset(Hull(Circle(center=(-a, b), radius=r0), Point(0, -c)), grow)
    right = Offset(Hull(Circle(center=(a, b), radius=r0), Point(0, -c)), grow)
}

# the lip: the heart shrunk by d, drawn as the hull of the shrunk lobes and the shrunk point
# (both halves share the point, so no slit opens between them there)
d_lip = T / 2 + play
half_tip = 90 deg - alpha                 # half the point's angle
def lip() -> solid {
    left = Hull(Circle(center=(-a, b), radius=r0 - d_lip), Point(0, -c + d_lip / sin(half_tip)))
    right = Hull(Circle(center=(a, b), radius=r0 - d_lip), Point(0, -c + d_lip / sin(half_tip)))
}

# FIX after the first valid program (W0517, lips and wall colliding 0.63 mm deep in the
# assembled view, then 0.24 mm after a first try): the dip is a fold round no inside radius
# whose crease is on the wall's outer face, where the outer face's two circles (r0 + T/2)
# meet; each lobe's middle line therefore ends short of the middle-line heart's dip, and the
# wall is shorter than the sharp middle line by 2.2 mm (a P0-long strip would overlap itself
# by that at the point). The strip is now the folded middle line's length and the bends
# follow it exactly.
theta_f = atan2(sqrt((r0 + T / 2) ** 2 - a ** 2), -a)   # the crease, seen from the right lobe
lobe_ang = theta_f - theta_t
lobe_w = r0 * degrees(lobe_ang) * pi / 180
fold = 180 deg - 2 * theta_f                      # the wall's turn at the dip (a right turn)
dip_w = abs(degrees(fold)) * pi / 180 * T / 2
Pw = 2 * tl + 2 * lobe_w + dip_w
lobe_r = r0 - T / 2

assembly box {
    base = heart(grow=T / 2)
    solid lid {
        shape = heart(grow=T / 2)
        drawing words {
            t = Text("BE MINE", position=(0, 10), size=18, font="serif:Bold", valign="middle",
                     max_width=90 mm, fill=true)
        }
    }
    base_lip = lip()
    lid_lip = lip()
    solid wall {
        strip = Rectangle(center=(0, 0), width=Pw, height=wall_h)
        flex = living_hinge(width=Pw - 2 * tl, height=wall_h, cx=0, cy=0)
    }

    # flat on the sheet
    base.bb.center == (0, 0)
    RightOf(lid, base, gap=5)
    AlignCenterY(lid, base)
    RightOf(base_lip, lid, gap=5)
    AlignCenterY(base_lip, lid)
    RightOf(lid_lip, base_lip, gap=5)
    AlignCenterY(lid_lip, base_lip)
    Below(wall, base, gap=5)
    AlignLeft(wall, base)

    # in 3D: the base on the table, its lip on it, the wall round the lip, the lid on top
    Place(base, position=(0, 0, 0))
    Place(base_lip, position=(0, 0, T))
    Place(lid_lip, position=(0, 0, wall_h))
    Place(lid, position=(0, 0, T + wall_h))
    Place(wall, rotation=(90 deg, 0, alpha),
          position=(Pw / 2 * cos(alpha) - T / 2 * sin(alpha),
                    -c + Pw / 2 * sin(alpha) + T / 2 * cos(alpha), T + wall_h / 2))
    Bend(wall, at=-(dip_w + lobe_w) / 2, angle=-lobe_ang, radius=lobe_r)
    Bend(wall, at=0, angle=-fold, radius=0)
    Bend(wall, at=(dip_w + lobe_w) / 2, angle=-lobe_ang, radius=lobe_r)

    assert distance(base.left.bb.center, base.right.bb.center) > 0 mm, "two lobes"
    assert 2 * a == 64 mm and 2 * r0 == 72 mm and b + c == 84 mm, "the heart as requested"
    assert wall.strip.bb.height + 2 * T == 60 mm, "60 mm tall outside"
    assert base.bb.width == 2 * (a + r0) + T, "base covers the wall"
    assert lid.words.t.bb.width <= 90 mm, "BE MINE at most 90 wide"
    assert P0 > 400 mm and P0 < 420 mm, "middle line about 412 mm"
    assert P0 - Pw > 2 mm and P0 - Pw < 2.5 mm, "the fold takes about 2.2 mm"
}
