# Request: a catenary-arch demonstration for the school physics club: seven voussoirs that
# stand with no glue once the former is pulled out, cut from 6 mm MDF (cut four sets and
# laminate each block to 24 mm deep).
# - The arch's centre line is the catenary y = rise + a - a cosh(x / a) with a 180 mm span
#   between its feet and a 180 mm rise to its crown; the arch is 30 mm thick (15 mm either
#   side of the centre line, measured square to it).
# - Seven blocks of equal length along the centre line, each joint square to the centre line;
#   the two foot blocks cut flat (horizontal) where they sit on the base. Each block's
#   number 1-7 engraved at its middle, 8 mm tall.
# - A former (centring) under the arch: its top follows the intrados 0.5 mm below it, its
#   feet on the base, two 30 mm tabs into mortises in the base (0.3 mm clearance, a loose
#   fit, so it lifts out), a 30 mm finger hole 60 mm up.
# - Base 260 x 80 mm: the mortises on its middle line, the blocks' footprints (24 mm deep)
#   engraved, "CATENARY ARCH" and the value of a engraved.

import "std/joints.aidl"

thickness 6 mm

span = 180 mm
rise = 180 mm
h = 15 mm                 # half the arch's thickness
n = 7
t = 6 mm
layers_deep = 24 mm

def ch(u) = (exp(u) + exp(-u)) / 2
def sh(u) = (exp(u) - exp(-u)) / 2
def ash(z) = log(z + sqrt(z * z + 1))
def ach(z) = log(z + sqrt(z * z - 1))

# a from a (cosh(span / 2a) - 1) = rise, by fixed-point steps
def step(a) = span / 2 / ach(1 + rise / a)
a1 = step(50 mm)
a2 = step(a1)
a3 = step(a2)
a4 = step(a3)
a5 = step(a4)
a6 = step(a5)
a7 = step(a6)
a8 = step(a7)
a9 = step(a8)
a10 = step(a9)
a11 = step(a10)
a12 = step(a11)
a13 = step(a12)
a14 = step(a13)
a = step(a14)

S = a * sh(span / 2 / a)          # half the centre line's length
ds = 2 * S / n

def cx(s) = a * ash(s / a)                    # x at arc length s from the crown
def cy(x) = rise + a - a * ch(x / a)
def nx(x) = sh(x / a) / ch(x / a)             # outward normal
def ny(x) = 1 / ch(x / a)
def outer(s, flat) = (cx(s) + h * nx(cx(s)), 0 mm if flat else cy(cx(s)) + h * ny(cx(s)))
def inner(s, flat, g) = (cx(s) - (h + g) * nx(cx(s)),
                         0 mm if flat else cy(cx(s)) - (h + g) * ny(cx(s)))
def s_at(k, j) = -S + k * ds + j * ds / 4
def block_pts(k) = ([outer(s_at(k, j), (k == 0 and j == 0) or (k == n - 1 and j == 4))
                     for j in range(5)] +
                    [inner(s_at(k, 4 - j), (k == 0 and j == 4) or (k == n - 1 and j == 0), 0 mm)
                     for j in range(5)])

# the former's top: the intrados 0.5 mm lower, sampled; its feet at the base's top (y = 0)
x_foot_in = cx(-S) - (h + 0.5 mm) * nx(cx(-S))     # left foot of the intrados (x < 0)
def fy(s) = max(0 mm, cy(cx(s)) - (h + 0.5 mm) * ny(cx(s)))
def fx(s) = cx(s) - (h + 0.5 mm) * nx(cx(s))
former_top = [(fx(-S + i * 2 * S / 24), fy(-S + i * 2 * S / 24)) for i in range(25)]

assembly catenary_arch {
    for k in range(n) {
        solid block {
            p = Polygon(block_pts(k))
            drawing number {
                l = Text(str(k + 1), position=(cx(s_at(k, 2)), cy(cx(s_at(k, 2)))), size=8,
                         valign="middle")
            }
        }
    }

    solid former {
        p = Polygon(former_top + [(-x_foot_in, -t), (x_foot_in, -t)])
        feet = tab_and_slot(part="tab", length=-2 * x_foot_in, thickness=t, tabs=2, tab=30 mm,
                            screw=0, rotation=180 deg, cx=0 mm, cy=-t)
        hole grip {
            c = Circle(center=(0, 60), diameter=30)
        }
    }

    solid base {
        body = Rectangle(center=(0, -120), width=260, height=80)
        m = tab_and_slot(part="slot", length=-2 * x_foot_in, thickness=t, tabs=2, tab=30 mm,
                         screw=0, clearance=0.3 mm, cx=0 mm, cy=-120 mm)
        drawing marks {
            fl = Rectangle(corner=(-cx(S) - h * nx(cx(S)), -120 - layers_deep / 2),
                           opposite=(-cx(S) + h * nx(cx(S)), -120 + layers_deep / 2))
            fr = Rectangle(corner=(cx(S) - h * nx(cx(S)), -120 - layers_deep / 2),
                           opposite=(cx(S) + h * nx(cx(S)), -120 + layers_deep / 2))
            title = Text("CATENARY ARCH", position=(0, -120 - 28), size=6, valign="middle")
            value = Text(f"y = a cosh(x/a),  a = {a:.1f} mm", position=(0, -120 + 28), size=4,
                         valign="middle")
        }
        Fixed(body)
    }

    # 3D: the blocks and the former stand in the plane y = 0 (one 6 mm layer shown), the base
    # flat under them
    for k in range(n) {
        Place(block[k], position=(0, t / 2, 0), face="front", up="up")
    }
    Place(former, position=(0, t / 2, 0), face="front", up="up")
    Place(base, position=(0, 120 mm, -t), face="up")

    assert abs(cy(span / 2)) < 0.01 mm and abs(cy(-span / 2)) < 0.01 mm, "feet 180 apart"
    assert abs(cy(0 mm) - 180 mm) < 0.001 mm, "rise 180"
    assert len(block) == 7, "seven blocks"
    assert abs(distance(outer(0 mm, false), inner(0 mm, false, 0 mm)) - 30 mm) < 0.001 mm, "30 thick"
    assert abs(block[0].p.bb.bottom) < 0.001 mm and abs(block[6].p.bb.bottom) < 0.001 mm, "feet flat on the base"
    assert distance(former, block[3]) >= 0.45 mm, "former 0.5 under the keystone"
    assert distance(former, block[1]) >= 0.45 mm, "former clear of the blocks"
    assert former.grip.c.center.y == 60 mm and former.grip.c.diameter == 30 mm, "finger hole"
    assert base.body.bb.width == 260 mm and base.body.bb.height == 80 mm, "base 260 x 80"
    assert distance(base.marks.title, base.m) >= 2 mm and distance(base.marks.value, base.m) >= 2 mm, "text clear of the mortises"
}
