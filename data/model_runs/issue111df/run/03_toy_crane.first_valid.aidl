# Request (toys): a slot-together toy tower crane, 3 mm birch ply. A 160 x 160 base (R10
# corners, "TOWER CRANE" engraved along its front) holds a mast of two 60 mm wide panels
# cross-halved into an X: panel A 235 mm tall slotted from the top, panel B 255 mm tall
# slotted from the bottom; each stands on two 10 mm tabs glued into mortises in the base.
# Both panels have a truss look: two columns of nine 19 mm bays, each cut into two
# triangles by a 3 mm diagonal that alternates direction. The jib, a 300 x 30 beam (90 mm
# behind the mast, 210 in front), rests on panel A's top and is cross-halved 10 + 10 with
# panel B's top; seven 22 mm truss bays in front of the mast and one behind; a 40 x 35
# counterweight hangs under its rear end with "ACME" engraved; a 4 mm string hole 10 mm
# from the tip. A J-hook (6 mm bar, 4 mm eye) hangs on the string. Five parts.

import "std/joints.aidl"

units mm
thickness 3 mm

t = 3 mm
mast_w = 60 mm
a_h = 235 mm
b_h = 255 mm
web = 3 mm
dd = web / 2 * sqrt(2)

# one truss bay: a square s x s from (xl, yb), cut into two triangles by a diagonal web
def bay(xl, yb, s, rising) -> hole {
    if rising {
        lo = Polygon([(xl + dd, yb), (xl + s, yb), (xl + s, yb + s - dd)])
        hi = Polygon([(xl, yb + dd), (xl, yb + s), (xl + s - dd, yb + s)])
    } else {
        lo = Polygon([(xl, yb), (xl + s - dd, yb), (xl, yb + s - dd)])
        hi = Polygon([(xl + dd, yb + s), (xl + s, yb + s), (xl + s, yb + dd)])
    }
}

def mast_panel(h, from_top) -> solid {
    body = Rectangle(bottom_left=(-mast_w / 2, -t), width=mast_w, height=h + t)
    feet = tab_and_slot(part="tab", length=mast_w, thickness=t, tabs=2, tab=10, screw=0,
                        rotation=180 deg, cx=0, cy=-t)
    if from_top {
        halving = cross_halving(depth=a_h / 2, thickness=t, clearance=0.1, cx=0, cy=h)
    } else {
        halving = cross_halving(depth=a_h / 2, thickness=t, clearance=0.1, rotation=180 deg,
                                cx=0, cy=0)
        jib_slot = cross_halving(depth=10, thickness=t, clearance=0.1, cx=0, cy=h)
    }
    for k in range(9) {
        left_bay = bay(-25, 12 + 23 * k, 19, k % 2 == 0)
        right_bay = bay(6, 12 + 23 * k, 19, k % 2 == 1)
    }
}

assembly crane {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=160, height=160, corner_radius=10)
        mortise_a = tab_and_slot(part="slot", length=mast_w, thickness=t, tabs=2, tab=10,
                                 screw=0, clearance=0.1, cx=0, cy=0)
        mortise_b = tab_and_slot(part="slot", length=mast_w, thickness=t, tabs=2, tab=10,
                                 screw=0, clearance=0.1, rotation=90 deg, cx=0, cy=0)
        drawing name {
            label = Text("TOWER CRANE", (0, -68), size=8)
        }
    }

    mast_a = mast_panel(a_h, true)
    mast_b = mast_panel(b_h, false)

    solid jib {
        beam = Rectangle(bottom_left=(-90, 0), width=300, height=30)
        weight = Rectangle(bottom_left=(-90, -35), width=40, height=35)
        slot = cross_halving(depth=10, thickness=t, clearance=0.1, rotation=180 deg, cx=0, cy=0)
        for k in range(7) {
            front_bay = bay(10 + 26 * k, 4, 22, k % 2 == 0)
        }
        rear_bay = bay(-40, 4, 22, false)
        hole string {
            c = Circle(center=(200, 15), diameter=4)
        }
        drawing mark {
            w = Text("ACME", (-70, -20), size=8, valign="middle")
        }
    }

    solid hook {
        shank = Rectangle(center=(0, -15), width=6, height=30)
        eye_ring = Circle(center=(0, 0), radius=6)
        j = ArcSlot(center=(9, -30), radius=9, start_angle=180 deg, end_angle=390 deg, width=6)
        hole eye {
            c = Circle(center=(0, 0), diameter=4)
        }
    }

    # 3D: base on the table, A in the x-z plane, B in the y-z plane, jib on A's top
    Place(base, position=(0, 0, 0))
    Place(mast_a, position=(0, t / 2, t), face="front", up="up")
    Place(mast_b, position=(-t / 2, 0, t), face="right", up="up")
    Place(jib, position=(0, t / 2, t + a_h), face="front", up="up")
    Place(hook, position=(200, t / 2, 120), face="front", up="up")

    # on the sheet
    RightOf(mast_a, base, gap=5)
    RightOf(mast_b, mast_a, gap=5)
    Below(jib, base, gap=5)
    RightOf(hook, mast_b, gap=5)

    assert base.plate.bb.width == 160 mm and base.plate.bb.height == 160 mm, "base 160 x 160"
    assert mast_a.body.bb.height - t == 235 mm and mast_b.body.bb.height - t == 255 mm,
        "mast panels 235 and 255 tall"
    assert mast_a.halving.depth + mast_b.halving.depth == a_h, "the X halving meets"
    assert jib.slot.depth + mast_b.jib_slot.depth == b_h - a_h, "jib halving 10 + 10"
    assert jib.beam.bb.width == 300 mm and jib.beam.bb.height == 30 mm, "jib 300 x 30"
    assert jib.weight.bb.width == 40 mm and jib.weight.bb.height == 35 mm, "counterweight 40 x 35"
    assert jib.beam.bb.right - jib.string.c.center.x == 10 mm, "string hole 10 mm from the tip"
}
