# Pets: a budgie (parakeet) swing for the cage, cut from 4 mm basswood. Two teardrop side
# pieces 140 mm tall (a 50 mm round foot, a 24 mm round head, joined smoothly). A flat perch
# 14 mm wide gives the bird 100 mm between the sides and ends in one 8 mm glued tenon at each
# end through a mortise in the middle of each foot. A top bar 16 mm wide, the same 100 mm
# between the sides, ends in one 8 mm tenon through the middle of each head and has a 5 mm
# hole in its middle for the hanging hook; "KIWI" (the bird) is engraved on it left of the
# hole in 6 mm single-stroke letters. Each foot has three 3.5 mm holes in a row 15 mm below
# the perch, 10 mm apart, to tie on bead strings. Assembly of 4 parts.

units mm
thickness 4 mm
import "std/joints.aidl"

param t = 4 mm, min = 3 mm, max = 6 mm
param inner = 100 mm, min = 80 mm, max = 140 mm
param foot_d = 50 mm, min = 40 mm, max = 70 mm
param head_d = 24 mm, min = 20 mm, max = 32 mm
param side_h = 140 mm, min = 110 mm, max = 180 mm
param perch_w = 14 mm, min = 10 mm, max = 18 mm
param bar_w = 16 mm, min = 12 mm, max = 20 mm
param tenon = 8 mm, min = 6 mm, max = 10 mm

def swing_side() -> solid {
    foot = Circle(center=(0, 0), diameter=foot_d)
    head = Circle(center=(0, side_h - foot_d / 2 - head_d / 2), diameter=head_d)
    drop = Hull(foot, head)
    perch_mortise = tab_and_slot(part="slot", length=perch_w, thickness=t, tabs=1, tab=tenon,
                                 screw=0, cx=0 mm, cy=0 mm)
    bar_mortise = tab_and_slot(part="slot", length=bar_w, thickness=t, tabs=1, tab=tenon,
                               screw=0, cx=0 mm, cy=side_h - foot_d / 2 - head_d / 2)
    hole beads {
        for i in range(3) {
            c = Circle(center=((i - 1) * 10 mm, -15 mm), diameter=3.5 mm)
        }
    }
}

# a bar `inner` long between the sides plus a tenon through each side
def rung(w=14 mm) -> solid {
    bar = Rectangle(center=(0, 0), width=inner + 2 * t, height=w)
    left = tab_and_slot(part="tab", length=w, thickness=t, tabs=1, tab=tenon, screw=0,
                        rotation=90 deg, cx=-(inner / 2 + t), cy=0 mm)
    right = tab_and_slot(part="tab", length=w, thickness=t, tabs=1, tab=tenon, screw=0,
                         rotation=-90 deg, cx=inner / 2 + t, cy=0 mm)
}

assembly swing {
    side_l = swing_side()
    side_r = swing_side()
    perch = rung(w=perch_w)
    top = rung(w=bar_w)
    # FIX after the first valid program: a leftover empty `solid hook { hole eye }` (a first
    # try at the hook hole, left in by mistake) made an empty part (W0509, W0502); removed
    hole hang { c = Circle(center=(0, 0), diameter=5 mm) }
    CutInto(hang, top)
    Concentric(hang.c, top.bar)
    drawing name {
        w = Text("KIWI", position=(-25, 0), size=6, valign="middle")
    }
    CutInto(name, top)
    name.w.position.x == top.bar.center.x - 25 mm
    name.w.position.y == top.bar.center.y

    # laid out flat for cutting
    RightOf(side_r, side_l, gap=8)
    Above(perch, side_l, gap=8)
    AlignLeft(perch, side_l)
    Above(top, perch, gap=8)
    AlignLeft(top, perch)

    # the request's own numbers
    assert side_l.drop.bb.height == 140 mm, "sides 140 mm tall"
    assert side_l.foot.diameter == 50 mm and side_l.head.diameter == 24 mm, "50 mm foot, 24 mm head"
    assert perch.bar.width - 2 * 4 mm == 100 mm and top.bar.width - 2 * 4 mm == 100 mm, "100 mm between the sides"
    assert perch.bar.height == 14 mm and top.bar.height == 16 mm, "perch 14, top bar 16 wide"
    assert hang.c.diameter == 5 mm, "5 mm hook hole"
    assert len(side_l.beads.c) == 3, "three bead holes"
    assert side_l.beads.c[0].diameter == 3.5 mm, "3.5 mm bead holes"
    assert side_l.foot.center.y - side_l.beads.c[1].center.y == 15 mm, "bead holes 15 mm below the perch"
    assert name.w.size == 6 mm, "6 mm letters"
}
