# Request: a rug punch-needle frame, 300 x 300 mm outside, from 6 mm birch ply rails 40 mm
# wide; carpet gripper strips (25 mm) are glued along the outer part of each rail later. The
# two side rails run the full 300 mm; the top and bottom rails fit between them and lock in
# with one flat sliding dovetail at each end (10 mm deep, 10 degrees, 0.1 mm clearance in the
# sockets). On the inner 15 mm of the top rail an engraved centring scale: a tick every
# 10 mm over the 200 mm middle, 4 mm long, 7 mm at every 50 mm, labelled 10 5 0 5 10 (cm from
# the centre) 3 mm high. On the bottom rail's inner edge "PUNCH NEEDLE FRAME" 5 mm high.

import "std/joints.aidl"

t = 6 mm
thickness t

size = 300 mm
rail = 40 mm
dt_depth = 10 mm
half = size / 2
inner = half - rail          # 110: the inner edges
mid = half - rail / 2        # 130: the rails' centre lines

def side_rail(s=1) -> solid {
    body = Rectangle(center=(s * mid, 0), width=rail, height=size)
    upper = dovetail(part="socket", length=rail, depth=dt_depth, tails=1, angle=10 deg,
                     clearance=0.1 mm, rotation=-90 deg * s, cx=s * inner, cy=mid)
    lower = dovetail(part="socket", length=rail, depth=dt_depth, tails=1, angle=10 deg,
                     clearance=0.1 mm, rotation=-90 deg * s, cx=s * inner, cy=-mid)
}

def cross_rail(s=1) -> solid {
    body = Rectangle(center=(0, s * mid), width=2 * (inner + dt_depth), height=rail)
    left_tail = dovetail(part="tail", length=rail, depth=dt_depth, tails=1, angle=10 deg,
                         rotation=90 deg, cx=-inner, cy=s * mid)
    right_tail = dovetail(part="tail", length=rail, depth=dt_depth, tails=1, angle=10 deg,
                          rotation=-90 deg, cx=inner, cy=s * mid)
}

assembly frame {
    left = side_rail(s=-1)
    right = side_rail(s=1)
    top = cross_rail(s=1)
    bottom = cross_rail(s=-1)

    # the centring scale on the top rail's inner edge (y = 110)
    drawing scale {
        for i in range(21) {
            tick = Line((-100 + i * 10, inner), (-100 + i * 10, inner + (7 if i % 5 == 0 else 4)))
        }
        for k in range(5) {
            num = Text(str(abs(k - 2) * 5), position=(-100 + k * 50, inner + 9), size=3,
                       valign="baseline")
        }
    }
    Rigid(scale)
    scale.tick[0].start.y == top.body.bottom.midpoint.y
    scale.tick[10].start.x == top.body.center.x
    CutInto(scale, top)

    drawing name {
        n = Text("PUNCH NEEDLE FRAME", position=(0, -inner - 7.5), size=5, valign="middle")
    }
    At(name.n.position, bottom.body.top.midpoint, dy=-7.5)
    CutInto(name, bottom)

    # on the sheet
    RightOf(right, left, gap=6)
    AlignTop(right, left)
    RightOf(top, right, gap=6)
    AlignTop(top, right)
    Below(bottom, top, gap=6)
    AlignLeft(bottom, top)

    # in 3D every rail is drawn where it sits in the frame
    Place(left, position=(0, 0, 0), face="up")
    Place(right, position=(0, 0, 0), face="up")
    Place(top, position=(0, 0, 0), face="up")
    Place(bottom, position=(0, 0, 0), face="up")

    # the request's numbers (as written, in the frame's coordinates)
    assert right.body.bb.right - left.body.bb.left == 300 mm, "300 mm wide"
    assert top.body.bb.top - bottom.body.bb.bottom == 300 mm, "300 mm tall"
    assert left.body.width == 40 mm and top.body.height == 40 mm
    assert top.body.bb.left == left.body.bb.right - 10 mm, "tails reach 10 mm into the sides"
    assert len(scale.tick) == 21 and len(scale.num) == 5
    assert scale.tick[1].start.x - scale.tick[0].start.x == 10 mm
    assert scale.tick[0].length == 7 mm and scale.tick[1].length == 4 mm
    assert scale.num[0].size == 3 mm
    assert scale.bb.top - top.body.bb.bottom <= 15 mm, "scale in the inner 15 mm"
    assert name.bb.bottom - bottom.body.bb.top >= -15 mm, "name in the inner 15 mm"
    assert name.n.size == 5 mm
}
