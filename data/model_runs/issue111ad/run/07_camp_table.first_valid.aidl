# Camping: a flat-pack camp side table from 6 mm birch plywood that slots
# together without tools. Two legs 360 wide x 250 tall cross-halved into an X
# (seen from above a +): leg A slotted 125 deep from the top middle, leg B 125 deep
# from the bottom middle; each leg has a half-ellipse arch cut from the bottom
# middle, 220 wide and 60 high, leaving two feet, and 2 tabs 30 wide on its top
# edge that drop into the top. Top 400 x 400, corners R30, with the leg slots
# under its middle lines, an 80 mm cup hole centred 140 right and 140 below the
# middle, "COFFEE" engraved 6 mm high round the cup hole (baseline 46 mm from its
# centre, over its top), and a 100 x 30 hand slot centred 165 above the middle.

import "std/joints.aidl"

units mm
thickness 6 mm

param t = 6 mm, min = 4, max = 9
param top_size = 400 mm, min = 300, max = 500
param leg_w = 360 mm, min = 260, max = 460
param leg_h = 250 mm, min = 180, max = 350

def leg(from_top=true, w=360 mm, h=250 mm, t=6 mm) -> solid {
    body = Rectangle(center=(0, h / 2), width=w, height=h)
    hole arch {
        e = Ellipse(center=(0, 0), rx=110, ry=60)
    }
    tabs = tab_and_slot(part="tab", length=w, thickness=t, tabs=2, tab=30 mm, screw=0,
                        cx=0 mm, cy=h)
    if from_top {
        halving = cross_halving(depth=h / 2, thickness=t, cx=0 mm, cy=h)
    } else {
        halving = cross_halving(depth=h / 2, thickness=t, rotation=180 deg, cx=0 mm, cy=0 mm)
    }
}

assembly camp_table {
    solid top {
        board = RoundedRectangle(center=(0, 0), width=top_size, height=top_size, corner_radius=30)
        slots_a = tab_and_slot(part="slot", length=leg_w, thickness=t, tabs=2, tab=30 mm,
                               screw=0, cx=0 mm, cy=0 mm)
        slots_b = tab_and_slot(part="slot", length=leg_w, thickness=t, tabs=2, tab=30 mm,
                               screw=0, rotation=90 deg, cx=0 mm, cy=0 mm)
        hole cup {
            c = Circle(center=(140, -140), diameter=80)
        }
        hole hand {
            s = Slot(center=(0, 165), length=100, width=30)
        }
        drawing label {
            ring = Circle(center=(140, -140), radius=46, construction=true)
            word = Text("COFFEE", along=ring, size=6)
        }
        Concentric(label.ring, cup.c)
        assert board.bb.width == 400 mm and board.bb.height == 400 mm, "top 400 x 400"
        assert cup.c.center.x == 140 mm and cup.c.center.y == -140 mm, "cup hole 140 right, 140 down"
        assert cup.c.diameter == 80 mm, "80 mm cup hole"
        assert hand.s.center.y == 165 mm, "hand slot 165 above the middle"
    }

    leg_a = leg(from_top=true, w=leg_w, h=leg_h, t=t)
    leg_b = leg(from_top=false, w=leg_w, h=leg_h, t=t)

    RightOf(leg_a, top, gap=10)
    AlignTop(leg_a, top)
    Below(leg_b, leg_a, gap=10)
    AlignLeft(leg_b, leg_a)

    assert leg_a.body.bb.width == 360 mm and leg_a.body.bb.height == 250 mm, "legs 360 x 250"
    assert leg_a.halving.depth == 125 mm and leg_b.halving.depth == 125 mm, "halved 125 each"
    assert leg_a.arch.e.rx * 2 == 220 mm and leg_a.arch.e.ry == 60 mm, "arch 220 x 60"
}
