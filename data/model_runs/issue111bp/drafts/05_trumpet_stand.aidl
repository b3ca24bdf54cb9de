# Request: a flat-pack stand for a trumpet, standing bell-down on a cone of two crossed fins,
# from 6 mm ply. Each fin 110 mm wide at the feet, standing 180 mm above the base, tapering
# from its full width 40 mm up to a 30 mm round top; a 60 mm wide arch (15 mm round corners,
# 30 mm high) between the feet. The two fins cross-halve at the middle (one slotted 90 mm
# down from the top, the other from the arch up to meet it), 0.2 mm clearance. Their four
# feet stand on a 170 mm round base, each glued in with one 12 mm tab; "TRUMPET" engraved
# 7 mm high along a 62 mm radius circle between two fins. Soften the fins' shoulders (r10).

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
HEIGHT = 180 mm
FOOT_W = 110 mm
ARCH_H = 30 mm
FOOT_X = (FOOT_W / 2 + 30 mm) / 2      # the middle of each foot: 42.5 mm out

def fin(from_top=true) -> solid {
    # y = -6 .. 0: the feet's tabs in the base; y = 0: the base's top
    feet = Rectangle(bottom_left=(-FOOT_W / 2, -T), width=FOOT_W, height=40 mm + T)
    top = Circle(center=(0, HEIGHT - 15), radius=15)
    shoulder = Rectangle(bottom_left=(-FOOT_W / 2, 30), width=FOOT_W, height=10)
    cone = Hull(top, shoulder)
    hole arch {
        r = RoundedRectangle(bottom_left=(-30, -T - 4), width=60, height=ARCH_H + T + 4,
                             corner_radii=[15, 15, 0, 0])
    }
    left_tab = tab_and_slot(part="tab", length=25 mm, thickness=T, tabs=1, tab=12 mm, screw=0,
                            rotation=180 deg, cx=-FOOT_X, cy=-T)
    right_tab = tab_and_slot(part="tab", length=25 mm, thickness=T, tabs=1, tab=12 mm, screw=0,
                             rotation=180 deg, cx=FOOT_X, cy=-T)
    if from_top {
        halving = cross_halving(depth=90 mm, thickness=T, clearance=0.2 mm, cx=0 mm, cy=HEIGHT)
    } else {
        halving = cross_halving(depth=HEIGHT - 90 mm - ARCH_H, thickness=T, clearance=0.2 mm,
                                rotation=180 deg, cx=0 mm, cy=ARCH_H)
    }
    Fillet(feet.top_left, 10)
    Fillet(feet.top_right, 10)
}

assembly stand {
    fin_a = fin(from_top=true)
    fin_b = fin(from_top=false)

    solid base {
        disc = Circle(center=(0, 0), diameter=170)
        a_left = tab_and_slot(part="slot", length=25 mm, thickness=T, tabs=1, tab=12 mm, screw=0,
                              cx=-FOOT_X, cy=0 mm)
        a_right = tab_and_slot(part="slot", length=25 mm, thickness=T, tabs=1, tab=12 mm,
                               screw=0, cx=FOOT_X, cy=0 mm)
        b_near = tab_and_slot(part="slot", length=25 mm, thickness=T, tabs=1, tab=12 mm, screw=0,
                              rotation=90 deg, cx=0 mm, cy=-FOOT_X)
        b_far = tab_and_slot(part="slot", length=25 mm, thickness=T, tabs=1, tab=12 mm, screw=0,
                             rotation=90 deg, cx=0 mm, cy=FOOT_X)
        drawing label {
            ring = Circle(center=(0, 0), radius=62, construction=true)
            t = Text("TRUMPET", along=ring, angle=45 deg, size=7)
        }
    }

    # 3D: fin A in the x-z plane, fin B in the y-z plane, both centred on the axis; the
    # base's top at z = 0
    Place(fin_a, rotation=(90 deg, 0, 0), position=(0, T / 2, 0))
    Place(fin_b, rotation=(90 deg, 0, 90 deg), position=(-T / 2, 0, 0))
    Place(base, position=(0, 0, -T))

    # on the sheet
    RightOf(fin_b, fin_a, gap=8)
    AlignBottom(fin_b, fin_a)
    RightOf(base, fin_b, gap=8)
    AlignBottom(base, fin_a)

    # the request's numbers
    assert fin_a.cone.bb.top - fin_a.feet.bb.bottom - T == 180 mm, "180 mm above the base"
    assert fin_a.feet.bb.width == 110 mm, "110 mm at the feet"
    assert fin_a.top.radius * 2 == 30 mm, "30 mm round top"
    assert fin_a.arch.r.bb.top - fin_a.feet.bb.bottom - T == 30 mm, "arch 30 high"
    assert fin_a.arch.r.width == 60 mm, "arch 60 wide"
    assert fin_a.halving.depth == 90 mm, "slotted 90 mm down"
    assert fin_a.halving.depth + fin_b.halving.depth == 180 mm - 30 mm, "halvings meet"
    assert base.disc.diameter == 170 mm, "170 mm base"
}
