# Request (crafts): a rest for my wood-burning (pyrography) pen, 6 mm ply. A base
# 160 x 110 mm (front corners rounded 6 mm) carries two uprights 80 mm wide, 70 mm apart
# (the front one 35 mm in front of the base's middle, the back one 35 mm behind it),
# each with a 60 deg V notch 15 mm deep at the top middle for
# the pen: the front V's top edge 60 mm above the base, the back one's 35 mm, so the hot
# tip points forward and up, away from the bench. Each upright is glued in with two
# 15 mm tabs. A removable nib tray 160 x 50 mm (back corners rounded 6 mm) drops onto
# the base's back edge with a flat dovetail joint (2 tails, 100 mm long, 10 mm deep,
# 10 deg). The tray has eight 4.5 mm holes for spare nibs, 18 mm apart in a row 30 mm
# behind the joint line, numbered 1 to 8 (5 mm engraved figures) 16 mm in front of
# each hole's centre. HOT is engraved on the base in front of the front upright, 7 mm
# bold letters, filled.
# FIX after the first valid program: with the dovetail 100 mm long on a 160 mm edge,
# the tray's band (10 mm deep) stays whole over the 30 mm at each end of the edge,
# where the base also has material: assembled, they would overlap and the tray could
# not drop in (no message named it; the dovetail doc says the tail panel "reaches
# across the band"). The joint now runs the whole 160 mm edge with 3 tails.

import "std/joints.aidl"

thickness 6 mm

base_w = 160 mm
base_d = 110 mm
rest_pitch = 70 mm
v_depth = 15 mm
v_half = 15 mm * tan(30 deg)

# an upright `h` tall above the base to the top of its V notch; 6 mm more go into the base
def upright(h=60 mm) -> solid {
    body = Polygon([(-40, 0), (40, 0), (40, h + 6), (v_half, h + 6), (0, h + 6 - v_depth),
                    (-v_half, h + 6), (-40, h + 6)])
    tabs = tab_and_slot(part="tab", length=80 mm, thickness=6 mm, tabs=2, tab=15 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
}

assembly pen_rest {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=base_w, height=base_d,
                                corner_radii=[0, 0, 6 mm, 6 mm])
        m_front = tab_and_slot(part="slot", length=80 mm, thickness=6 mm, tabs=2, tab=15 mm,
                               screw=0, cx=0 mm, cy=-rest_pitch / 2)
        m_back = tab_and_slot(part="slot", length=80 mm, thickness=6 mm, tabs=2, tab=15 mm,
                              screw=0, cx=0 mm, cy=rest_pitch / 2)
        socket = dovetail(part="socket", length=base_w, depth=10 mm, tails=3, angle=10 deg,
                          rotation=180 deg, cx=0 mm, cy=base_d / 2)
        drawing warn {
            t = Text("HOT", position=(0, -47), size=7 mm, font="sans:Bold", fill=true,
                     valign="middle")
        }
        Fixed(body)
    }

    solid tray {
        body = RoundedRectangle(bottom_left=(-80, -10), width=base_w, height=60,
                                corner_radii=[6 mm, 6 mm, 0, 0])
        tails = dovetail(part="tail", length=base_w, depth=10 mm, tails=3, angle=10 deg,
                         rotation=180 deg, cx=0 mm, cy=0 mm)
        hole nibs {
            for i in range(8) {
                n = Circle(center=((i - 3.5) * 18 mm, 30), diameter=4.5 mm)
            }
        }
        drawing numbers {
            for i in range(8) {
                t = Text(str(i + 1), position=((i - 3.5) * 18 mm, 14), size=5 mm, valign="middle")
            }
        }
    }
    Above(tray, base, gap=10 mm)
    AlignCenterX(tray, base)

    front = upright(h=60 mm)
    back = upright(h=35 mm)
    RightOf(front, base, gap=10 mm)
    AlignBottom(front, base)
    RightOf(back, front, gap=10 mm)
    AlignBottom(back, front)

    assert base.body.bb.width == 160 mm and base.body.bb.height == 110 mm, "160 x 110 base"
    assert base.m_back.slot[0].bb.center_y - base.m_front.slot[0].bb.center_y == 70 mm,
        "uprights 70 mm apart"
    assert front.body.bb.height - 6 mm == 60 mm, "front V top 60 mm above the base"
    assert back.body.bb.height - 6 mm == 35 mm, "back V top 35 mm above the base"
    assert tray.body.bb.height - 10 mm == 50 mm, "tray 50 mm deep behind the joint"
    assert tray.tails.length == tray.body.bb.width, "FIX: the joint runs the whole edge"
    assert len(tray.nibs.n) == 8, "eight nib holes"
    assert tray.nibs.n[1].center.x - tray.nibs.n[0].center.x == 18 mm, "18 mm apart"
    assert distance(tray.numbers, tray.nibs) >= 3 mm, "figures clear of the holes"
    assert distance(base.warn, base.m_front) >= 3 mm, "HOT clear of the mortises"
}
