# Request: a tilt stand for my tenkeyless keyboard (360 x 130 mm), 6 mm birch ply, glued.
# Two identical side wedges, 140 mm deep: flat bottom, 35 mm tall at the back, the top sloping
# down to 14 mm high 8 mm from the front, where a lip 8 mm long stands 20 mm tall to stop the
# keyboard sliding off (its two top corners R2, the back top corner R3). Two cross rails,
# 12 mm tall, 300 mm between the sides' inner faces, each ending in a through tenon 8 mm tall
# x 6 mm long glued in a mortise (0.1 mm clearance); the mortises' centres 40 mm and 120 mm
# from the front, 9 mm above the floor. The back rail has "TKL RISER" engraved (5 mm
# letters) on its front face. Lay the parts out for cutting 5 mm apart, and place them in 3D.

import "std/joints.aidl"

thickness 6 mm

param depth = 140 mm
param back_h = 35 mm
param lip_len = 8 mm
param lip_h = 20 mm
param slope_h = 14 mm
param between = 300 mm
param rail_h = 12 mm
param tenon = 8 mm
param ply = 6 mm
param gap = 5 mm

def side() -> solid {
    p = Polygon([(0, 0), (depth, 0), (depth, back_h), (lip_len, slope_h), (lip_len, lip_h),
                 (0, lip_h)])
    Fillet(p.points[2], 3 mm)
    Fillet([p.points[4], p.points[5]], 2 mm)
    front_mortise = tab_and_slot(part="slot", length=rail_h, thickness=ply, tabs=1, tab=tenon,
                                 screw=0, clearance=0.1 mm, rotation=90 deg, cx=40 mm, cy=9 mm)
    back_mortise = tab_and_slot(part="slot", length=rail_h, thickness=ply, tabs=1, tab=tenon,
                                screw=0, clearance=0.1 mm, rotation=90 deg, cx=120 mm, cy=9 mm)
}

def rail(label="") -> solid {
    body = Rectangle(center=(0, 0), width=between + 2 * ply, height=rail_h)
    left_tenon = tab_and_slot(part="tab", length=rail_h, thickness=ply, tabs=1, tab=tenon,
                              screw=0, rotation=90 deg, cx=-(between / 2 + ply), cy=0 mm)
    right_tenon = tab_and_slot(part="tab", length=rail_h, thickness=ply, tabs=1, tab=tenon,
                               screw=0, rotation=-90 deg, cx=between / 2 + ply, cy=0 mm)
    if label != "" {
        drawing name {
            t = Text(label, position=(0, 0), size=5, valign="middle")
        }
    }
}

assembly keyboard_riser {
    side_a = side()
    side_b = side()
    rail_front = rail()
    rail_back = rail(label="TKL RISER")

    RightOf(side_b, side_a, gap=gap)
    AlignBottom(side_b, side_a)
    Below(rail_front, side_a, gap=gap)
    AlignLeft(rail_front, side_a)
    Below(rail_back, rail_front, gap=gap)
    AlignLeft(rail_back, rail_front)

    # 3D: x across the keyboard, y from front to back, z up; both sides turned the same way
    Place(side_a, position=(-between / 2 - ply, 0, 0), face="right", up="up")
    Place(side_b, position=(between / 2, 0, 0), face="right", up="up")
    Place(rail_front, position=(0, 40 mm + ply / 2, 9 mm), face="front", up="up")
    Place(rail_back, position=(0, 120 mm + ply / 2, 9 mm), face="front", up="up")

    # the request's numbers
    assert side_a.p.bb.width == 140 mm, "sides 140 deep"
    assert side_a.p.bb.height == 35 mm, "35 tall at the back"
    assert side_a.p.points[3].x == 8 mm and side_a.p.points[3].y == 14 mm, "slope ends 14 high, 8 from the front"
    assert side_a.p.points[4].y == 20 mm, "lip 20 tall"
    assert rail_front.body.bb.width - 2 * ply == 300 mm, "300 between the sides"
    assert rail_front.body.bb.height == 12 mm, "rails 12 tall"
    assert side_a.front_mortise.slot[0].bb.center_x == 40 mm, "front mortise 40 from the front"
    assert side_a.back_mortise.slot[0].bb.center_x == 120 mm, "back mortise 120 from the front"
    assert side_a.front_mortise.slot[0].bb.center_y == 9 mm, "mortises 9 above the floor"
    assert side_a.front_mortise.slot[0].bb.height == 8.1 mm, "mortise 8 + 0.1 tall"
    assert side_a.front_mortise.slot[0].bb.width == 6.1 mm, "mortise 6 + 0.1 long"
    # the rails must stay under the slope, or the keyboard rests on them
    assert 9 mm + rail_h / 2 < slope_h + (40 mm - lip_len) * (back_h - slope_h) / (depth - lip_len),
           "front rail below the slope"
    assert atan((back_h - slope_h) / (depth - lip_len)) > 8 deg, "about 9 degrees of tilt"
}
