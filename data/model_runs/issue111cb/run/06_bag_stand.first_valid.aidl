# Request (camping): a flat-pack stand that holds a bin bag open at the campsite, 6 mm ply.
# - Two panels 300 mm wide x 450 mm tall slot together in an X (a plus in plan) by a cross
#   halving at their middle (0.2 mm play): one slotted 225 mm down from the top, the other
#   225 mm up from the bottom.
# - Each panel has two lightening windows 80 x 300 mm, corners r10, centred 65 mm either
#   side of its middle and on its height.
# - A ring 300 mm outside, 250 mm inside sits on top; the bag's mouth folds over it. Each of
#   the four fins has a 15 mm wide, 6 mm tall tab on its top edge, centred 137.5 mm from
#   the middle, through a 15.2 x 6.2 mm slot in the ring.
# - "LEAVE NO TRACE" engraved 10 mm high along the ring's middle, centred at 45 deg.

import "std/joints.aidl"
import "std/shapes.aidl"

thickness 6 mm

t = 6 mm
h = 450 mm
w = 300 mm
tab_r = 137.5 mm

def fin_panel(from_top=true) -> solid {
    body = Rectangle(bottom_left=(-w / 2, 0), width=w, height=h)
    tab_l = Rectangle(center=(-tab_r, h + t / 2 - 0.5), width=15, height=t + 1)
    tab_r_ = Rectangle(center=(tab_r, h + t / 2 - 0.5), width=15, height=t + 1)
    hole win_l { r = RoundedRectangle(center=(-65, h / 2), width=80, height=300, corner_radius=10) }
    hole win_r { r = RoundedRectangle(center=(65, h / 2), width=80, height=300, corner_radius=10) }
    if from_top {
        halving = cross_halving(depth=h / 2, thickness=t, clearance=0.2 mm, rotation=0 deg,
                                cx=0 mm, cy=h)
    } else {
        halving = cross_halving(depth=h / 2, thickness=t, clearance=0.2 mm, rotation=180 deg,
                                cx=0 mm, cy=0 mm)
    }
    Fixed(body)
}

assembly bag_stand {
    a = fin_panel(from_top=true)
    b = fin_panel(from_top=false)

    solid ring {
        band = washer(outer=300 mm, inner=250 mm, cx=0 mm, cy=0 mm)
        hole slot { r = Rectangle(center=(tab_r, 0), width=15.2, height=6.2) }
        slots = CircularPattern(slot, 4, (0, 0))
        drawing motto {
            mid = Circle(center=(0, 0), radius=tab_r, construction=true)
            words = Text("LEAVE NO TRACE", along=mid, angle=45 deg, size=10, valign="middle")
        }
        Fixed(band)
    }

    # flat: side by side, the ring beside them
    RightOf(b, a, gap=8)
    AlignBottom(b, a)
    RightOf(ring, b, gap=8)
    AlignBottom(ring, b)

    # 3D: a in the x-z plane, b in the y-z plane, the ring on top
    Place(a, rotation=(90 deg, 0, 0), position=(0, t / 2, 0))
    Place(b, rotation=(90 deg, 0, 90 deg), position=(-t / 2, 0, 0))
    Place(ring, position=(0, 0, h))

    assert a.body.width == 300 mm and a.body.height == 450 mm
    assert a.halving.depth + b.halving.depth == 450 mm
    assert ring.band.ring.diameter == 300 mm and ring.band.bore.b.diameter == 250 mm
    assert len(ring.slots) == 4
    assert a.tab_l.bb.top - a.body.bb.top == 6 mm, "tabs stand 6 mm, the ring's thickness"
    assert a.tab_r_.bb.center_x - a.body.bb.center_x == 137.5 mm
    assert a.win_r.r.bb.center_x - a.body.bb.center_x == 65 mm
    assert a.win_r.r.width == 80 mm and a.win_r.r.height == 300 mm
}
