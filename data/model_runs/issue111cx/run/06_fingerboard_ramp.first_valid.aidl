# Request: a quarter-pipe for fingerboarding (finger skateboards), 3 mm ply.
# - 100 mm wide. Transition radius 80 mm, 80 mm tall, a 50 mm deck on top.
# - Two side cheeks with the quarter-circle profile (5 mm in from the ramp's sides); to
#   avoid a feather edge at the floor, the cheek starts where the curve is 3 mm high.
# - The riding skin: one strip 100 mm wide bent over the cheeks with a living hinge
#   (cuts 15 mm, bridges 3 mm, 2 mm pitch) over the whole curve, with 10 mm flat on the
#   floor in front; its top end stands under the deck's front edge (the coping lip).
# - A back wall 10 mm in from the back, glued into the cheeks with 2 tabs (15 mm) each side.
# - The deck glued onto 2 tabs (12 mm) on each cheek's top, "MINI RAMP" engraved 7 mm high.
import "std/joints.aidl"
import "std/plates.aidl"

thickness 3 mm

t = 3 mm
W = 100 mm
R = 80 mm
H = 80 mm
D = 50 mm
lip = 3 mm
cheek_in = 5 mm
cheek_y = W / 2 - cheek_in             # the cheeks' middles at +/- this
flat = 10 mm
a0 = -asin((R - lip) / R)               # where the cheek's curve starts
x0 = R * cos(a0)
bend_len = 90 deg / 1 rad * (R - t + t / 2)   # the bend's width on the sheet
skin_l = flat + bend_len
wall_x = R + D - 10 mm - t / 2          # the back wall's middle

def cheek() -> solid {
    floor = Line((x0, 0), (R + D, 0))
    back = Line((R + D, 0), (R + D, H + t))
    top = Line((R + D, H + t), (R, H + t))
    riser = Line((R, H + t), (R, H))
    curve = Arc(center=(0, R), radius=R, start_angle=a0, end_angle=0 deg)
    toe = Line((x0, lip), (x0, 0))
    deck_tabs = tab_and_slot(part="tab", length=D, thickness=t, tabs=2, tab=12 mm, screw=0,
                             cx=R + D / 2, cy=H + t)
    wall_slots = tab_and_slot(part="slot", length=H, thickness=t, tabs=2, tab=15 mm, screw=0,
                              rotation=90 deg, cx=wall_x, cy=H / 2)
}

assembly ramp {
    cheek_a = cheek()
    cheek_b = cheek()

    solid skin {
        strip = Rectangle(bottom_left=(0, -W / 2), width=skin_l, height=W)
        hinge = living_hinge(width=bend_len, height=W, pitch=2 mm, cut=15 mm, bridge=3 mm,
                             cx=flat + bend_len / 2, cy=0)
    }

    solid wall {
        # tabs' tips on the cheeks' outer faces
        board = Rectangle(bottom_left=(-(cheek_y + t / 2), 0), width=2 * cheek_y + t, height=H)
        left_tabs = tab_and_slot(part="tab", length=H, thickness=t, tabs=2, tab=15 mm, screw=0,
                                 rotation=90 deg, cx=-(cheek_y + t / 2), cy=H / 2)
        right_tabs = tab_and_slot(part="tab", length=H, thickness=t, tabs=2, tab=15 mm, screw=0,
                                  rotation=-90 deg, cx=cheek_y + t / 2, cy=H / 2)
    }

    solid deck {
        board = Rectangle(bottom_left=(-t, -W / 2), width=D + t, height=W)
        for s in [-1, 1] {
            cheek_slots = tab_and_slot(part="slot", length=D, thickness=t, tabs=2, tab=12 mm,
                                       screw=0, cx=D / 2, cy=s * cheek_y)
        }
        drawing name {
            word = Text("MINI RAMP", position=((D - t) / 2, 0), size=7, rotation=90 deg,
                        valign="middle")
        }
    }

    # flat on the sheet
    RightOf(cheek_b, cheek_a, gap=8)
    AlignBottom(cheek_b, cheek_a)
    Below(skin, cheek_a, gap=8)
    AlignLeft(skin, cheek_a)
    RightOf(wall, skin, gap=8)
    AlignTop(wall, skin)
    RightOf(deck, wall, gap=8)
    AlignTop(deck, wall)

    # 3D: x from the ramp's foot to its back, y across, z up
    Place(cheek_a, position=(0, -cheek_y + t / 2, 0), face="front", up="up")
    Place(cheek_b, position=(0, cheek_y + t / 2, 0), face="front", up="up")
    Place(skin, position=(-flat, 0, 0), face="up")
    Bend(skin, at=flat + bend_len / 2, angle=90 deg, radius=R - t)
    Place(wall, position=(wall_x - t / 2, 0, 0), face="right", up="up")
    Place(deck, position=(R, 0, H), face="up")

    # the request's numbers
    assert cheek_a.curve.radius == 80 mm, "transition radius 80"
    assert cheek_a.riser.end.y == 80 mm, "80 mm tall"
    assert cheek_a.top.start.x - cheek_a.top.end.x == 50 mm, "50 mm deck"
    assert skin.strip.height == 100 mm and deck.board.height == 100 mm, "100 mm wide"
    assert cheek_a.toe.start.y == 3 mm, "cheek starts where the curve is 3 mm high"
    assert W / 2 - (deck.cheek_slots[1].slot[0].bb.center_y) == 5 mm, "cheeks 5 mm in"
    assert R + D - (wall_x + t / 2) == 10 mm, "back wall 10 mm in from the back"
}
