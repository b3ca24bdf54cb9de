# Request: a tabletop bookcase for paperbacks, cut from 6 mm birch ply. 400 mm wide overall,
# 180 mm deep. Two sides 180 x 490 mm, the top front corner rounded R40, an arch 110 mm wide and
# 22 mm high cut from the bottom edge between the feet. Three shelves 400 x 180 mm whose ends
# pass through the sides as 2 tabs of 30 mm, each end screwed with an M3 x 16 screw into a
# captive nut. The bottom shelf's top is 40 mm above the table; two tiers of 210 mm clear
# height (198 mm paperbacks). A back rail 400 x 40 mm stands on each of the two lower shelves,
# 10 mm in from the back edge, held by one glued 20 mm tenon at each end. The left side's outer
# face is engraved "ANNA'S BOOKS" (serif bold, filled) in the upper tier.

import "std/joints.aidl"

t = 6 mm
thickness t

D = 180 mm           # depth
H = 490 mm           # side height
W = 400 mm           # overall width (shelf tabs flush with the sides' outer faces)
tier = 210 mm        # clear height of a tier
rail_h = 40 mm
rail_in = 10 mm      # the rail's back face from the sides' back edge
shelf_tops = [40 mm + i * (tier + t) for i in range(3)]

# s = 1: the front edge at +x (left side seen from outside); s = -1: front at -x (right side)
def side(s=1, label="") -> solid {
    body = RoundedRectangle(center=(0, H / 2), width=D, height=H,
                            corner_radii=[40 mm if s < 0 else 0 mm, 40 mm if s > 0 else 0 mm, 0 mm, 0 mm])
    for i in range(3) {
        sh = tab_and_slot(part="slot", length=D, thickness=t, tabs=2, tab=30 mm, screw=3,
                          cx=0 mm, cy=shelf_tops[i] - t / 2)
    }
    for i in range(2) {
        rs = tab_and_slot(part="slot", length=rail_h, thickness=t, tabs=1, tab=20 mm, screw=0,
                          rotation=90 deg, cx=-s * (D / 2 - rail_in - t / 2),
                          cy=shelf_tops[i] + rail_h / 2)
    }
    hole arch {
        e = Ellipse(center=(0, 0), rx=55 mm, ry=22 mm)
    }
    if label != "" {
        drawing name {
            n = Text(label, position=(0, shelf_tops[1] + tier / 2), size=18, font="serif:Bold",
                     valign="middle", max_width=150 mm, fill=true)
        }
    }
}

def shelf() -> solid {
    body = Rectangle(center=(0, 0), width=W, height=D)
    lt = tab_and_slot(part="tab", length=D, thickness=t, tabs=2, tab=30 mm, screw=3,
                      rotation=90 deg, cx=-W / 2, cy=0 mm)
    rt = tab_and_slot(part="tab", length=D, thickness=t, tabs=2, tab=30 mm, screw=3,
                      rotation=-90 deg, cx=W / 2, cy=0 mm)
}

def rail() -> solid {
    body = Rectangle(center=(0, rail_h / 2), width=W, height=rail_h)
    lt = tab_and_slot(part="tab", length=rail_h, thickness=t, tabs=1, tab=20 mm, screw=0,
                      rotation=90 deg, cx=-W / 2, cy=rail_h / 2)
    rt = tab_and_slot(part="tab", length=rail_h, thickness=t, tabs=1, tab=20 mm, screw=0,
                      rotation=-90 deg, cx=W / 2, cy=rail_h / 2)
}

assembly bookcase {
    left = side(s=1, label="ANNA'S BOOKS")
    right = side(s=-1)
    for i in range(3) {
        sh = shelf()
        Place(sh, position=(0, 0, shelf_tops[i] - t), face="up", up="back")
    }
    for i in range(2) {
        rl = rail()
        Place(rl, position=(0, D / 2 - rail_in, shelf_tops[i]), face="front", up="up")
    }
    # 3D: the sides' outer faces look out, their fronts to -y
    Place(left, position=(-W / 2 + t, 0, 0), face="left", up="up")
    Place(right, position=(W / 2 - t, 0, 0), face="right", up="up")

    # flat layout for cutting
    RightOf(right, left, gap=10)
    AlignBottom(right, left)
    RightOf(sh[0], right, gap=10)
    AlignBottom(sh[0], right)
    Above(sh[1], sh[0], gap=10)
    AlignLeft(sh[1], sh[0])
    Above(sh[2], sh[1], gap=10)
    AlignLeft(sh[2], sh[1])
    RightOf(rl[0], sh[0], gap=10)
    AlignBottom(rl[0], sh[0])
    Above(rl[1], rl[0], gap=10)
    AlignLeft(rl[1], rl[0])

    # the request's numbers
    assert len(sh) == 3 and len(rl) == 2, "three shelves, two rails"
    assert left.body.bb.width == 180 mm and left.body.bb.height == 490 mm, "sides 180 x 490"
    assert sh[0].body.bb.width == 400 mm and sh[0].body.bb.height == 180 mm, "shelves 400 x 180"
    assert rl[0].body.bb.width == 400 mm and rl[0].body.bb.height == 40 mm, "rails 400 x 40"
    assert shelf_tops[0] == 40 mm, "bottom shelf top 40 mm up"
    assert shelf_tops[1] - t - shelf_tops[0] == 210 mm and shelf_tops[2] - t - shelf_tops[1] == 210 mm,
        "two tiers of 210 mm clear"
    assert H - shelf_tops[2] >= 10 mm, "material above the top shelf's slot"
    assert left.arch.e.rx * 2 == 110 mm and left.arch.e.ry == 22 mm, "foot arch 110 x 22"
    assert D / 2 - rail_in - t / 2 == 77 mm, "rail 10 mm in from the back edge"
}
