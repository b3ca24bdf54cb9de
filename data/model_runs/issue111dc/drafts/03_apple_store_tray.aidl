# Request: a stackable apple-storage tray for the garden shed, 6 mm ply, finger-jointed
# (20 mm fingers), glued. Outside 400 long x 300 wide. Long sides 70 mm tall, each with a
# row of 5 round vent holes 25 mm across, 70 mm apart, at mid-height. The two ends stand
# 120 mm tall so that trays stack on their ends with air between, their top corners rounded
# 15 mm, each with a hand hole 100 x 30 (round-ended) whose top is 25 mm below the end's top,
# and the variety engraved (serif bold, filled, 14 mm) under it: "COX" on one end, "BRAMLEY"
# on the other. The bottom has 16 vent slots 60 x 10 in 4 rows of 4 (85 mm apart along,
# 60 mm across), centred. Five parts.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
L = 400 mm
W = 300 mm
side_h = 70 mm
end_h = 120 mm
F = 20 mm

# FIX after the first valid program: the end's finger_edge along the 70 mm joint started with
# a gap, whose cut runs 1 mm on past the joint (to 71 mm) and nicked the taller end 1 x 6 mm
# above each side's top edge (seen with --describe: "notch ... 24.333 wide" from 46.67 to 71).
# Now the sides' edges start with gaps and the ends' with tabs (the end's top segment is
# material), and the bottom plate, starting with tabs all round, owns the corner squares.
def tray_side() -> solid {
    body = Rectangle(center=(0, side_h / 2), width=L, height=side_h)
    fb = finger_edge(length=L, thickness=T, finger=F, start="gap", rotation=180 deg, cx=0, cy=0)
    fl = finger_edge(length=side_h, thickness=T, finger=F, start="gap", rotation=90 deg,
                     cx=-L / 2, cy=side_h / 2)
    fr = finger_edge(length=side_h, thickness=T, finger=F, start="gap", rotation=-90 deg,
                     cx=L / 2, cy=side_h / 2)
    hole vent { c = Circle(center=(-140, side_h / 2), diameter=25) }
    vents = LinearPattern(vent, 5, (70, 0))
}

def tray_end(word="COX") -> solid {
    body = Rectangle(center=(0, end_h / 2), width=W, height=end_h)
    fb = finger_edge(length=W, thickness=T, finger=F, start="gap", rotation=180 deg, cx=0, cy=0)
    fl = finger_edge(length=side_h, thickness=T, finger=F, start="tab", rotation=90 deg,
                     cx=-W / 2, cy=side_h / 2)
    fr = finger_edge(length=side_h, thickness=T, finger=F, start="tab", rotation=-90 deg,
                     cx=W / 2, cy=side_h / 2)
    hole hand { s = Slot(center=(0, end_h - 25 - 15), length=100, width=30) }
    drawing name {
        t = Text(word, position=(0, 30), size=14, font="serif:Bold", fill=true)
    }
    Fillet(at=[body.top_left, body.top_right], radius=15)
}

assembly apple_tray {
    solid bottom {
        body = Rectangle(center=(0, 0), width=L, height=W)
        ft = finger_edge(length=L, thickness=T, finger=F, start="tab", cx=0, cy=W / 2)
        fb = finger_edge(length=L, thickness=T, finger=F, start="tab", rotation=180 deg,
                         cx=0, cy=-W / 2)
        fl = finger_edge(length=W, thickness=T, finger=F, start="tab", rotation=90 deg,
                         cx=-L / 2, cy=0)
        fr = finger_edge(length=W, thickness=T, finger=F, start="tab", rotation=-90 deg,
                         cx=L / 2, cy=0)
        hole vent { s = Slot(center=(-127.5, -90), length=60, width=10) }
        vents = GridPattern(vent, 4, 4, (85, 60))
    }
    front = tray_side()
    back = tray_side()
    end_a = tray_end(word="COX")
    end_b = tray_end(word="BRAMLEY")

    # on the sheet
    Below(front, bottom, gap=10)
    AlignLeft(front, bottom)
    Above(back, bottom, gap=10)
    AlignLeft(back, bottom)
    RightOf(end_a, bottom, gap=10)
    AlignTop(end_a, bottom)
    Below(end_b, end_a, gap=10)
    AlignLeft(end_b, end_a)

    # assembled: the bottom on z = 0, x along the tray
    Place(bottom, position=(0, 0, 0), face="up", up="back")
    Place(front, position=(0, -W / 2 + T, 0), face="front", up="up")
    Place(back, position=(0, W / 2 - T, 0), face="back", up="up")
    Place(end_a, position=(-L / 2 + T, 0, 0), face="left", up="up")
    Place(end_b, position=(L / 2 - T, 0, 0), face="right", up="up")

    # the request's numbers
    assert bottom.body.width == 400 mm and bottom.body.height == 300 mm, "400 x 300 outside"
    assert front.body.height == 70 mm and end_a.body.height == 120 mm, "sides 70, ends 120"
    assert len(front.vents) == 5, "5 vent holes a side"
    assert front.vents[1].c.center.x - front.vents[0].c.center.x == 70 mm, "vents 70 apart"
    assert front.vent.c.diameter == 25 mm, "vents 25 across"
    assert len(bottom.vents) == 16, "16 bottom slots"
    assert end_a.body.bb.top - end_a.hand.bb.top == 25 mm, "hand hole 25 below the top"
    assert end_a.hand.bb.width == 100 mm and end_a.hand.bb.height == 30 mm, "hand hole 100 x 30"
    assert end_b.name.bb.top < end_b.hand.bb.bottom - 5 mm, "name under the hand hole"
    assert end_b.name.bb.width < W - 2 * T - 20 mm, "BRAMLEY clear of the joints"
    assert abs(bottom.vents[15].s.center.x + bottom.vents[0].s.center.x -
               2 * bottom.body.center.x) < 0.01 mm, "slots centred along"
}
