# Request: a torii-style floor-top stand for a 30 cm (12 inch) gong, from 9 mm ply, five parts.
# Two pillars 70 wide, their top 480 above the floor, 400 apart between their inner edges
# (the gong hangs between them with 50 mm to spare each side). Across their tops a curved
# crossbar 640 long: its underside straight between the pillars and rising 20 mm over its last
# 40 mm at each end, its top an arc 50 high in the middle and 70 at the tips. Each pillar
# locks into the crossbar's underside with one flat sliding dovetail (15 deep). Two 6 mm cord
# holes in the crossbar 180 apart, 20 up, and "GONG" engraved filled between them. Each pillar
# stands in a foot 250 long x 60 tall (top corners chamfered 20) by a cross-halving, half
# the foot's height each. The right pillar has a 22 mm hole 300 up to park the mallet.

units mm
thickness 9 mm
import "std/joints.aidl"

T = 9 mm
PILLAR_W = 70 mm
PILLAR_H = 480 mm
INNER = 400 mm
PX = INNER / 2 + PILLAR_W / 2      # the pillars' centres
TAIL = 15 mm
FOOT_L = 250 mm
FOOT_H = 60 mm

def pillar(mallet=false) -> solid {
    # y up from the floor; the tail stands TAIL above the crossbar's underside
    body = Rectangle(bottom_left=(-PILLAR_W / 2, 0), width=PILLAR_W, height=PILLAR_H + TAIL)
    top = dovetail(part="tail", length=PILLAR_W, depth=TAIL, tails=1, angle=10 deg,
                   cx=0 mm, cy=PILLAR_H)
    foot = cross_halving(depth=FOOT_H / 2, thickness=T, rotation=180 deg, cx=0 mm, cy=0 mm)
    if mallet {
        hole park { c = Circle(center=(0, 300 mm), diameter=22 mm) }
    }
}

def foot() -> solid {
    body = Rectangle(bottom_left=(-FOOT_L / 2, 0), width=FOOT_L, height=FOOT_H)
    slot = cross_halving(depth=FOOT_H / 2, thickness=T, cx=0 mm, cy=FOOT_H)
    Chamfer([body.top_left, body.top_right], 20 mm)
}

assembly gong_stand {
    left = pillar()
    right = pillar(mallet=true)
    foot_l = foot()
    foot_r = foot()

    # y up from the crossbar's underside (the pillars' tops)
    solid crossbar {
        under = Line((-280 mm, 0), (280 mm, 0))
        rise_r = Line((280 mm, 0), (320 mm, 20 mm))
        end_r = Line((320 mm, 20 mm), (320 mm, 70 mm))
        top = Arc(start=(320 mm, 70 mm), through=(0, 50 mm), end=(-320 mm, 70 mm))
        end_l = Line((-320 mm, 70 mm), (-320 mm, 20 mm))
        rise_l = Line((-320 mm, 20 mm), (-280 mm, 0))
        sock_l = dovetail(part="socket", length=PILLAR_W, depth=TAIL, tails=1, angle=10 deg,
                          cx=-PX, cy=0 mm)
        sock_r = dovetail(part="socket", length=PILLAR_W, depth=TAIL, tails=1, angle=10 deg,
                          cx=PX, cy=0 mm)
        for x in [-90 mm, 90 mm] {
            hole cord { c = Circle(center=(x, 20 mm), diameter=6 mm) }
        }
        drawing name { t = Text("GONG", position=(0, 26 mm), size=16 mm, font="sans:Bold", valign="middle", fill=true) }
    }

    # flat, for cutting
    RightOf(right, left, gap=10 mm)
    AlignBottom(right, left)
    RightOf(foot_l, right, gap=10 mm)
    AlignBottom(foot_l, left)
    Above(foot_r, foot_l, gap=10 mm)
    AlignLeft(foot_r, foot_l)
    Above(crossbar, left, gap=10 mm)
    AlignLeft(crossbar, left)

    # assembled: pillars and crossbar face the front, the feet run front to back
    Place(left, position=(-PX, T / 2, 0), face="front", up="up")
    Place(right, position=(PX, T / 2, 0), face="front", up="up")
    Place(crossbar, position=(0, T / 2, PILLAR_H), face="front", up="up")
    Place(foot_l, position=(-PX - T / 2, 0, 0), face="right", up="up")
    Place(foot_r, position=(PX - T / 2, 0, 0), face="right", up="up")

    assert crossbar.sock_r.bb.center_x - crossbar.sock_l.bb.center_x - 70 mm == 400 mm, "400 between the pillars"
    assert left.body.bb.width == 70 mm, "pillars 70 wide"
    assert crossbar.bb.width == 640 mm, "crossbar 640 long"
    assert crossbar.top.through.y - crossbar.under.start.y == 50 mm, "50 high in the middle"
    assert crossbar.end_r.end.y - crossbar.under.start.y == 70 mm, "70 at the tips"
    assert crossbar.cord[1].c.center.x - crossbar.cord[0].c.center.x == 180 mm, "cord holes 180 apart"
    assert foot_l.body.bb.width == 250 mm and foot_l.body.bb.height == 60 mm, "feet 250 x 60"
    assert left.foot.depth + foot_l.slot.depth == 60 mm, "halvings meet"
    assert right.park.c.center.y - right.body.bb.bottom == 300 mm, "mallet hole 300 up"
}
