# Request (crafts): a bead loom for seed-bead bracelets, from 6 mm ply, to cut on my small
# 200 mm laser. The base is 300 x 80 mm, made as two halves joined across the middle by a
# sliding dovetail (two tails, 10 mm deep). Two end uprights 80 mm wide and 70 mm tall stand
# across the base, their middles 13 mm in from each end, each glued into the base with two
# 15 mm tabs. Each upright's top edge carries a warp comb: 25 notches 1 mm wide and 5 mm deep
# at 2 mm pitch, centred; and an 8 mm hole for the warp-tie dowel 30 mm above the base's top
# face, centred. Along the base's front edge an engraved ruler: a tick every 10 mm from 0 to
# 250 mm (0 at 125 mm left of the middle), 4 mm long, 8 mm at every 50 mm, labelled 0, 50,
# 100, 150, 200, 250 (3.5 mm tall).

units mm
thickness 6 mm

import "std/joints.aidl"

param notches = 25, min = 10, max = 35
param notch_pitch = 2 mm, min = 1.5 mm, max = 4 mm

t = 6 mm
base_len = 300 mm
base_w = 80 mm
up_h = 70 mm
up_x = base_len / 2 - 13 mm       # each upright's middle from the base's middle

def tick_len(k) = 8 mm if k % 5 == 0 else 4 mm

def upright() -> solid {
    body = Rectangle(bottom_left=(-base_w / 2, 0), width=base_w, height=up_h)
    for i in range(notches) {
        hole notch {
            n = Rectangle(center=((i - (notches - 1) / 2) * notch_pitch, up_h - 2),
                          width=1, height=6)
        }
    }
    hole dowel { c = Circle(center=(0, t + 30), diameter=8) }
    tabs = tab_and_slot(part="tab", length=base_w, thickness=t, tabs=2, tab=15 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    Fixed(body)
    assert len(notch) == 25
    assert notch[1].n.center.x - notch[0].n.center.x == 2 mm
    assert body.bb.top - notch[0].n.bb.bottom == 5 mm, "notches 5 mm deep"
    assert abs(notch[12].n.center.x - body.bb.center_x) < 0.001 mm, "comb centred"
    assert dowel.c.center.y - body.bb.bottom - 6 mm == 30 mm, "dowel 30 mm above the base"
}

assembly loom {
    solid left_half {
        body = Rectangle(corner=(-base_len / 2, -base_w / 2), opposite=(10, base_w / 2))
        joint = dovetail(part="tail", length=base_w, depth=10 mm, tails=2, rotation=-90 deg,
                         cx=0 mm, cy=0 mm)
        slots = tab_and_slot(part="slot", length=base_w, thickness=t, tabs=2, tab=15 mm,
                             screw=0, rotation=90 deg, cx=-up_x, cy=0 mm)
        drawing ruler {
            for k in range(13) {
                tick = Line((-125 + k * 10, -base_w / 2 + 1), (-125 + k * 10,
                            -base_w / 2 + 1 + tick_len(k)))
            }
            for k in range(0, 13, 5) {
                num = Text(str(k * 10), position=(-125 + k * 10, -base_w / 2 + 11), size=3.5)
            }
        }
        Fixed(body)
        Fixed(ruler)
    }
    solid right_half {
        body = Rectangle(corner=(0, -base_w / 2), opposite=(base_len / 2, base_w / 2))
        joint = dovetail(part="socket", length=base_w, depth=10 mm, tails=2, rotation=-90 deg,
                         cx=0 mm, cy=0 mm)
        slots = tab_and_slot(part="slot", length=base_w, thickness=t, tabs=2, tab=15 mm,
                             screw=0, rotation=90 deg, cx=up_x, cy=0 mm)
        drawing ruler {
            for k in range(13, 26) {
                tick = Line((-125 + k * 10, -base_w / 2 + 1), (-125 + k * 10,
                            -base_w / 2 + 1 + tick_len(k)))
            }
            for k in range(15, 26, 5) {
                num = Text(str(k * 10), position=(-125 + k * 10, -base_w / 2 + 11), size=3.5)
            }
        }
        Fixed(body)
        Fixed(ruler)
    }
    left_end = upright()
    right_end = upright()

    # flat for cutting, each piece within the 200 mm bed
    Below(right_half, left_half, gap=6)
    AlignLeft(right_half, left_half)
    RightOf(left_end, left_half, gap=6)
    AlignTop(left_end, left_half)
    Below(right_end, left_end, gap=6)
    AlignLeft(right_end, left_end)

    # assembled: the halves side by side as joined, the uprights standing across them
    Place(left_half, position=(0, 0, 0))
    Place(right_half, position=(0, 0, 0))
    Place(left_end, position=(-up_x - t / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(right_end, position=(up_x - t / 2, 0, 0), rotation=(90 deg, 0, 90 deg))

    # the tail half reaches 10 mm across the joint's band into the socket half
    assert left_half.body.bb.width - 10 mm + right_half.body.bb.width == 300 mm, "300 overall"
    assert left_half.body.bb.width <= 200 mm and right_half.body.bb.width <= 200 mm,
        "each half fits the 200 mm bed"
    assert left_half.body.bb.height == 80 mm
    assert left_half.slots.bb.center_x - left_half.body.bb.left == 13 mm, "upright 13 mm in"
    assert right_half.body.bb.right - right_half.slots.bb.center_x == 13 mm, "upright 13 mm in"
    assert len(left_half.ruler.tick) + len(right_half.ruler.tick) == 26, "ticks 0..250"
    assert left_end.body.bb.width == 80 mm and left_end.body.bb.height == 70 mm
}
