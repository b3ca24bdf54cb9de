# Request: the shell of a 14 inch (356 mm) frame drum, bodhran style, glued up from 6 mm
# birch ply: 10 rings (60 mm deep), each ring 12 mm wide (356 mm outside, 332 inside) and
# made of six 60 deg segments so it nests on a 600 x 400 sheet; alternate rings turned
# 30 deg so the butt joints are staggered like brickwork. Each segment has two 3 mm dowel
# holes on the 344 mm circle, 10 and 40 deg from its start (so they line up through every
# layer), and an engraved 3 mm glue-up mark (layer letter A-J, segment number 1-6) 25 deg
# from its start. Across the back, two crossed bars (the hand grip) 24 mm wide, cross-halved
# at their middle (6.3 mm slots, 12 mm deep), running at 45 and 135 deg; their ends sit 6 mm
# deep in 6.4 mm notches in the inside edge of the four back rings (G-J), so each bar is
# 332 + 2 x 6 = 344 mm long.

import "std/joints.aidl"

t = 6 mm
thickness t

letters = ["A", "B", "C", "D", "E", "F", "G", "H", "I", "J"]
bar_angles = [45, 135, 225, 315]
def seg_start(layer, j) = 30 deg * (layer % 2) + j * 60 deg

def shell_segment(layer=0, j=0, ox=0 mm, oy=0 mm, notched=false) -> solid {
    ring = Sector(center=(ox, oy), radius=178, start_angle=seg_start(layer, j),
                  end_angle=seg_start(layer, j) + 60 deg, inner_radius=166)
    for a in [10, 40] {
        hole pin {
            c = Circle(center=(ox + 172 * cos(seg_start(layer, j) + a * 1 deg),
                               oy + 172 * sin(seg_start(layer, j) + a * 1 deg)), diameter=3)
        }
    }
    if notched {
        for b in bar_angles {
            if b * 1 deg > seg_start(layer, j) and b * 1 deg < seg_start(layer, j) + 60 deg {
                hole notch {
                    n = Rectangle(center=(ox + 168 * cos(b * 1 deg), oy + 168 * sin(b * 1 deg)),
                                  width=8, height=6.4, rotation=b * 1 deg, overrun=true)
                }
            }
        }
    }
    drawing mark {
        m = Text(letters[layer] + str(j + 1),
                 position=(ox + 172 * cos(seg_start(layer, j) + 25 deg),
                           oy + 172 * sin(seg_start(layer, j) + 25 deg)),
                 size=3, valign="middle", rotation=seg_start(layer, j) + 25 deg - 90 deg)
    }
}

def cross_bar(top=true, oy=0 mm) -> solid {
    body = Rectangle(center=(0, oy), width=344, height=24)
    if top {
        halving = cross_halving(depth=12 mm, thickness=6 mm, clearance=0.3 mm, cx=0 mm, cy=oy + 12 mm)
    } else {
        halving = cross_halving(depth=12 mm, thickness=6 mm, clearance=0.3 mm,
                                rotation=180 deg, cx=0 mm, cy=oy - 12 mm)
    }
}

assembly frame_drum {
    for k in range(10) {
        for j in range(6) {
            seg = shell_segment(layer=k, j=j, ox=(k % 5) * 380 mm, oy=-(k // 5) * 380 mm,
                                notched=k >= 6)
            Place(seg, position=(-(k % 5) * 380 mm, (k // 5) * 380 mm, k * t))
        }
    }
    bar_a = cross_bar(top=true, oy=-600 mm)
    bar_b = cross_bar(top=false, oy=-640 mm)
    # standing on edge across the back four rings (z 36 to 60), mid-planes through the axis
    Place(bar_a, position=(-2.1213 mm, 2.1213 mm, 48 mm + 600 mm), rotation=(90 deg, 0 deg, 45 deg))
    Place(bar_b, position=(-2.1213 mm, -2.1213 mm, 48 mm + 640 mm), rotation=(90 deg, 0 deg, 135 deg))

    # the request's numbers
    assert len(seg) == 10 and len(seg[0]) == 6, "10 rings of 6 segments"
    assert 10 * t == 60 mm, "60 mm deep"
    assert abs(2 * seg[0][0].ring.radius - 356 mm) < 0.01 mm, "356 mm outside"
    assert abs(2 * seg[0][0].ring.inner_radius - 332 mm) < 0.01 mm, "332 mm inside"
    assert abs(seg_start(1, 0) - seg_start(0, 0) - 30 deg) < 0.01 deg, "joints staggered 30 deg"
    assert distance(seg[0][0].pin[1].c.center - seg[0][0].ring.center,
                    seg[1][0].pin[0].c.center - seg[1][0].ring.center) < 0.01 mm, "dowel holes line up layer to layer"
    assert abs(bar_a.body.width - (332 mm + 2 * 6 mm)) < 0.01 mm, "bars 344 mm"
    assert abs(bar_a.body.height - 24 mm) < 0.01 mm and 4 * t == 24 mm, "bars as wide as the four back rings"
    assert len(seg[6][0].notch) + len(seg[6][1].notch) + len(seg[6][2].notch) + len(seg[6][3].notch) +
           len(seg[6][4].notch) + len(seg[6][5].notch) == 4, "four notches per back ring"
}
