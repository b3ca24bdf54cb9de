# Request: a buzz-wire ("steady hand") game for a school fete, 6 mm ply. A base 320 x 100
# with R8 corners. Two posts 30 wide standing 80 above the base, 140 either side of the
# middle, 10 mm behind the base's centre line, each glued into the base by two 8 mm tenons;
# round tops (R10 corners); a 3 mm hole 12 below each post's top for the 2.5 mm wire.
# On the base: STEADY HAND filled (12 mm, bold) 30 below the centre line; START and FINISH
# engraved (6 mm) under the left and right posts; two M3 holes 50 apart for a 2xAA holder,
# centred 60 left of the middle, 25 above the centre line; a 12 mm hole for the buzzer 60
# right of the middle, 25 above. The wand: a 130 x 18 handle (R8 ends) with a ring of 30 mm
# outside, 18 mm inside, on its end, split by a 4 mm gap to slip it on the wire, and a 3 mm
# hole for the lead 5 mm from the handle's far end.

import "std/joints.aidl"
import "std/fasteners.aidl"

units mm
thickness 6 mm

t = 6 mm
post_x = 140 mm
post_y = 10 mm
post_w = 30 mm
post_h = 80 mm        # above the base
wire_hole = 3 mm

def post() -> solid {
    body = RoundedRectangle(bottom_left=(-post_w / 2, 0), width=post_w, height=post_h + t,
                            corner_radii=[10 mm, 10 mm, 0 mm, 0 mm])
    feet = tab_and_slot(part="tab", length=post_w, thickness=t, tabs=2, tab=8 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    hole wire { c = Circle(center=(0, post_h + t - 12 mm), diameter=wire_hole) }
    assert body.height - t == 80 mm, "posts stand 80 above the base"
    assert body.bb.top - wire.c.center.y == 12 mm, "wire hole 12 below the top"
}

assembly buzz_wire {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=320, height=100, corner_radius=8)
        left_mortise = tab_and_slot(part="slot", length=post_w, thickness=t, tabs=2, tab=8 mm,
                                    screw=0, cx=-post_x, cy=post_y)
        right_mortise = tab_and_slot(part="slot", length=post_w, thickness=t, tabs=2, tab=8 mm,
                                     screw=0, cx=post_x, cy=post_y)
        holder_a = clearance_hole(size=3, cx=-60 mm - 25 mm, cy=25 mm)
        holder_b = clearance_hole(size=3, cx=-60 mm + 25 mm, cy=25 mm)
        hole buzzer { c = Circle(center=(60, 25), diameter=12) }
        drawing title {
            w = Text("STEADY HAND", position=(0, -30), size=12, font="sans:Bold",
                     valign="middle", fill=true)
        }
        drawing marks {
            s = Text("START", position=(-post_x, -10), size=6, valign="middle")
            f = Text("FINISH", position=(post_x, -10), size=6, valign="middle")
        }
        assert holder_b.c.center.x - holder_a.c.center.x == 50 mm, "holder screws 50 apart"
        assert buzzer.c.diameter == 12 mm, "12 mm buzzer hole"
        assert distance(title, marks) >= 5 mm, "title clear of START / FINISH"
        assert title.bb.bottom >= plate.bb.bottom + 6 mm, "title inside the base"
        assert distance(marks, left_mortise) >= 5 mm, "START clear of the post"
    }

    left_post = post()
    right_post = post()

    solid wand {
        handle = RoundedRectangle(center=(60, 0), width=130, height=18, corner_radius=8)
        ring = Circle(center=(-15, 0), diameter=30)
        hole eye { c = Circle(center=(-15, 0), diameter=18) }
        hole split { g = Rectangle(center=(-27, 0), width=8, height=4, overrun=true) }
        hole lead { c = Circle(center=(120, 0), diameter=3) }
        assert handle.width == 130 mm and handle.height == 18 mm, "handle 130 x 18"
        assert handle.bb.right - lead.c.center.x == 5 mm, "lead hole 5 from the end"
        assert ring.diameter - eye.c.diameter == 12 mm, "ring 30 outside, 18 inside"
        assert split.g.height >= 2.5 mm + 1 mm, "the gap passes the wire"
    }

    # flat on the sheet
    Below(left_post, base, gap=8)
    AlignLeft(left_post, base)
    RightOf(right_post, left_post, gap=8)
    AlignBottom(right_post, left_post)
    RightOf(wand, right_post, gap=8)
    AlignBottom(wand, right_post)

    # assembled: base flat, posts standing in their mortises facing the front,
    # the wand hanging on the wire between them, its ring round the wire
    Place(base, position=(0, 0, 0), face="up")
    Place(left_post, position=(-post_x, post_y + t / 2, 0), face="front", up="up")
    Place(right_post, position=(post_x, post_y + t / 2, 0), face="front", up="up")
    Place(wand, position=(-t / 2, post_y + 15, post_h + t - 12), face="right", up="up")

    assert right_post.wire.c.center.x - left_post.wire.c.center.x == 0 mm, "posts alike"
    assert base.plate.width == 320 mm and base.plate.height == 100 mm, "base 320 x 100"
    assert base.right_mortise.bb.center_x - base.left_mortise.bb.center_x == 280 mm,
        "posts 140 either side"
}
