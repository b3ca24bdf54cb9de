# Request: a classroom monochord, 6 mm birch ply: a closed finger-jointed sound box 520 x
# 100 x 50 mm (outside, 20 mm fingers) whose lid is the soundboard. One steel string runs
# along the lid's middle from a zither pin (4.8 mm hole, 20 mm in from the left end) over two
# fixed bridges 440 mm apart (the speaking length, symmetric about the middle) to a hitch pin
# (3 mm hole, 18 mm in from the right end). Two 30 mm sound holes 90 and 180 mm right of the
# middle, 25 mm behind the string, each ringed by an engraved 38 mm circle. Engraved on the
# lid: the string's line between the bridges, a 30 mm mark at each bridge, in front of the
# string the just-intonation ticks (10 mm long, labelled "1/2", "2/3", ... 3.5 mm) where a
# movable bridge leaves that fraction of the string sounding from the right bridge
# (1/4, 1/3, 2/5... here: 1/2, 2/3, 3/4, 4/5, 5/6, 8/9, 3/5, 1/3, 1/4), behind it the twelve
# equal-tempered semitone ticks (8 mm, numbered 1-12, 3 mm), and "MONOCHORD" (7 mm bold,
# filled) at the back, 100 mm left of the middle. Three bridges to cut: 40 mm wide, 12 mm high, 28 mm across
# the top, with a 1 mm V notch for the string (two glued, one loose).

import "std/joints.aidl"

thickness 6 mm
t = 6 mm

param L = 440 mm, min = 400 mm, max = 480 mm
box_len = 520 mm
xb = L / 2
ratios = [[1, 2], [2, 3], [3, 4], [4, 5], [5, 6], [8, 9], [3, 5], [1, 3], [1, 4]]

def xr(p) = xb - L * p[0] / p[1]
def xet(n) = xb - L * 2 ** (-n / 12)

def bridge() -> solid {
    body = Polygon([(-20, 0), (20, 0), (14, 12), (0.5, 12), (0, 11), (-0.5, 12), (-14, 12)])
}

assembly monochord {
    box = finger_box(length=box_len, depth=100 mm, height=50 mm, thickness=t, finger=20 mm,
                     closed=true, gap=8 mm)

    hole openings {
        zither = Circle(center=(-box_len / 2 + 20, 0), diameter=4.8)
        hitch = Circle(center=(box_len / 2 - 18, 0), diameter=3)
        snd_l = Circle(center=(90, 25), diameter=30)
        snd_r = Circle(center=(180, 25), diameter=30)
    }
    At(openings.zither.center, box.lid.outline.center, dx=-box_len / 2 + 20, dy=0)
    CutInto(openings, box.lid)

    drawing scale {
        string = Line((-xb, 0), (xb, 0))
        mark_l = Line((-xb, -15), (-xb, 15))
        mark_r = Line((xb, -15), (xb, 15))
        ring_l = Circle(center=(90, 25), diameter=38)
        ring_r = Circle(center=(180, 25), diameter=38)
        for p in ratios {
            jt = Line((xr(p), -6), (xr(p), -16))
            jl = Text(f"{p[0]}/{p[1]}", position=(xr(p), -21), size=3.5, valign="middle")
        }
        for n in range(1, 13) {
            et = Line((xet(n), 6), (xet(n), 14))
            el = Text(str(n), position=(xet(n), 18), size=3, valign="middle")
        }
        title = Text("MONOCHORD", position=(-100, 33), size=7, font="sans:Bold", fill=true,
                     valign="middle")
    }
    At(scale.string.midpoint, box.lid.outline.center)
    CutInto(scale, box.lid)

    b1 = bridge()
    b2 = bridge()
    b3 = bridge()
    RightOf(b1, box, gap=8)
    AlignTop(b1, box)
    Below(b2, b1, gap=6)
    AlignLeft(b2, b1)
    Below(b3, b2, gap=6)
    AlignLeft(b3, b2)
    # in 3D the two fixed bridges stand across the string on the lid (z = 50)
    Place(b1, position=(-xb + t / 2, 0, 50), face="left", up="up")
    Place(b2, position=(xb + t / 2, 0, 50), face="left", up="up")
    Place(b3, position=(t / 2, 0, 50), face="left", up="up")

    # the request's numbers
    assert box.lid.outline.width == 520 mm and box.lid.outline.height == 100 mm, "box 520 x 100"
    assert box.front.outline.height == 50 mm, "box 50 high"
    assert scale.mark_r.start.x - scale.mark_l.start.x == 440 mm, "bridges 440 apart"
    assert openings.zither.center.x - box.lid.outline.bb.left == 20 mm, "zither pin 20 in"
    assert box.lid.outline.bb.right - openings.hitch.center.x == 18 mm, "hitch pin 18 in"
    assert openings.snd_r.center.x - openings.snd_l.center.x == 90 mm and
        openings.snd_l.center.x - scale.string.midpoint.x == 90 mm, "sound holes 90 and 180 right"
    assert openings.snd_l.center.y - scale.string.start.y == 25 mm, "25 behind the string"
    assert len(scale.jt) == 9 and len(scale.et) == 12, "nine ratio ticks, twelve semitones"
    assert scale.mark_r.start.x - scale.jt[0].start.x == 220 mm, "the octave at the middle"
    assert scale.mark_r.start.x - scale.et[11].start.x == 220 mm, "12 semitones: the octave"
    assert distance(scale.title, scale.el[3]) >= 3 mm, "title clear of the semitone labels"
    assert distance(scale.et[11], scale.ring_l) >= 3 mm, "semitone ticks clear of the sound holes"
    assert b1.body.bb.width == 40 mm and b1.body.bb.height == 12 mm, "bridges 40 x 12"
}
