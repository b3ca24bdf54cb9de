# Request (workshop): a shooting board for trimming end grain square with a hand plane, cut
# from 9 mm birch ply. Base 450 x 300 mm. Bed 450 x 200 mm glued and screwed on the base
# (four countersunk M4 screws, 8.4 mm heads) flush with its back edge, leaving a 100 mm
# runway for the plane along the front. Fence 200 mm long (the bed's full depth) standing
# 50 mm above the bed, its left face 40 mm from the left end, held square by two 40 mm
# tenons through the bed, and backed by one triangular brace (40 x 40, one 20 mm tenon).
# A hook cleat 300 x 40 hangs under the base, its front face 15 mm behind the front edge,
# on two 40 mm tenons through the base, to catch the bench edge. A 30 mm hanging hole
# through bed and base at the right back corner (centre 25 mm in from the right end, 30 mm
# from the back). Engraved on the bed: "SHOOTING BOARD" and a ruler along the bed's front
# edge measured from the fence face, a tick every 10 mm to 400 mm, numbered every 50 mm.

units mm
thickness 9 mm

import "std/joints.aidl"
import "std/fasteners.aidl"

T = 9 mm
base_w = 450 mm
base_d = 300 mm
bed_d = 200 mm
fence_h = 50 mm
fence_x = -base_w / 2 + 40 mm          # the fence's left face, in the base's frame
bed_cy = base_d / 2 - bed_d / 2        # bed centre y in the base's frame
cleat_y = -base_d / 2 + 15 mm          # cleat's front face
hang_x = base_w / 2 - 25 mm
hang_y = base_d / 2 - 30 mm

assembly shooting_board {
    solid base {
        body = Rectangle(center=(0, 0), width=base_w, height=base_d)
        # cleat tenons: the cleat stands from cleat_y to cleat_y + T
        cleat_mortise = tab_and_slot(part="slot", length=300 mm, thickness=T, tabs=2, tab=40 mm,
                                     screw=0, cx=0 mm, cy=cleat_y + T / 2)
        hole hang { c = Circle(center=(hang_x, hang_y), diameter=30) }
    }

    solid bed {
        body = Rectangle(center=(0, 0), width=base_w, height=bed_d)
        fence_mortise = tab_and_slot(part="slot", length=bed_d, thickness=T, tabs=2, tab=40 mm,
                                     screw=0, rotation=90 deg, cx=fence_x + T / 2, cy=0 mm)
        brace_mortise = tab_and_slot(part="slot", length=40 mm, thickness=T, tabs=1, tab=20 mm,
                                     screw=0, cx=-base_w / 2 + 20 mm, cy=0 mm)
        hole hang { c = Circle(center=(hang_x, hang_y - bed_cy), diameter=30) }
        for p in [[-150, 70], [-150, -70], [150, 70], [150, -70]] {
            screw = clearance_hole(size=4, cx=p[0] * 1 mm, cy=p[1] * 1 mm)
        }
        Countersink(screw, diameter=8.4 mm)
        drawing marks {
            title = Text("SHOOTING BOARD", position=(40, 40), size=14, font="sans:Bold",
                         valign="middle", fill=true)
            for i in range(41) {
                tick = Line((fence_x + T + i * 10 mm, -bed_d / 2),
                            (fence_x + T + i * 10 mm, -bed_d / 2 + (8 mm if i % 5 == 0 else 4 mm)))
            }
            # FIX after the first valid program: the "0" sat half under the fence (note W0532);
            # the numbers start at 50
            for j in range(1, 8) {
                num = Text(str(j * 50), position=(fence_x + T + j * 50 mm, -bed_d / 2 + 11 mm), size=4)
            }
        }
    }

    solid fence {
        body = Rectangle(bottom_left=(-bed_d / 2, 0), width=bed_d, height=fence_h + T)
        tenons = tab_and_slot(part="tab", length=bed_d, thickness=T, tabs=2, tab=40 mm,
                              screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
    }

    solid brace {
        body = Polygon([(0, 0), (40, 0), (40, 40 + T), (0, T)])
        tenon = tab_and_slot(part="tab", length=40 mm, thickness=T, tabs=1, tab=20 mm,
                             screw=0, rotation=180 deg, cx=20 mm, cy=0 mm)
    }

    solid cleat {
        body = Rectangle(bottom_left=(-150, -40), width=300, height=40 + T)
        tenons = tab_and_slot(part="tab", length=300 mm, thickness=T, tabs=2, tab=40 mm,
                              screw=0, cx=0 mm, cy=T)
    }

    # flat on the sheet
    Below(bed, base, gap=10)
    AlignLeft(bed, base)
    Below(fence, bed, gap=10)
    AlignLeft(fence, bed)
    RightOf(brace, fence, gap=10)
    AlignTop(brace, fence)
    RightOf(cleat, brace, gap=10)
    AlignTop(cleat, brace)

    # assembled
    Place(base, position=(0, 0, 0))
    Place(bed, position=(0, bed_cy, T))
    Place(fence, position=(fence_x, bed_cy, T), face="right", up="up")
    Place(brace, position=(-base_w / 2, bed_cy + T / 2, T), face="front", up="up")
    Place(cleat, position=(0, cleat_y + T, 0), face="front", up="up")

    # the request's numbers
    assert base.body.bb.width == 450 mm and base.body.bb.height == 300 mm, "base 450 x 300"
    assert bed.body.bb.width == 450 mm and bed.body.bb.height == 200 mm, "bed 450 x 200"
    assert base_d - bed_d == 100 mm, "a 100 mm runway"
    assert fence.body.bb.width == 200 mm, "fence spans the bed's depth"
    assert fence.body.bb.height - T == 50 mm, "fence stands 50 above the bed"
    assert fence_x - (-base_w / 2) == 40 mm, "fence 40 from the left end"
    assert cleat.body.bb.width == 300 mm and cleat.body.bb.height - T == 40 mm, "cleat 300 x 40"
    assert len(bed.screw) == 4, "four screws"
    assert base.hang.c.center.x - bed.hang.c.center.x == 0 mm, "hang holes line up in x"
    assert (base.hang.c.center.y - base.body.bb.bottom) - (bed.hang.c.center.y - bed.body.bb.bottom) == 100 mm,
        "hang holes line up in y"
    assert base.body.bb.right - base.hang.c.center.x == 25 mm, "hang hole 25 from the right end"
    assert base.body.bb.top - base.hang.c.center.y == 30 mm, "hang hole 30 from the back"
}
