# Request: a pot gripper (pot lifter) for camping cook pots, laser-cut from 3 mm stainless, two
# levers crossing like pliers on an M5 bolt (5.2 mm holes, a 18 mm boss round each). Each lever
# is a 12 mm wide bar with round ends: its handle runs 110 mm back from the pivot, ending 20 mm
# off the centre line (so the handles stand 28 mm apart inside, at rest); its jaw runs 20 mm
# forward and 10 mm across, then straight on to 45 mm in front of the pivot, so the jaws stand
# 8 mm apart at rest and close when the handles are squeezed. A 4 mm lanyard hole in each
# handle's round end. "CAMP KITCHEN" engraved 4 mm along the upper lever's handle.

import "std/fasteners.aidl"

thickness 3 mm

handle_len = 110 mm
handle_off = 20 mm
jaw_len = 45 mm
jaw_off = 10 mm
bar_w = 12 mm

def lever(s=1, label=false) -> solid {
    bar = Stroke(Polyline([(-handle_len, handle_off * s), (0, 0), (20, -jaw_off * s), (jaw_len, -jaw_off * s)]),
                 width=bar_w)
    boss = Circle(center=(0, 0), diameter=18)
    hole pivot { c = Circle(center=(0, 0), diameter=5.2) }
    hole lanyard { c = Circle(center=(-handle_len, handle_off * s), diameter=4) }
    if label {
        drawing name {
            word = Text("CAMP KITCHEN", position=(-handle_len / 2, handle_off * s / 2), size=4,
                        valign="middle", rotation=atan2(-handle_off * s, handle_len))
        }
    }
}

assembly pot_gripper {
    upper = lever(s=1, label=true)
    lower = lever(s=-1)

    Fixed(upper)
    Below(lower, upper, gap=5)
    AlignLeft(lower, upper)

    # in 3D: stacked on the pivot bolt, the upper lever on top
    Place(lower, position=(0, 0, 0), face="up")
    Place(upper, position=(0, 0, 3 mm), face="up")

    assert upper.pivot.c.diameter == 5.2 mm and upper.boss.diameter == 18 mm, "M5 pivot, 18 mm boss"
    assert upper.lanyard.c.center.x - upper.pivot.c.center.x == -110 mm, "handle 110 mm back"
    assert ((upper.lanyard.c.center.y - upper.pivot.c.center.y) - (lower.lanyard.c.center.y - lower.pivot.c.center.y)
            - bar_w == 28 mm), "handles 28 mm apart inside"
    assert upper.bar.bb.right - upper.pivot.c.center.x == 45 mm + bar_w / 2, "jaw 45 mm in front of the pivot"
    assert (-jaw_off * -1 - bar_w / 2) - (-jaw_off + bar_w / 2) == 8 mm, "jaws 8 mm apart at rest"
    assert upper.lanyard.c.diameter == 4 mm, "4 mm lanyard hole"
}
