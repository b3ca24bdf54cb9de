# Request (pets): a kitten's play arch, cut from 6 mm birch ply. A base board 500 x 220 mm with
# R20 corners. Two half-ring arches stand on it, 100 mm apart between their inner faces: each
# arch is 440 mm across outside (radius 220) with a 40 mm band, and each foot has a 20 mm tenon
# glued into a mortise in the base. A top bar 100 x 40 mm joins the arches at their crown with a
# 20 mm tenon through a mortise in each arch; it has two 6 mm cord holes 50 mm apart, 10 mm below
# its middle, to hang toys from. Each arch also has 6 mm cord holes at 45 and 135 deg on the
# middle of its band. Two fish toys 95 mm long (70 x 36 mm body, a 25 mm tail), each with an eye
# hole and a 5 mm cord hole. The cat's name MISO engraved on the base in front of the arches,
# 20 mm bold filled.

import "std/joints.aidl"

thickness 6 mm

param t = 6 mm, min = 4 mm, max = 9 mm
r_out = 220 mm
band = 40 mm
foot_x = r_out - band / 2
gap_between = 100 mm
arch_y = gap_between / 2 + t / 2
tenon = 20 mm

def arch() -> solid {
    ring = Sector(center=(0, 0), radius=r_out, start_angle=0 deg, end_angle=180 deg,
                  inner_radius=r_out - band)
    foot_l = Rectangle(center=(-foot_x, -t / 2), width=band, height=t)
    foot_r = Rectangle(center=(foot_x, -t / 2), width=band, height=t)
    tab_l = tab_and_slot(part="tab", length=band, thickness=t, tabs=1, tab=tenon, screw=0,
                         rotation=180 deg, cx=-foot_x, cy=-t)
    tab_r = tab_and_slot(part="tab", length=band, thickness=t, tabs=1, tab=tenon, screw=0,
                         rotation=180 deg, cx=foot_x, cy=-t)
    hole crown { r = Rectangle(center=(0, foot_x), width=t, height=tenon) }
    hole cord_l { c = Circle(center=(foot_x * cos(135 deg), foot_x * sin(135 deg)), diameter=6) }
    hole cord_r { c = Circle(center=(foot_x * cos(45 deg), foot_x * sin(45 deg)), diameter=6) }
}

def fish() -> solid {
    body = Ellipse(center=(0, 0), rx=35, ry=18)
    # FIX after the first valid program: the tail's apex only 5 mm into the body left a ~4 mm
    # neck a cat could bite through; now 15 mm in (a ~10 mm neck), filleted R3 where they meet,
    # still showing 25 mm past the body's end
    tail = Triangle(center=(35 - 15 + 40 / 2, 0), base=30, height=40, rotation=90 deg)
    Fillet([body, tail], 3)
    hole eye { c = Circle(center=(-20, 4), radius=3) }
    hole cord { c = Circle(center=(0, 10), diameter=5) }
}

assembly cat_play_arch {
    solid base {
        board = RoundedRectangle(center=(0, 0), width=500, height=220, corner_radius=20)
        for sy in [-arch_y, arch_y] {
            for sx in [-foot_x, foot_x] {
                m = tab_and_slot(part="slot", length=band, thickness=t, tabs=1, tab=tenon,
                                 screw=0, cx=sx, cy=sy)
            }
        }
        drawing name {
            word = Text("MISO", position=(0, -85), size=20, font="sans:Bold", valign="middle",
                        fill=true)
        }
    }
    arch_a = arch()
    arch_b = arch()

    solid bar {
        body = Rectangle(center=(0, 0), width=gap_between, height=band)
        tenon_l = Rectangle(center=(-(gap_between + t) / 2, 0), width=t, height=tenon)
        tenon_r = Rectangle(center=((gap_between + t) / 2, 0), width=t, height=tenon)
        hole cords {
            for i in range(2) { c = Circle(center=(-25 + 50 * i, -10), diameter=6) }
        }
    }
    fish_a = fish()
    fish_b = fish()

    # flat on the sheet
    Above(arch_a, base, gap=10)
    AlignLeft(arch_a, base)
    Above(arch_b, arch_a, gap=10)
    AlignLeft(arch_b, base)
    RightOf(bar, base, gap=10)
    AlignBottom(bar, base)
    Above(fish_a, bar, gap=10)
    AlignLeft(fish_a, bar)
    Above(fish_b, fish_a, gap=10)
    AlignLeft(fish_b, bar)

    # assembled
    Place(base, position=(0, 0, 0))
    Place(arch_a, position=(0, -arch_y + t / 2, t), face="front", up="up")
    Place(arch_b, position=(0, arch_y + t / 2, t), face="front", up="up")
    Place(bar, position=(-t / 2, 0, t + foot_x), face="right", up="up")
    # the fish hang under the bar's cord holes (y = -25 and 25), at two heights
    Place(fish_a, position=(0, -25 + t / 2, 150), face="front", up="up")
    Place(fish_b, position=(0, 25 + t / 2, 110), face="front", up="up")

    assert base.board.width == 500 mm and base.board.height == 220 mm, "base 500 x 220"
    assert arch_a.ring.bb.width == 440 mm, "arch 440 mm across"
    assert arch_a.ring.width == 40 mm, "40 mm band"
    assert 2 * arch_y - t == 100 mm, "arches 100 mm apart inside"
    assert bar.body.width == 100 mm and bar.body.height == 40 mm, "bar 100 x 40"
    assert bar.cords.c[1].center.x - bar.cords.c[0].center.x == 50 mm, "bar cord holes 50 apart"
    assert fish_a.bb.width == 95 mm, "fish 95 mm long"
    assert len(base.m) == 2 and len(base.m[0]) == 2, "four mortises in the base"
}
