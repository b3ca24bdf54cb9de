# REQUEST (04, pets): a platform for a hamster's bin cage. 6 mm unfinished ply (pet-safe).
# A deck 240 x 160 mm, R10 corners, 150 mm above the floor on two end panels, each 160 wide,
# inset 15 mm from the deck's ends (their middle 105 mm from its centre), with an arched door
# 60 mm wide and 75 mm high (a round top) so the hamster can run under, and two glued 12 mm
# tabs up through mortises in the deck. A ramp 360 x 60 mm leans from the floor onto the
# deck's front edge (its top 30 mm past the edge, so no steeper than 30 deg), with grip
# grooves engraved across it every 20 mm, 50 mm long, from 20 mm up to 20 mm short of the
# top. "NIBBLES" engraved on the deck (sans bold, filled, 12 mm) between the mortises.

import "std/joints.aidl"

thickness 6 mm

ply = 6 mm
deck_w = 240 mm
deck_d = 160 mm
high = 150 mm
leg_x = 105 mm
ramp_l = 360 mm
ramp_w = 60 mm
rest = ramp_l - 30 mm           # where the ramp's underside meets the deck's front edge
ramp_angle = asin((high + ply) / rest)

def end_panel() -> solid {
    panel = Rectangle(bottom_left=(-deck_d / 2, 0), width=deck_d, height=high + ply)
    hole door {
        low = Rectangle(bottom_left=(-30, -1), width=60, height=46)
        top = Circle(center=(0, 45), diameter=60)
    }
    joint = tab_and_slot(part="tab", length=deck_d, thickness=ply, tabs=2, tab=12 mm, screw=0,
                         cx=0, cy=high + ply)
    Rigid(self)
}

assembly hamster_platform {
    solid deck {
        board = RoundedRectangle(center=(0, 0), width=deck_w, height=deck_d, corner_radius=10)
        for s in [-1, 1] {
            mortise = tab_and_slot(part="slot", length=deck_d, thickness=ply, tabs=2, tab=12 mm,
                                   screw=0, rotation=90 deg, cx=s * leg_x, cy=0)
        }
        drawing name {
            t = Text("NIBBLES", position=(0, 0), size=12, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }
    left_end = end_panel()
    right_end = end_panel()
    solid ramp {
        plank = Rectangle(bottom_left=(-ramp_w / 2, 0), width=ramp_w, height=ramp_l)
        drawing grip {
            for k in range(17) {
                g = Line((-25, 20 + 20 * k), (25, 20 + 20 * k))
            }
        }
    }

    # 3D: the deck on the end panels, the ramp leaning on the deck's front edge (y = -80)
    Place(deck, position=(0, 0, high), face="up")
    Place(left_end, position=(-leg_x - ply / 2, 0, 0), face="right", up="up")
    Place(right_end, position=(leg_x - ply / 2, 0, 0), face="right", up="up")
    Place(ramp, position=(0, -deck_d / 2 - rest * cos(ramp_angle), 0), rotation=(ramp_angle, 0, 0))

    # flat on the sheet
    RightOf(left_end, deck, gap=8)
    AlignTop(left_end, deck)
    RightOf(right_end, left_end, gap=8)
    AlignTop(right_end, left_end)
    RightOf(ramp, right_end, gap=8)
    AlignTop(ramp, right_end)

    assert deck.board.width == 240 mm and deck.board.height == 160 mm, "deck 240 x 160"
    assert deck.mortise[1].slot[0].bb.center_x - deck.mortise[0].slot[0].bb.center_x == 210 mm,
        "end panels 105 from the centre"
    assert left_end.panel.bb.height - ply == 150 mm, "150 high"
    assert left_end.panel.bb.width == 160 mm, "160 wide"
    assert left_end.door.bb.width == 60 mm, "door 60 wide"
    assert left_end.door.top.top.y - left_end.panel.bb.bottom == 75 mm, "door 75 high"
    assert ramp.plank.height == 360 mm and ramp.plank.width == 60 mm, "ramp 360 x 60"
    assert ramp_angle <= 30 deg, "no steeper than 30 deg"
    assert len(ramp.grip.g) == 17, "grooves every 20 mm"
    assert ramp.grip.g[16].start.y <= ramp.plank.bb.top - 20 mm, "last groove 20 short of the top"
    assert distance(deck.name.t, deck.mortise[0]) >= 5 mm and distance(deck.name.t, deck.mortise[1]) >= 5 mm,
        "name clear of the mortises"
}
