# Request (garden): a little wheelbarrow planter for the patio, in 6 mm exterior ply. The tub
# is an open finger-jointed box 200 long x 130 deep x 70 tall (outside, 15 mm fingers) with
# five 8 mm drain holes in its floor (one in the middle, four 50 x 30 mm out from it).
# Two handle rails, 30 mm wide, glued and bolted (two M4 bolts each, through the rail and
# the tub's long wall) to the outside of the tub's long walls: each runs from the wheel's
# axle, 60 mm in front of the tub, back past the tub to a rounded handle 120 mm behind it,
# rising 40 mm from the axle to the tub's back end, and has a 24 mm leg 85 mm behind the
# tub's middle standing 60 mm below the tub's floor. A 100 mm spoked wheel (six windows,
# 12 mm rim, 8.4 mm axle hole for an 8 mm dowel) turns between the rails, its bottom level
# with the leg's foot. "HERB GARDEN" is engraved (filled, bold, 10 mm) on the tub's front,
# centred, 55 mm above the tub's bottom edge.

units mm
t = 6 mm
thickness t

L = 200 mm
D = 130 mm
H = 70 mm
wheel_d = 100 mm
axle = (L / 2 + 60 mm, -10 mm)          # in a rail's frame: x along, y = height above floor
tub_back = (-L / 2, -10 mm + 40 mm)
handle_end = (-L / 2 - 120 mm, 45 mm)
foot_z = -60 mm
bolt_a = (60 mm, 12 mm)
bolt_b = (-60 mm, 22 mm)

import "std/joints.aidl"
import "std/fasteners.aidl"

def rail() -> solid {
    bar = Stroke(Polyline([axle, tub_back, handle_end]), width=30)
    leg = Rectangle(bottom_left=(-85 mm - 12 mm, foot_z), width=24, height=80)
    hole axle_h {
        c = Circle(center=axle, diameter=8.4)
    }
    ba = clearance_hole(size=4, cx=bolt_a[0], cy=bolt_a[1])
    bb = clearance_hole(size=4, cx=bolt_b[0], cy=bolt_b[1])
}

def wall_bolts(mirror_x=1) -> hole {
    span = Rectangle(bottom_left=(-L / 2, 0), width=L, height=H, construction=true)
    ba = clearance_hole(size=4, cx=mirror_x * bolt_a[0], cy=bolt_a[1])
    bb = clearance_hole(size=4, cx=mirror_x * bolt_b[0], cy=bolt_b[1])
}

assembly wheelbarrow {
    tub = finger_box(length=L, depth=D, height=H, thickness=t, finger=15 mm, closed=false)
    rail_f = rail()
    rail_b = rail()
    solid wheel {
        disc = Circle(center=(0, 0), diameter=wheel_d)
        hole windows {
            for i in range(6) {
                w = Sector(center=(0, 0), radius=wheel_d / 2 - 12 mm, inner_radius=12,
                           start_angle=i * 60 deg + 10 deg, end_angle=i * 60 deg + 50 deg)
            }
        }
        hole hub {
            c = Circle(center=(0, 0), diameter=8.4)
        }
    }

    # bolt holes in the tub's long walls, matching the rails (the back wall is seen from
    # behind, so its x runs the other way)
    front_bolts = wall_bolts(mirror_x=1)
    back_bolts = wall_bolts(mirror_x=-1)
    At(front_bolts.span.center, tub.front.outline.center)
    At(back_bolts.span.center, tub.back.outline.center)
    CutInto(front_bolts, tub.front)
    CutInto(back_bolts, tub.back)

    hole drains {
        c0 = Circle(center=(0, 0), diameter=8)
        c1 = Circle(center=(50, 30), diameter=8)
        c2 = Circle(center=(-50, 30), diameter=8)
        c3 = Circle(center=(50, -30), diameter=8)
        c4 = Circle(center=(-50, -30), diameter=8)
    }
    At(drains.c0.center, tub.bottom.outline.center)
    CutInto(drains, tub.bottom)

    drawing sign {
        s = Text("HERB GARDEN", position=(0, 0), size=10, font="sans:Bold", valign="middle",
                 fill=true)
    }
    At(sign.s.position, tub.front.outline.center, dy=55 mm - H / 2)
    CutInto(sign, tub.front)

    # flat on the sheet
    RightOf(rail_f, tub, gap=10)
    AlignTop(rail_f, tub)
    Below(rail_b, rail_f, gap=10)
    AlignLeft(rail_b, rail_f)
    Below(wheel, rail_b, gap=10)
    AlignLeft(wheel, rail_b)

    # assembled: the tub stands on z = 0 centred on x = y = 0; rails against its long walls
    Place(rail_f, position=(0, -D / 2, 0), face="front", up="up")
    Place(rail_b, position=(0, D / 2 + t, 0), face="front", up="up")
    Place(wheel, position=(axle[0], t / 2, axle[1]), face="front", up="up")

    assert tub.bottom.outline.width == 200 mm and tub.bottom.outline.height == 130 mm and
        tub.front.outline.height == 70 mm, "tub 200 x 130 x 70"
    assert wheel.disc.diameter == 100 mm, "100 mm wheel"
    assert axle[1] - wheel_d / 2 == foot_z, "wheel bottom level with the foot"
    assert foot_z == -60 mm, "leg 60 below the floor"
    assert axle[0] - L / 2 == 60 mm, "axle 60 in front of the tub"
    assert axle[0] - wheel_d / 2 - L / 2 >= 5 mm, "wheel clear of the tub"
    assert handle_end[0] == -L / 2 - 120 mm, "handles 120 behind the tub"
    assert tub_back[1] - axle[1] == 40 mm, "rail rises 40 mm to the tub's back end"
    assert distance(sign.s, front_bolts) >= 10 mm, "sign clear of the bolts"
}
