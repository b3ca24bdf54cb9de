# Request: a "four in a row" game for the kids, laser cut. Two 3 mm ply faces 284 x 240 mm
# (10 mm rounded top corners) with 7 columns x 6 rows of 24 mm viewing holes; between them
# 4 mm ply strips make 7 channels 32 mm wide for 30 mm discs of 3 mm acrylic (42 discs, 21 of
# them with an engraved 20 mm ring to tell the players apart). Columns 38 mm apart, rows
# 30 mm apart (the discs stack touching). Under the discs a 4 mm ply release bar 320 x 12 mm
# slides out sideways to empty the board, with an 8 mm pull hole near each end; it runs on
# two 12 x 20 mm blocks at the ends, under two 12 mm end strips. Two 140 x 40 mm feet of 3 mm
# ply with a 10.2 mm wide, 20 mm deep slot hug the frame's bottom at its ends. "CONNECT 4"
# engraved filled in bold sans, 14 mm high, in the front face's top border.

thickness 3 mm

FACE_W = 284 mm
FACE_H = 240 mm
PITCH_X = 38 mm
PITCH_Y = 30 mm
DISC_D = 30 mm
CHANNEL = 32 mm
BAR_TOP = 32 mm        # the discs rest on the release bar's top edge
GAP = 4 mm             # the strips' thickness: the room between the faces

def col_x(c) = -3 * PITCH_X + c * PITCH_X
def row_y(r) = BAR_TOP + DISC_D / 2 + r * PITCH_Y

def face(title=false) -> solid {
    body = RoundedRectangle(bottom_left=(-FACE_W / 2, 0), width=FACE_W, height=FACE_H,
                            corner_radii=[10, 10, 0, 0])
    hole windows {
        for r in range(6) {
            for c in range(7) {
                w = Circle(center=(col_x(c), row_y(r)), diameter=24)
            }
        }
    }
    if title {
        drawing name {
            t = Text("CONNECT 4", position=(0, (row_y(5) + DISC_D / 2 + FACE_H) / 2), size=14,
                     font="sans:Bold", valign="middle", fill=true)
        }
    }
}

# a 4 mm part of the middle layer, drawn where it sits in the frame
def spacer(x, y, w, h) -> solid {
    thickness 4 mm
    r = Rectangle(center=(x, y), width=w, height=h)
}

def disc(marked=false) -> solid {
    c = Circle(center=(0, 0), diameter=DISC_D)
    if marked {
        drawing ring { r = Circle(center=(0, 0), diameter=20) }
    }
}

def foot() -> solid {
    body = RoundedRectangle(center=(0, 0), width=140, height=40, corner_radius=4)
    hole hug { r = Rectangle(bottom_left=(-5.1, 0), width=10.2, height=21) }
}

assembly game {
    front = face(title=true)
    back = face()

    # the middle layer: 6 strips between the channels, 2 end strips, 2 end blocks, the bar
    for k in range(6) {
        strip = spacer(x=col_x(k) + PITCH_X / 2, y=(BAR_TOP + FACE_H) / 2, w=PITCH_X - CHANNEL,
                       h=FACE_H - BAR_TOP)
    }
    left_end = spacer(x=-FACE_W / 2 + 6, y=(BAR_TOP + FACE_H) / 2, w=12, h=FACE_H - BAR_TOP)
    right_end = spacer(x=FACE_W / 2 - 6, y=(BAR_TOP + FACE_H) / 2, w=12, h=FACE_H - BAR_TOP)
    left_block = spacer(x=-FACE_W / 2 + 6, y=10, w=12, h=20)
    right_block = spacer(x=FACE_W / 2 - 6, y=10, w=12, h=20)
    solid bar {
        thickness 4 mm
        r = Rectangle(center=(0, 26), width=320, height=12)
        hole pulls {
            a = Circle(center=(-153, 26), diameter=8)
            b = Circle(center=(153, 26), diameter=8)
        }
    }

    left_foot = foot()
    right_foot = foot()

    # 3D: the board standing up (frame y -> up), front face toward -y
    Place(front, rotation=(90 deg, 0, 0), position=(0, 0, 0))
    Place(back, rotation=(90 deg, 0, 0), position=(0, 3 + GAP, 0))
    for k in range(6) {
        Place(strip[k], rotation=(90 deg, 0, 0), position=(0, GAP, 0))
    }
    Place(left_end, rotation=(90 deg, 0, 0), position=(0, GAP, 0))
    Place(right_end, rotation=(90 deg, 0, 0), position=(0, GAP, 0))
    Place(left_block, rotation=(90 deg, 0, 0), position=(0, GAP, 0))
    Place(right_block, rotation=(90 deg, 0, 0), position=(0, GAP, 0))
    Place(bar, rotation=(90 deg, 0, 0), position=(0, GAP, 0))
    # feet across the frame at the end blocks (x = -136 and 136), the slot's middle on the
    # sandwich's middle (y = 2)
    Place(left_foot, rotation=(90 deg, 0, 90 deg), position=(-FACE_W / 2 + 6 - 1.5, 2, 0))
    Place(right_foot, rotation=(90 deg, 0, 90 deg), position=(FACE_W / 2 - 6 - 1.5, 2, 0))

    # the discs: a full board, alternate players; on the sheet in a grid under the faces
    for r in range(6) {
        for c in range(7) {
            d = disc(marked=(r + c) % 2 == 1)
            Place(d, rotation=(90 deg, 0, 0), position=(col_x(c), 0.5 + 3, row_y(r)))
            d.bb.center_x == -FACE_W / 2 + DISC_D / 2 + c * 34 mm
            d.bb.center_y == -DISC_D / 2 - 10 mm - r * 34 mm
        }
    }

    # on the sheet
    RightOf(back, front, gap=8)
    AlignBottom(back, front)
    RightOf(left_end, back, gap=6)
    AlignBottom(left_end, back)
    RightOf(right_end, left_end, gap=6)
    AlignBottom(right_end, back)
    for k in range(6) {
        if k == 0 {
            RightOf(strip[k], right_end, gap=6)
        } else {
            RightOf(strip[k], strip[k - 1], gap=6)
        }
        AlignBottom(strip[k], back)
    }
    Below(bar, back, gap=10)
    AlignLeft(bar, back)
    Below(left_block, bar, gap=6)
    AlignLeft(left_block, bar)
    RightOf(right_block, left_block, gap=6)
    AlignBottom(right_block, left_block)
    RightOf(left_foot, right_block, gap=6)
    AlignTop(left_foot, left_block)
    RightOf(right_foot, left_foot, gap=6)
    AlignTop(right_foot, left_block)

    # the request's numbers
    assert len(front.windows.w) == 6 and len(front.windows.w[0]) == 7, "7 columns x 6 rows"
    assert len(d) * len(d[0]) == 42, "42 discs"
    assert front.body.bb.width == 284 mm and front.body.bb.height == 240 mm, "faces 284 x 240"
    assert front.windows.w[0][1].center.x - front.windows.w[0][0].center.x == 38 mm, "columns"
    assert front.windows.w[1][0].center.y - front.windows.w[0][0].center.y == 30 mm, "rows"
    assert strip[1].r.bb.left - strip[0].r.bb.right == 32 mm, "channels 32 wide"
    assert strip[0].r.bb.left - left_end.r.bb.right == 32 mm, "end channel 32 wide"
    assert GAP - 3 mm >= 0.5 mm, "3 mm discs run free between the faces"
    assert bar.r.width == 320 mm and bar.r.height == 12 mm, "bar 320 x 12"
    assert left_foot.hug.r.width == 10.2 mm and left_foot.hug.r.height - 1 mm == 20 mm, "feet slot"
}
