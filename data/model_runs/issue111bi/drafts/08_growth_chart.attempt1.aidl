# Request: a growth chart for my niece Lily's bedroom wall, as a birthday gift. 6 mm birch ply,
# 160 mm wide, hung with its bottom edge 50 cm above the floor and reading up to 170 cm at its
# top (so 1200 mm tall). My laser takes 600 x 400, so it is cut in three sections, 395, 400 and
# 405 mm tall, so the seams fall between the centimetre marks, joined by sliding dovetails
# (two tails, 60 mm long, 10 mm deep, 10 deg) placed right of centre, away from the scale.
# - the scale engraved along the left edge (from 1 mm in): a mark every cm, 8 mm long; every
#   5 cm 14 mm; every 10 cm 22 mm, with its height in cm engraved filled (8 mm figures, 6 mm
#   right of the long mark), from 60 to 160;
# - LILY engraved filled in 50 mm bold letters up the right half of the middle section,
#   reading bottom to top, and a 40 mm filled star in the top section;
# - rounded 20 mm corners at the top right and bottom right (the scale side stays square);
# - two keyholes (9 mm head, 4.5 mm slot, 10 mm up) 80 mm apart, centred, 60 mm below the top;
#   one countersunk M4 screw hole (8 mm head) 60 mm above the bottom, 40 mm right of centre.

units mm
thickness 6 mm
import "std/joints.aidl"
import "std/plates.aidl"
import "std/fasteners.aidl"

W = 160 mm
SEAMS = [0 mm, 395 mm, 795 mm, 1200 mm]
FIRST = [1, 40, 80]       # the cm marks each section carries: FIRST[k] .. LAST[k] - 1
LAST = [40, 80, 120]
BOTTOM_CM = 50
DX = 20 mm                # the dovetails' middle, right of the centre line
DLEN = 60 mm
DDEPTH = 10 mm

def tick_len(n) = 22 if n % 10 == 0 else (14 if n % 5 == 0 else 8)

# section k of the chart, drawn where it sits on the finished board (y from the bottom edge)
def section(k=0) -> solid {
    body = RoundedRectangle(bottom_left=(-W / 2, SEAMS[k]), width=W, height=SEAMS[k + 1] - SEAMS[k],
                            corner_radii=[0, 20 if k == 2 else 0, 20 if k == 0 else 0, 0])
    if k < 2 {
        solid band {
            b = Rectangle(center=(DX, SEAMS[k + 1] + DDEPTH / 2), width=DLEN, height=DDEPTH)
        }
        tails = dovetail(part="tail", length=DLEN, depth=DDEPTH, tails=2, angle=10 deg,
                         cx=DX, cy=SEAMS[k + 1])
    }
    if k > 0 {
        sockets = dovetail(part="socket", length=DLEN, depth=DDEPTH, tails=2, angle=10 deg,
                           cx=DX, cy=SEAMS[k])
    }
    drawing scale {
        for n in range(FIRST[k], LAST[k]) {
            t = Line((-W / 2 + 1, n * 10 mm), (-W / 2 + 1 + tick_len(n), n * 10 mm))
        }
        for n in [m for m in range(FIRST[k], LAST[k]) if m % 10 == 0] {
            lab = Text(str(BOTTOM_CM + n), position=(-W / 2 + 1 + 22 + 6, n * 10 mm), size=8,
                       anchor="start", valign="middle", font="sans", fill=true)
        }
    }
}

assembly growth_chart {
    for k in range(3) {
        sec = section(k=k)
        Place(sec, position=(0, 0, 0))
    }

    drawing name {
        t = Text("LILY", position=(35, 595), size=50, rotation=90 deg, font="sans:Bold",
                 valign="middle", fill=true)
    }
    CutInto(name, sec[1])

    drawing deco {
        s = Star(center=(35, 1000), points=5, outer_radius=20, inner_radius=8.5, fill=true)
    }
    CutInto(deco, sec[2])

    hangers = [keyhole(head=9, slot_width=4.5, length=10, direction=90 deg, cx=-40, cy=1140),
               keyhole(head=9, slot_width=4.5, length=10, direction=90 deg, cx=40, cy=1140)]
    CutInto(hangers[0], sec[2])
    CutInto(hangers[1], sec[2])

    screw = clearance_hole(size=4, cx=40, cy=60)
    Countersink(screw, diameter=8)
    CutInto(screw, sec[0])

    # on the sheet: the sections side by side
    RightOf(sec[1], sec[0], gap=10)
    AlignBottom(sec[1].body, sec[0].body)
    RightOf(sec[2], sec[1], gap=10)
    AlignBottom(sec[2].body, sec[1].body)

    # the request's numbers
    assert sec[0].body.bb.width == 160 mm, "160 wide"
    assert sec[0].body.bb.height + sec[1].body.bb.height + sec[2].body.bb.height == 1200 mm,
        "1200 tall"
    assert sec[0].body.bb.height == 395 mm and sec[1].body.bb.height == 400 mm and
        sec[2].body.bb.height == 405 mm, "sections 395 / 400 / 405"
    assert BOTTOM_CM + 1200 mm / 10 mm == 170, "reads up to 170 at the top"
    assert len(sec[0].scale.t) + len(sec[1].scale.t) + len(sec[2].scale.t) == 119, "a mark every cm"
    assert len(sec[0].scale.lab) + len(sec[1].scale.lab) + len(sec[2].scale.lab) == 11,
        "labels 60 .. 160"
    assert sec[0].tails.depth == 10 mm and sec[0].tails.length == 60 mm, "dovetails 60 x 10"
    assert name.t.size == 50 mm, "50 mm letters"
    assert deco.s.bb.height <= 40 mm, "star within 40"
    assert hangers[1].head_hole.center.x - hangers[0].head_hole.center.x == 80 mm, "keyholes 80 apart"
    assert sec[2].body.bb.top - hangers[0].head_hole.center.y == 60 mm, "keyholes 60 below the top"
    assert screw.c.center.y - sec[0].body.bb.bottom == 60 mm, "screw 60 above the bottom"
    assert screw.c.center.x - sec[0].body.bb.center_x == 40 mm, "screw 40 right of centre"
}
