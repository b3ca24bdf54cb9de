# Request (office): a counter-top leaflet stand for DL leaflets (99 x 210 mm), 3 mm plywood,
# two pockets one behind and above the other. Inside width 110 mm, each pocket 25 mm deep.
# Front pocket: a front lip 60 mm high standing on the counter, its floor 10 mm above the
# counter. Back pocket: its front board (also the back of the front pocket) 150 mm high, its
# floor 90 mm above the counter. A back board 240 mm high. Two side panels 69 mm deep hold
# everything on glued tenons in mortises (no screws), 5 mm of side in front of the lip and
# behind the back; the sides' front edge 65 high, then a straight slope to the top 240 at
# 50 mm back; their outer corners rounded R3. "TAKE ONE" engraved filled (sans bold, 12 mm)
# in the middle of the front lip.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm          # the plywood
e = 5 mm          # side material in front of the lip and behind the back
p = 25 mm         # pocket depth inside
w_in = 110 mm     # inside width
f1 = 10 mm        # front pocket floor above the counter
f2 = 90 mm        # back pocket floor above the counter
depth = 2 * e + 3 * t + 2 * p

# a board between the sides: tenons on both ends, drawn with its bottom edge on y = 0
def board(h=60 mm, n=2, tw=15 mm) -> solid {
    body = Rectangle(center=(0, h / 2), width=w_in + 2 * t, height=h)
    jl = tab_and_slot(part="tab", length=h, thickness=t, tabs=n, tab=tw, screw=0,
                      rotation=90 deg, cx=-(w_in / 2 + t), cy=h / 2)
    jr = tab_and_slot(part="tab", length=h, thickness=t, tabs=n, tab=tw, screw=0,
                      rotation=-90 deg, cx=w_in / 2 + t, cy=h / 2)
}

# a side: x runs from the front (0) to the back, y up from the counter
def side() -> solid {
    body = Polygon([(0, 0), (depth, 0), (depth, 240), (50, 240), (0, 65)])
    Fillet(body, 3 mm)
    m1 = tab_and_slot(part="slot", length=60 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                      rotation=90 deg, cx=e + t / 2, cy=30 mm)
    m2 = tab_and_slot(part="slot", length=p, thickness=t, tabs=1, tab=12 mm, screw=0,
                      rotation=0 deg, cx=e + t + p / 2, cy=f1 + t / 2)
    m3 = tab_and_slot(part="slot", length=150 mm, thickness=t, tabs=3, tab=20 mm, screw=0,
                      rotation=90 deg, cx=e + t + p + t / 2, cy=75 mm)
    m4 = tab_and_slot(part="slot", length=p, thickness=t, tabs=1, tab=12 mm, screw=0,
                      rotation=0 deg, cx=e + 2 * t + p + p / 2, cy=f2 + t / 2)
    m5 = tab_and_slot(part="slot", length=240 mm, thickness=t, tabs=3, tab=25 mm, screw=0,
                      rotation=90 deg, cx=e + 2 * t + 2 * p + t / 2, cy=120 mm)
}

assembly stand {
    lip = board(h=60 mm, n=2, tw=15 mm)
    floor1 = board(h=p, n=1, tw=12 mm)
    riser = board(h=150 mm, n=3, tw=20 mm)
    floor2 = board(h=p, n=1, tw=12 mm)
    back = board(h=240 mm, n=3, tw=25 mm)
    left = side()
    right = side()

    drawing label {
        t1 = Text("TAKE ONE", position=(0, 0), size=12, font="sans:Bold", valign="middle",
                  fill=true)
    }
    AlignCenterX(label, lip.body)
    label.t1.position.y == lip.body.bb.center_y
    CutInto(label, lip)

    # laid out flat for cutting
    Above(floor1, lip, gap=5)
    AlignCenterX(floor1, lip)
    Above(riser, floor1, gap=5)
    AlignCenterX(riser, lip)
    Above(floor2, riser, gap=5)
    AlignCenterX(floor2, lip)
    RightOf(back, lip, gap=5)
    AlignBottom(back, lip)
    RightOf(left, back, gap=5)
    AlignBottom(left, lip)
    RightOf(right, left, gap=5)
    AlignBottom(right, lip)

    # assembled: x across, y from the front to the back, z up
    Place(lip, position=(0, e + t, 0), face="front", up="up")
    Place(floor1, position=(0, e + t, f1), face="up", up="back")
    Place(riser, position=(0, e + 2 * t + p, 0), face="front", up="up")
    Place(floor2, position=(0, e + 2 * t + p, f2), face="up", up="back")
    Place(back, position=(0, e + 3 * t + 2 * p, 0), face="front", up="up")
    Place(right, position=(w_in / 2, 0, 0), face="right", up="up")
    Place(left, position=(-w_in / 2 - t, 0, 0), face="right", up="up")

    # the request's numbers
    assert lip.body.bb.width - 2 * 3 mm == 110 mm, "inside width 110"
    assert lip.body.bb.width - 2 * 3 mm >= 99 mm + 5 mm, "a DL leaflet fits across"
    assert floor1.body.bb.height == 25 mm and floor2.body.bb.height == 25 mm, "pockets 25 deep"
    assert lip.body.bb.height == 60 mm, "front lip 60 high"
    assert riser.body.bb.height == 150 mm, "back pocket's front 150 high"
    assert back.body.bb.height == 240 mm, "back 240 high"
    assert left.body.bb.width == 69 mm and left.body.bb.height == 240 mm, "sides 69 deep, 240 high"
    assert f1 == 10 mm and f2 == 90 mm, "floors 10 and 90 above the counter"
    assert label.bb.width <= lip.body.bb.width - 2 * 3 mm - 10 mm, "label clear of the tenons"
}
