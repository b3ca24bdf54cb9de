# Living-hinge cuff bracelet (gifts). Full sizes: 3 mm birch ply, a band 170 mm long and
# 32 mm wide with round ends (a stadium, 16 mm end radius). Its middle 120 mm is a living
# hinge across the band's full width so it bends round a wrist: columns 2 mm apart, cuts
# 12 mm long with 3 mm bridges, the end cuts open at the band's long edges. A 4 mm hole in
# each end for a ribbon tie, centred on the band's middle line 10 mm from the tip. A small
# 6-point star 10 mm across (tip to tip) engraved halfway between each tie
# hole and the hinge.

import "std/plates.aidl"

units mm
thickness 3 mm

solid cuff {
    band = Slot(center=(0, 0), length=170, width=32)

    flex = living_hinge(width=120 mm, height=32 mm, pitch=2 mm, cut=12 mm, bridge=3 mm)
    CenterInside(flex, band)

    hole ties {
        l = Circle(center=(-75, 0), diameter=4)
        r = Circle(center=(75, 0), diameter=4)
    }
    ties.l.center.x == band.bb.left + 10
    ties.r.center.x == band.bb.right - 10
    ties.l.center.y == band.center.y
    ties.r.center.y == band.center.y

    drawing deco {
        s1 = Star(center=(-67.5, 0), points=6, outer_radius=5, inner_radius=2.5)
        s2 = Star(center=(67.5, 0), points=6, outer_radius=5, inner_radius=2.5)
    }
    deco.s1.center.x == (ties.l.center.x + flex.bb.left) / 2
    deco.s2.center.x == (ties.r.center.x + flex.bb.right) / 2
    deco.s1.center.y == band.center.y
    deco.s2.center.y == band.center.y

    assert band.bb.width == 170 mm and band.bb.height == 32 mm, "band 170 x 32"
    assert band.radius == 16 mm, "16 mm round ends"
    assert flex.bb.width <= 120 mm, "hinge within the middle 120 mm"
    assert abs(flex.bb.center_x - band.bb.center_x) < 0.01 mm, "hinge in the middle"
    assert flex.bb.bottom <= band.bb.bottom and flex.bb.top >= band.bb.top, "hinge across the full width"
    assert ties.l.diameter == 4 mm, "4 mm tie holes"
    assert ties.l.center.x - band.bb.left == 10 mm, "left tie 10 mm from the tip"
    assert band.bb.right - ties.r.center.x == 10 mm, "right tie 10 mm from the tip"
    assert deco.s1.bb.right < flex.bb.left and deco.s1.bb.left > ties.l.bb.right, "star between tie and hinge"
    assert deco.s1.outer_radius == 5 mm, "stars 10 mm across"
}
