# Request: a birthday present for a coffee-loving friend: an AeroPress caddy in 6 mm
# oak ply. A deck and a base, both 260 x 110 mm with 8 mm corners, joined by two end
# panels 45 mm tall between them (sides 110 mm in from the middle, so the deck
# overhangs them), each end panel with two 25 mm tenons up through the deck and two
# down into the base, and a 50 x 20 mm oval window. In the deck: a 66 mm hole for the
# AeroPress standing on its plunger (centre 72 mm left of the middle), a 60 mm hole
# for the funnel (at the middle), a 66 x 12 mm slot for the filter papers standing on
# edge (centre 50 mm right), a 30 x 45 mm scoop pocket with 6 mm corners (centre 88
# mm right, 15 mm to the front) and an 8 mm wide, 30 mm long slot for the paddle
# (centre 88 mm right, 30 mm to the back). Engraved along the front margin, centred,
# 9 mm from the front edge: "GOOD MORNING, SAM" (filled sans bold, 7 mm capitals).

units mm
thickness 6 mm
import "std/joints.aidl"

T = 6 mm
L = 260 mm
D = 110 mm
SIDE_H = 45 mm
SIDE_X = 110 mm    # inner face of each end panel from the middle

def end_panel() -> solid {
    body = Rectangle(bottom_left=(-D / 2, -T), width=D, height=SIDE_H + 2 * T)
    top_tenons = tab_and_slot(part="tab", length=D, thickness=T, tabs=2, tab=25 mm, screw=0,
                              cx=0 mm, cy=SIDE_H + T)
    bottom_tenons = tab_and_slot(part="tab", length=D, thickness=T, tabs=2, tab=25 mm, screw=0,
                                 rotation=180 deg, cx=0 mm, cy=-T)
    hole window { e = Ellipse(center=(0, SIDE_H / 2), rx=25, ry=10) }
}

def board() -> solid {
    body = RoundedRectangle(center=(0, 0), width=L, height=D, corner_radius=8)
    left_mortises = tab_and_slot(part="slot", length=D, thickness=T, tabs=2, tab=25 mm, screw=0,
                                 rotation=90 deg, cx=-(SIDE_X + T / 2), cy=0 mm)
    right_mortises = tab_and_slot(part="slot", length=D, thickness=T, tabs=2, tab=25 mm, screw=0,
                                  rotation=90 deg, cx=SIDE_X + T / 2, cy=0 mm)
}

assembly aeropress_caddy {
    base = board()
    deck = board()
    hole press { c = Circle(center=(-72, 0), diameter=66) }
    hole funnel { c = Circle(center=(0, 0), diameter=60) }
    hole filters { r = Rectangle(center=(50, 0), width=12, height=66) }
    hole scoop { r = RoundedRectangle(center=(88, -15), width=30, height=45, corner_radius=6) }
    hole paddle { s = Slot(center=(88, 30), length=30, width=8) }
    drawing greeting {
        t = Text("GOOD MORNING, SAM", position=(0, 0), size=7, font="sans:Bold", valign="middle",
                 fill=true)
    }
    At(press.c.center, deck.body.center, dx=-72 mm)
    At(funnel.c.center, deck.body.center)
    At(filters.r.center, deck.body.center, dx=50 mm)
    At(scoop.r.center, deck.body.center, dx=88 mm, dy=-15 mm)
    At(paddle.s.center, deck.body.center, dx=88 mm, dy=30 mm)
    At(greeting.t.position, deck.body.center, dy=-D / 2 + 9 mm)
    CutInto(press, deck)
    CutInto(funnel, deck)
    CutInto(filters, deck)
    CutInto(scoop, deck)
    CutInto(paddle, deck)
    CutInto(greeting, deck)

    left_end = end_panel()
    right_end = end_panel()

    # flat layout
    Above(deck, base, gap=8)
    AlignLeft(deck, base)
    Above(left_end, deck, gap=8)
    AlignLeft(left_end, base)
    RightOf(right_end, left_end, gap=8)
    AlignBottom(right_end, left_end)

    # 3D: x along the caddy, y to the back, z up
    Place(base, position=(0, 0, 0), face="up")
    Place(deck, position=(0, 0, T + SIDE_H), face="up")
    Place(right_end, position=(SIDE_X, 0, T), face="right", up="up")
    Place(left_end, position=(-SIDE_X, 0, T), face="left", up="up")

    assert deck.body.width == 260 mm and deck.body.height == 110 mm, "260 x 110"
    assert left_end.body.height - 2 * T == 45 mm, "45 mm between deck and base"
    assert press.c.diameter == 66 mm and funnel.c.diameter == 60 mm, "66 and 60 mm holes"
    assert press.c.center.x - deck.body.center.x == -72 mm, "press 72 left"
    assert filters.r.width == 12 mm and filters.r.height == 66 mm, "filter slot 66 x 12"
    assert scoop.r.width == 30 mm and scoop.r.height == 45 mm, "scoop 30 x 45"
    assert paddle.s.length == 30 mm and paddle.s.width == 8 mm, "paddle 30 x 8"
    assert distance(greeting, press) >= 2 mm and distance(greeting, funnel) >= 2 mm, "greeting clear"
    assert distance(scoop, paddle) >= 5 mm, "scoop and paddle apart"
    assert distance(press, deck.left_mortises) >= 3 mm, "press hole clear of the mortises"
}
