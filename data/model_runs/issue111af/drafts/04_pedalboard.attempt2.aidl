# Request (music): a guitar pedalboard in 6 mm birch ply, four parts, glued:
# - a sloping deck 450 mm wide, as deep as the slope (about 304 mm), R10 corners, with 8 cable
#   and zip-tie slots 80 x 20 mm in 2 rows (y = +-60 from its middle) of 4 (x = -150, -50, 50,
#   150), and "FX BOARD" engraved at the front edge;
# - two wedge sides 300 mm deep, 30 mm high at the front and 80 mm at the back, each with 2 tabs
#   30 mm wide on its sloping top edge into mortises in the deck; the sides' middles 202 mm
#   either side of the deck's middle;
# - a back rail 60 mm high standing 5 mm above the floor between the sides (its middle 13 mm in
#   from the sides' back edge), one 30 mm tenon each end through a mortise in the side; in it a
#   12 mm DC inlet hole and two 9.5 mm jack holes (IN, OUT) with engraved names.

units mm
thickness 6 mm
import "std/joints.aidl"

t = 6 mm
param deck_w = 450 mm, min = 300 mm, max = 800 mm
depth = 300 mm
front_h = 30 mm
back_h = 80 mm
slope = sqrt(depth ** 2 + (back_h - front_h) ** 2)
tilt = atan2(back_h - front_h, depth)
side_x = 202 mm
rail_h = 60 mm
rail_x = depth - 13 mm          # the rail's middle on the side
rail_len = 2 * side_x - t       # between the sides' inner faces
tab_w = 30 mm

def side_panel() -> solid {
    body = Polygon([(0, 0), (depth, 0), (depth, back_h), (0, front_h)])
    top_tabs = tab_and_slot(part="tab", length=slope, thickness=t, tabs=2, tab=tab_w, screw=0,
                            rotation=tilt, cx=depth / 2, cy=(front_h + back_h) / 2)
    rail_m = tab_and_slot(part="slot", length=rail_h, thickness=t, tabs=1, tab=tab_w, screw=0,
                          rotation=90 deg, cx=rail_x, cy=5 mm + rail_h / 2)
}

assembly pedalboard {
    solid deck {
        body = RoundedRectangle(center=(0, 0), width=deck_w, height=slope, corner_radius=10)
        hole cables {
            for r in range(2) {
                for c in range(4) {
                    s = Slot(center=(-150 + c * 100, -60 + r * 120), length=80, width=20)
                }
            }
        }
        left_m = tab_and_slot(part="slot", length=slope, thickness=t, tabs=2, tab=tab_w, screw=0,
                              rotation=90 deg, cx=-side_x, cy=0 mm)
        right_m = tab_and_slot(part="slot", length=slope, thickness=t, tabs=2, tab=tab_w, screw=0,
                               rotation=90 deg, cx=side_x, cy=0 mm)
        drawing name { n = Text("FX BOARD", position=(0, -slope / 2 + 14), size=8, valign="middle") }
        Fixed(body)
    }

    left = side_panel()
    right = side_panel()

    solid rail {
        body = Rectangle(center=(0, 0), width=rail_len + 2 * t, height=rail_h)
        lt = tab_and_slot(part="tab", length=rail_h, thickness=t, tabs=1, tab=tab_w, screw=0,
                          rotation=90 deg, cx=-(rail_len / 2 + t), cy=0 mm)
        rt = tab_and_slot(part="tab", length=rail_h, thickness=t, tabs=1, tab=tab_w, screw=0,
                          rotation=-90 deg, cx=rail_len / 2 + t, cy=0 mm)
        hole sockets {
            dc = Circle(center=(120, 0), diameter=12)
            jack_in = Circle(center=(-120, 0), diameter=9.5)
            jack_out = Circle(center=(-80, 0), diameter=9.5)
        }
        drawing names {
            a = Text("IN", position=(-120, 14), size=5, valign="middle")
            b = Text("OUT", position=(-80, 14), size=5, valign="middle")
            c = Text("DC 9V", position=(120, 14), size=5, valign="middle")
        }
        Fixed(body)
    }

    # laid out flat for cutting
    Below(rail, deck, gap=10)
    AlignCenterX(rail, deck)
    RightOf(left, deck, gap=10)
    AlignTop(left, deck)
    Below(right, left, gap=10)
    AlignLeft(right, left)

    assert deck.body.width == 450 mm, "deck 450 wide"
    assert abs(deck.body.height - 304.14 mm) < 0.01 mm, "deck as deep as the slope"
    assert len(deck.cables.s) == 8, "8 cable slots"
    assert deck.cables.s[0].length == 80 mm and deck.cables.s[0].width == 20 mm, "slots 80 x 20"
    assert left.body.bb.width == 300 mm and left.body.bb.height == 80 mm, "side 300 deep, 80 high"
    assert rail.body.height == 60 mm, "rail 60 high"
    assert rail.body.width == 2 * 202 mm - 6 mm + 2 * 6 mm, "rail spans the sides"
    assert rail.sockets.dc.diameter == 12 mm and rail.sockets.jack_in.diameter == 9.5 mm, "DC 12, jacks 9.5"
}
