# Request: a family birthday board for the hall wall. Backing 400 x 300 mm in 6 mm ply,
# R10 corners, hung on two keyholes (8 mm head) 340 mm apart, 30 mm below the top edge.
# "FAMILY BIRTHDAYS" engraved filled (bold serif, 18 mm capitals), its middle 30 mm below
# the top edge. Under it twelve month boxes in 3 rows x 4 columns, each an engraved
# 85 x 65 mm rounded frame (R4) at 95 x 75 mm pitch, the grid's top edge 60 mm below the
# board's top, with the month (JAN ... DEC, 7 mm strokes) 9 mm below the box's top edge and
# three 2 mm pilot holes for cup hooks 20 mm below the box's top edge, 27 mm apart.
# Five 24 mm round tags in 3 mm ply hang on the hooks, each with a 3 mm hole 8 mm above its
# centre and the name (4.5 mm) and date (3 mm) engraved: MUM 12 MAR, DAD 3 JUL, ELLA 28 NOV,
# SAM 9 FEB, NAN 21 MAR (MUM and NAN share March).

import "std/plates.aidl"

thickness 6 mm

BW = 400 mm
BH = 300 mm
PX = 95 mm
PY = 75 mm
BOXW = 85 mm
BOXH = 65 mm
GRID_TOP = BH / 2 - 60 mm
MONTHS = ["JAN", "FEB", "MAR", "APR", "MAY", "JUN", "JUL", "AUG", "SEP", "OCT", "NOV", "DEC"]
# name, date, month index (0 = JAN), hook (0, 1, 2)
TAGS = [["MUM", "12 MAR", 2, 0], ["DAD", "3 JUL", 6, 1], ["ELLA", "28 NOV", 10, 1],
        ["SAM", "9 FEB", 1, 1], ["NAN", "21 MAR", 2, 2]]

def box_x(m) = ((m % 4) - 1.5) * PX
def box_top(m) = GRID_TOP - (m // 4) * PY
def hook_x(m, k) = box_x(m) + (k - 1) * 27
def hook_y(m) = box_top(m) - 20

def tag(name="", date="") -> solid {
    thickness 3 mm
    disc = Circle(center=(0, 0), diameter=24)
    hole hang {
        c = Circle(center=(0, 8), diameter=3)
    }
    drawing words {
        n = Text(name, position=(0, 0), size=4.5, valign="middle")
        d = Text(date, position=(0, -6), size=3, valign="middle")
    }
}

assembly birthday_board {
    solid backing {
        body = RoundedRectangle(center=(0, 0), width=BW, height=BH, corner_radius=10)
        hang_l = keyhole(head=8 mm, cx=-170 mm, cy=BH / 2 - 30 mm)
        hang_r = keyhole(head=8 mm, cx=170 mm, cy=BH / 2 - 30 mm)
        drawing title {
            t = Text("FAMILY BIRTHDAYS", position=(0, BH / 2 - 30 mm), size=18, font="serif:Bold",
                     valign="middle", fill=true)
        }
        drawing months {
            for m in range(12) {
                frame = RoundedRectangle(center=(box_x(m), box_top(m) - BOXH / 2), width=BOXW,
                                         height=BOXH, corner_radius=4)
                name = Text(MONTHS[m], position=(box_x(m), box_top(m) - 9), size=7, valign="middle")
            }
        }
        hole hooks {
            for m in range(12) {
                for k in range(3) {
                    p = Circle(center=(hook_x(m, k), hook_y(m)), diameter=2)
                }
            }
        }
    }

    for i in range(len(TAGS)) {
        tags = tag(name=TAGS[i][0], date=TAGS[i][1])
        # hung on its hook: the tag's hole on the hook, lying against the board
        Place(tags, on=backing, position=(hook_x(TAGS[i][2], TAGS[i][3]),
                                           hook_y(TAGS[i][2]) - 8))
    }

    # flat on the sheet: the tags in a column right of the board
    RightOf(tags[0], backing, gap=10)
    AlignTop(tags[0], backing)
    for i in range(1, len(TAGS)) {
        Below(tags[i], tags[i - 1], gap=5)
        AlignLeft(tags[i], tags[0])
    }

    Place(backing, position=(0, 0, 0), face="front", up="up")

    assert backing.body.width == 400 mm and backing.body.height == 300 mm, "400 x 300 board"
    assert backing.hang_r.head_hole.center.x - backing.hang_l.head_hole.center.x == 340 mm, "keyholes 340 apart"
    assert backing.body.bb.top - backing.hang_l.head_hole.center.y == 30 mm, "keyholes 30 below the top"
    assert backing.body.bb.top - backing.title.t.position.y == 30 mm, "title 30 below the top"
    assert len(backing.months.frame) == 12, "twelve months"
    assert backing.months.frame[1].center.x - backing.months.frame[0].center.x == 95 mm, "95 pitch"
    assert backing.months.frame[0].center.y - backing.months.frame[4].center.y == 75 mm, "75 pitch"
    assert backing.body.bb.top - backing.months.frame[0].bb.top == 60 mm, "grid 60 below the top"
    assert backing.hooks.p[0][1].center.x - backing.hooks.p[0][0].center.x == 27 mm, "hooks 27 apart"
    assert backing.months.frame[0].bb.top - backing.hooks.p[0][0].center.y == 20 mm, "hooks 20 below the box top"
    assert len(tags) == 5, "five tags"
    assert tags[0].disc.diameter == 24 mm, "24 mm tags"
    assert tags[0].hang.c.center.y - tags[0].disc.center.y == 8 mm, "tag hole 8 above the centre"
    assert backing.title.bb.width <= BW - 2 * 40 mm, "title clear of the keyholes"
    assert distance(backing.title, backing.months) >= 5 mm, "title clear of the month boxes"
}
