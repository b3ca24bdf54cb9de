# Request (pets): a basking platform with a hide under it for a bearded dragon's vivarium,
# 6 mm poplar ply. A 250 x 150 mm deck (10 mm corner radii) with the pet's name "SPIKE"
# engraved filled, 30 mm tall bold, in its middle. It stands 120 mm high (deck underside) on two
# side walls and a back wall; the front is open as the hide's entrance. The walls stand 10 mm
# in from the deck's left, right and back edges (outer faces), so the side walls are 130 mm
# deep and the back wall 230 mm wide; each wall is glued into the deck with three 20 mm tabs
# through slots, and the back wall meets the side walls in finger joints (6 mm material). Each
# side wall has an arched window 60 mm wide and 70 mm tall (round top), 30 mm above the floor.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
DECK_W = 250 mm
DECK_D = 150 mm
H = 120 mm
INSET = 10 mm
SIDE_D = DECK_D - 2 * INSET    # 130: front of the deck inset too, the hide's mouth 10 mm in
BACK_W = DECK_W - 2 * INSET    # 230

def side_wall() -> solid {
    body = Rectangle(bottom_left=(-SIDE_D / 2, 0), width=SIDE_D, height=H + T)
    top_tabs = tab_and_slot(part="tab", length=SIDE_D, thickness=T, tabs=3, tab=20 mm,
                            screw=0, cx=0 mm, cy=H + T)
    back_fingers = finger_edge(length=H, thickness=T, finger=20 mm, start="tab",
                               rotation=-90 deg, cx=SIDE_D / 2, cy=H / 2)
    hole window {
        arch = Hull(Circle(center=(0, 70), radius=30),
                    Rectangle(center=(0, 50), width=60, height=40))
    }
}

assembly vivarium_platform {
    solid deck {
        board = RoundedRectangle(center=(0, 0), width=DECK_W, height=DECK_D, corner_radius=10)
        left_slots = tab_and_slot(part="slot", length=SIDE_D, thickness=T, tabs=3, tab=20 mm,
                                  screw=0, rotation=90 deg, cx=-DECK_W / 2 + INSET + T / 2,
                                  cy=0 mm)
        right_slots = tab_and_slot(part="slot", length=SIDE_D, thickness=T, tabs=3, tab=20 mm,
                                   screw=0, rotation=90 deg, cx=DECK_W / 2 - INSET - T / 2,
                                   cy=0 mm)
        back_slots = tab_and_slot(part="slot", length=BACK_W, thickness=T, tabs=3, tab=20 mm,
                                  screw=0, cx=0 mm, cy=DECK_D / 2 - INSET - T / 2)
        drawing name {
            word = Text("SPIKE", position=(0, 0), size=30, valign="middle", font="sans:Bold",
                        fill=true)
        }
        Fixed(board)
    }

    left = side_wall()
    right = side_wall()

    solid back {
        body = Rectangle(bottom_left=(-BACK_W / 2, 0), width=BACK_W, height=H + T)
        top_tabs = tab_and_slot(part="tab", length=BACK_W, thickness=T, tabs=3, tab=20 mm,
                                screw=0, cx=0 mm, cy=H + T)
        left_fingers = finger_edge(length=H, thickness=T, finger=20 mm, start="gap",
                                   rotation=90 deg, cx=-BACK_W / 2, cy=H / 2)
        right_fingers = finger_edge(length=H, thickness=T, finger=20 mm, start="gap",
                                    rotation=-90 deg, cx=BACK_W / 2, cy=H / 2)
    }

    # flat on the sheet
    Below(back, deck, gap=10)
    AlignCenterX(back, deck)
    Below(left, back, gap=10)
    AlignLeft(left, back)
    RightOf(right, left, gap=10)
    AlignBottom(right, left)

    # in 3D: deck on top, its name up; walls under it, 10 mm in from its edges
    Place(deck, position=(0, 0, H), face="up", up="back")
    Place(left, position=(-DECK_W / 2 + INSET, 0, 0), face="right", up="up")
    Place(right, position=(DECK_W / 2 - INSET - T, 0, 0), face="right", up="up")
    Place(back, position=(0, DECK_D / 2 - INSET, 0), face="front", up="up")

    assert deck.board.bb.width == 250 mm and deck.board.bb.height == 150 mm, "deck 250 x 150"
    assert left.body.bb.height - T == 120 mm, "120 mm under the deck"
    assert deck.board.bb.right - (deck.right_slots.bb.center_x + T / 2) == 10 mm,
        "side walls 10 mm in"
    assert deck.board.bb.top - (deck.back_slots.bb.center_y + T / 2) == 10 mm,
        "back wall 10 mm in"
    assert len(deck.left_slots.slot) == 3 and len(back.top_tabs.gap) == 4, "three tabs a wall"
    assert left.window.bb.width == 60 mm and left.window.bb.height == 70 mm, "window 60 x 70"
    assert left.window.bb.bottom - left.body.bb.bottom == 30 mm, "window 30 mm up"
}
