# Request (bathroom / dressing table): a stand that holds a stack of hair bands (alice
# bands) slid over it. 6 mm birch ply. Two arches, each a half-ellipse 140 wide at the
# base and 170 tall, with a half-ellipse window 80 wide and 120 tall whose base is 25 mm
# up. The arches stand 100 mm apart (inside faces), joined by three 20 mm wide cross bars,
# each with a single 12 mm tenon glued into a mortise at both ends: one under the crown
# (mortise centre 8 mm below the top) lying flat, two upright at the sides, 50 mm up, their
# outer faces 5 mm inside the rim. "ROSIE" engraved filled, 10 mm bold, on the front arch's
# base strip.

import "std/joints.aidl"

thickness 6 mm

param t = 6 mm, min = 4 mm, max = 8 mm
param arch_w = 140 mm, min = 110 mm, max = 180 mm
param arch_h = 170 mm, min = 130 mm, max = 220 mm
param win_w = 80 mm, min = 50 mm, max = 110 mm
param win_h = 120 mm, min = 80 mm, max = 160 mm
param win_up = 25 mm, min = 18 mm, max = 40 mm
param span = 100 mm, min = 70 mm, max = 140 mm
param bar_w = 20 mm, min = 16 mm, max = 30 mm
param side_up = 50 mm, min = 35 mm, max = 70 mm

# x of the rim at height y
def rim_x(y) = arch_w / 2 * sqrt(1 - (y / arch_h) ** 2)
side_x = rim_x(side_up) - 5 mm - t / 2
top_y = arch_h - 8 mm

def arch(name="") -> solid {
    # (0, 0) is the middle of the base
    shape = Intersect(Ellipse(center=(0, 0), rx=arch_w / 2, ry=arch_h),
                      Rectangle(bottom_left=(-arch_w / 2 - 1, 0), width=arch_w + 2,
                                height=arch_h + 1))
    hole window {
        w = Intersect(Ellipse(center=(0, win_up), rx=win_w / 2, ry=win_h),
                      Rectangle(bottom_left=(-win_w / 2 - 1, win_up), width=win_w + 2,
                                height=win_h + 1))
    }
    crown = tab_and_slot(part="slot", length=bar_w, thickness=t, tabs=1, tab=12 mm, screw=0,
                         cx=0, cy=top_y)
    left_m = tab_and_slot(part="slot", length=bar_w, thickness=t, tabs=1, tab=12 mm, screw=0,
                          rotation=90 deg, cx=-side_x, cy=side_up)
    right_m = tab_and_slot(part="slot", length=bar_w, thickness=t, tabs=1, tab=12 mm, screw=0,
                           rotation=90 deg, cx=side_x, cy=side_up)
    if name != "" {
        drawing label {
            word = Text(name, position=(0, win_up / 2), size=10, font="sans:Bold",
                        valign="middle", fill=true)
        }
    }
}

def bar() -> solid {
    # (0, 0) is its middle; the tenons at both ends, tips span + 2 t apart
    body = Rectangle(center=(0, 0), width=span + 2 * t, height=bar_w)
    left_t = tab_and_slot(part="tab", length=bar_w, thickness=t, tabs=1, tab=12 mm, screw=0,
                          rotation=90 deg, cx=-(span / 2 + t), cy=0)
    right_t = tab_and_slot(part="tab", length=bar_w, thickness=t, tabs=1, tab=12 mm, screw=0,
                           rotation=-90 deg, cx=span / 2 + t, cy=0)
}

assembly headband_stand {
    front = arch(name="ROSIE")
    back = arch()
    crown_bar = bar()
    left_bar = bar()
    right_bar = bar()

    # on the sheet
    RightOf(back, front, gap=6)
    AlignBottom(back, front)
    Below(crown_bar, front, gap=6)
    AlignLeft(crown_bar, front)
    Below(left_bar, crown_bar, gap=6)
    AlignLeft(left_bar, crown_bar)
    Below(right_bar, left_bar, gap=6)
    AlignLeft(right_bar, left_bar)

    # assembled: the arches' inside faces span apart, the bars between them
    Place(front, position=(0, -span / 2, 0), face="front", up="up")
    Place(back, position=(0, span / 2, 0), face="back", up="up")
    Place(crown_bar, position=(0, 0, top_y - t / 2), face="up", up="left")
    Place(left_bar, position=(-side_x + t / 2, 0, side_up), face="left", up="up")
    Place(right_bar, position=(side_x - t / 2, 0, side_up), face="right", up="up")

    # the request's numbers
    assert front.shape.bb.width == 140 mm and front.shape.bb.height == 170 mm, "arch 140 x 170"
    assert front.window.w.bb.width == 80 mm and front.window.w.bb.height == 120 mm,
        "window 80 x 120"
    assert front.window.w.bb.bottom - front.shape.bb.bottom == 25 mm, "window 25 mm up"
    assert crown_bar.body.bb.width - 2 * 6 mm == 100 mm, "arches 100 apart"
    assert front.shape.bb.top - front.crown.slot[0].bb.center_y == 8 mm, "crown mortise 8 down"
    assert front.right_m.slot[0].bb.center_y - front.shape.bb.bottom == 50 mm, "sides 50 up"
    assert front.label.word.bb.bottom >= front.shape.bb.bottom + 3 mm and
        front.label.word.bb.top <= front.window.w.bb.bottom - 3 mm, "name on the base strip"
    assert front.right_m.slot[0].bb.left > front.window.w.bb.right + 3 mm,
        "side mortise clear of the window"
}
