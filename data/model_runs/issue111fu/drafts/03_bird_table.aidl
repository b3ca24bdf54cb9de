# Request: a roofed bird table top for a 70 mm garden post, all 6 mm exterior ply.
# - Tray 320 x 260 mm: four 8 mm drain holes 15 mm in from the corners; four 5 mm screw holes
#   on a 50 mm square in the middle (for a post-top bracket), countersunk 10 mm on top.
# - Two gable ends, 240 mm wide, 150 mm tall at the eaves and 270 mm at the apex (a 45 deg
#   roof), standing across the tray with their middles 137 mm either side of the tray's
#   centre, each on two 40 mm tenons through mortises in the tray; a 60 mm round hole in each
#   gable, its centre 150 mm above the tray.
# - Two roof panels 360 mm long on the gables: each slope of each gable has one 40 mm tenon
#   up through a mortise in the roof panel (tenons flush with the roof's top); the roof
#   overhangs the eaves by 25 mm; at the ridge one panel laps over the other's end.
# - "FEED THE BIRDS" fill-engraved on the lapping roof panel, serif, 18 mm letters.

import "std/joints.aidl"

units mm
thickness 6 mm

T = 6 mm
EAVE = 150 mm
APEX = 270 mm
HALF = 120 mm
SLOPE = sqrt(2) * 120 mm        # a slope edge, eave to apex
OVER = 25 mm                    # roof past the eaves
MORT_Y = OVER + SLOPE / 2       # roof mortise centre from the roof's eave edge

def gable() -> solid {
    # y = 0: the shoulder that stands on the tray; the tenon tips reach y = -T
    body = Polygon([(-HALF, -T), (HALF, -T), (HALF, EAVE), (0, APEX), (-HALF, EAVE)])
    feet = tab_and_slot(part="tab", length=2 * HALF, thickness=T, tabs=2, tab=40, screw=0,
                        rotation=180 deg, cx=0, cy=-T)
    left = tab_and_slot(part="tab", length=SLOPE, thickness=T, tabs=1, tab=40, screw=0,
                        rotation=45 deg, cx=-HALF / 2, cy=(EAVE + APEX) / 2)
    right = tab_and_slot(part="tab", length=SLOPE, thickness=T, tabs=1, tab=40, screw=0,
                         rotation=-45 deg, cx=HALF / 2, cy=(EAVE + APEX) / 2)
    hole window {
        c = Circle(center=(0, 150), diameter=60)
    }
    assert body.bb.width == 240 mm, "gable 240 wide"
    assert body.points[2].y == 150 mm and body.points[3].y == 270 mm, "eaves 150, apex 270"
    assert window.c.diameter == 60 mm, "60 mm hole"
}

def roof(width=100 mm) -> solid {
    board = Rectangle(bottom_left=(-180, 0), width=360, height=width)
    m_left = tab_and_slot(part="slot", length=SLOPE, thickness=T, tabs=1, tab=40, screw=0,
                          rotation=90 deg, cx=-137, cy=MORT_Y)
    m_right = tab_and_slot(part="slot", length=SLOPE, thickness=T, tabs=1, tab=40, screw=0,
                           rotation=90 deg, cx=137, cy=MORT_Y)
    assert board.width == 360 mm, "roof 360 long"
}

assembly bird_table {
    solid tray {
        plate = Rectangle(center=(0, 0), width=320, height=260)
        hole drain { c = Circle(center=(0, 0), diameter=8) }
        drains = CornerPattern(drain, plate, inset=15)
        square = Rectangle(center=(0, 0), width=50, height=50, construction=true)
        hole screw { c = Circle(center=(0, 0), diameter=5) }
        screws = CornerPattern(screw, square)
        Countersink(screws, diameter=10)
        m_left = tab_and_slot(part="slot", length=240, thickness=T, tabs=2, tab=40, screw=0,
                              rotation=90 deg, cx=-137, cy=0)
        m_right = tab_and_slot(part="slot", length=240, thickness=T, tabs=2, tab=40, screw=0,
                               rotation=90 deg, cx=137, cy=0)
        Fixed(plate)
        assert plate.width == 320 mm and plate.height == 260 mm, "tray 320 x 260"
        assert len(drains) == 4, "four drains"
        assert drains[0].c.center.x - plate.bb.left == 15 mm, "drains 15 mm in"
        assert drains[0].c.center.y - plate.bb.bottom == 15 mm, "drains 15 mm in"
        assert screws[2].c.center.x - screws[0].c.center.x == 50 mm, "50 mm square"
        assert m_right.slot[0].bb.center_x - plate.center.x == 137 mm, "gable 137 mm from the middle"
    }

    g_left = gable()
    g_right = gable()
    # the ridge: the long panel laps over the short one's end (a thickness shorter)
    long_roof = roof(width=OVER + SLOPE)
    short_roof = roof(width=OVER + SLOPE - T)
    drawing words {
        t = Text("FEED THE BIRDS", position=(0, 0), size=18, font="serif", valign="middle",
                 fill=true)
    }
    CenterInside(words, long_roof.board)
    CutInto(words, long_roof)

    # flat on the sheet
    RightOf(g_left, tray, gap=10)
    AlignBottom(g_left, tray)
    RightOf(g_right, g_left, gap=10)
    AlignBottom(g_right, g_left)
    Above(long_roof, tray, gap=10)
    AlignLeft(long_roof, tray)
    RightOf(short_roof, long_roof, gap=10)
    AlignBottom(short_roof, long_roof)

    # assembled: gables stand on the tray, the roof lies on the slopes
    Place(tray, position=(0, 0, 0))
    Place(g_left, position=(-137 + T / 2, 0, T), face="left", up="up")
    Place(g_right, position=(137 - T / 2, 0, T), face="right", up="up")
    Place(long_roof, position=(0, HALF + OVER / sqrt(2) - T / sqrt(2),
                               T + EAVE - OVER / sqrt(2) - T / sqrt(2)),
          face=(0, 1, 1), up=(0, -1, 1))
    Place(short_roof, position=(0, -(HALF + OVER / sqrt(2) - T / sqrt(2)),
                                T + EAVE - OVER / sqrt(2) - T / sqrt(2)),
          face=(0, -1, 1), up=(0, 1, 1))

    assert long_roof.board.height - OVER == sqrt(2) * 120 mm, "roof reaches the apex"
    assert words.t.size == 18 mm, "18 mm letters"
}
