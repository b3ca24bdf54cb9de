# Request (home): a decorative screen to stand in front of an unused fireplace where we put
# candles, cut from 6 mm birch ply. The panel is 600 mm wide, its sides 420 mm tall, with an
# arched top that rises to 500 mm in the middle; the arch's two side corners rounded R15.
# A sunburst cut through it: a 80 mm round hub whose centre is 260 mm above the floor and 16
# rays around it, each a 14 mm wide slot running from 70 mm to 170 mm out from the hub's centre.
# A row of 7 "ember" holes 20 mm across, 50 mm apart, centred 45 mm above the floor.
# It stands on two feet 260 mm long and 70 mm tall (top corners R20), each 220 mm left and right
# of the centre, joined by cross-halving: a 35 mm slot up from the panel's bottom edge and a
# 35 mm slot down from the middle of each foot's top edge (35 + 35 = the 70 mm foot).

import "std/joints.aidl"

thickness 6 mm

param board = 6 mm, min = 3 mm, max = 9 mm
panel_w = 600 mm
side_h = 420 mm
arch_h = 500 mm
hub_y = 260 mm
foot_len = 260 mm
foot_h = 70 mm
foot_x = 220 mm
halving = 35 mm

def foot() -> solid {
    body = RoundedRectangle(center=(0, foot_h / 2), width=foot_len, height=foot_h,
                            corner_radii=[20, 20, 0, 0])
    slot = cross_halving(depth=halving, thickness=board, cx=0, cy=foot_h)
}

assembly fire_screen {
    solid panel {
        left = Line((-panel_w / 2, side_h), (-panel_w / 2, 0))
        bottom = Line((-panel_w / 2, 0), (panel_w / 2, 0))
        right = Line((panel_w / 2, 0), (panel_w / 2, side_h))
        top = Arc(start=(panel_w / 2, side_h), through=(0, arch_h), end=(-panel_w / 2, side_h))
        Fillet([top.start, top.end], 15)

        hole hub { c = Circle(center=(0, hub_y), diameter=80) }
        hole ray { s = Slot(center=(0, hub_y + 120), length=100, width=14, rotation=90 deg) }
        rays = CircularPattern(ray, 16, (0, hub_y))

        hole ember { c = Circle(center=(-150, 45), diameter=20) }
        embers = LinearPattern(ember, 7, (50, 0))

        slot_l = cross_halving(depth=halving, thickness=board, rotation=180 deg, cx=-foot_x, cy=0)
        slot_r = cross_halving(depth=halving, thickness=board, rotation=180 deg, cx=foot_x, cy=0)
    }
    foot_l = foot()
    foot_r = foot()

    # flat on the sheet: the feet under the panel
    Below(foot_l, panel, gap=10)
    AlignLeft(foot_l, panel)
    Below(foot_r, panel, gap=10)
    AlignRight(foot_r, panel)

    # standing: the panel faces the room, the feet run front to back through it
    Place(panel, position=(0, board / 2, 0), face="front", up="up")
    Place(foot_l, position=(-foot_x - board / 2, 0, 0), face="right", up="up")
    Place(foot_r, position=(foot_x - board / 2, 0, 0), face="right", up="up")

    # the request's own numbers
    assert panel.bb.width == 600 mm, "panel 600 mm wide"
    assert panel.bb.height == 500 mm, "arch rises to 500 mm"
    assert panel.left.start.y - panel.left.end.y == 420 mm, "sides 420 mm tall"
    assert len(panel.rays) == 16, "16 rays"
    assert len(panel.embers) == 7, "7 ember holes"
    assert panel.embers[6].c.center.x - panel.embers[0].c.center.x == 300 mm, "7 holes 50 apart"
    assert foot_l.body.width == 260 mm and foot_l.body.height == 70 mm, "feet 260 x 70"
    assert foot_l.slot.depth + panel.slot_l.depth == 70 mm, "halvings meet at the foot's height"
    assert panel.ray.s.center.y - panel.hub.c.center.y + 50 mm == 170 mm, "rays reach 170 mm out"
}
