# Request (holidays): a flat-pack kinara (Kwanzaa candle holder) from 3 mm birch ply. A top
# board 360 x 60 mm with 6 mm rounded corners holds seven brass candle cups in seven 22 mm
# holes in a row, 48 mm apart, centred. It rests on a front and a back panel, each 360 mm long
# and 90 mm tall, standing 6 mm in from the board's long edges and glued into it with three
# 20 mm tabs. Each panel's bottom edge is cut into a shallow arch 240 mm wide and 30 mm high
# in the middle, leaving two feet. The front panel is engraved "KWANZAA" in filled bold
# letters 14 mm tall (baseline 55 mm above the bottom), and under each candle the name of its
# principle (UMOJA, KUJICHAGULIA, UJIMA, UJAMAA, NIA, KUUMBA, IMANI) 4 mm tall, baseline
# 44 mm above the bottom, each at most 44 mm wide.

units mm
thickness 3 mm

import "std/joints.aidl"

param pitch = 48 mm, min = 40 mm, max = 50 mm
param cup_d = 22 mm, min = 18 mm, max = 26 mm

t = 3 mm
length = 360 mm
panel_h = 90 mm
panel_y = 30 mm - 6 mm - t / 2      # each panel's middle from the board's centre line
principles = ["UMOJA", "KUJICHAGULIA", "UJIMA", "UJAMAA", "NIA", "KUUMBA", "IMANI"]

def candle_x(i) = (i - 3) * pitch

def panel() -> solid {
    l1 = Line((-length / 2, 0), (-120, 0))
    # counter-clockwise: from the right foot over the top to the left foot
    arch = Arc(start=(120, 0), through=(0, 30), end=(-120, 0))
    l2 = Line((120, 0), (length / 2, 0))
    l3 = Line((length / 2, 0), (length / 2, panel_h))
    l4 = Line((length / 2, panel_h), (-length / 2, panel_h))
    l5 = Line((-length / 2, panel_h), (-length / 2, 0))
    tabs = tab_and_slot(part="tab", length=length, thickness=t, tabs=3, tab=20 mm, screw=0,
                        cx=0 mm, cy=panel_h)
    assert arch.through.y - l1.start.y == 30 mm, "arch 30 mm high"
    assert arch.start.x - arch.end.x == 240 mm, "arch 240 mm wide"
}

assembly kinara {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=length, height=60, corner_radius=6)
        for i in range(7) {
            hole cup { c = Circle(center=(candle_x(i), 0), diameter=cup_d) }
        }
        front_slots = tab_and_slot(part="slot", length=length, thickness=t, tabs=3, tab=20 mm,
                                   screw=0, cx=0 mm, cy=-panel_y)
        back_slots = tab_and_slot(part="slot", length=length, thickness=t, tabs=3, tab=20 mm,
                                  screw=0, cx=0 mm, cy=panel_y)
        Fixed(body)
        assert len(cup) == 7
        assert cup[1].c.center.x - cup[0].c.center.x == 48 mm
        assert abs(cup[3].c.center.x - body.bb.center_x) < 0.001 mm, "row centred"
        assert front_slots.bb.bottom - body.bb.bottom == 6 mm, "front panel 6 mm in"
        assert body.bb.top - back_slots.bb.top == 6 mm, "back panel 6 mm in"
    }
    front = panel()
    back = panel()

    drawing words {
        title = Text("KWANZAA", position=(0, 55), size=14, font="sans:Bold", fill=true)
        for i in range(7) {
            p = Text(principles[i], position=(candle_x(i), 44), size=4, max_width=44 mm)
        }
    }
    CutInto(words, front)
    words.title.position.x == front.bb.center_x
    words.title.position.y == front.bb.bottom + 55 mm

    # flat for cutting
    Below(front, board, gap=6)
    Below(back, front, gap=6)
    AlignCenterX(front, board)
    AlignCenterX(back, board)

    # assembled: the panels stand under the board, their tabs through its slots
    Place(board, position=(0, 0, panel_h - t))
    Place(front, position=(0, -panel_y + t / 2, 0), rotation=(90 deg, 0, 0))
    Place(back, position=(0, panel_y + t / 2, 0), rotation=(90 deg, 0, 0))

    assert words.p[1].position.y - front.bb.bottom == 44 mm
    assert abs(words.p[6].position.x - (board.cup[6].c.center.x - board.bb.center_x +
        front.bb.center_x)) < 0.001 mm, "each name under its candle"
    assert front.bb.width == 360 mm and front.bb.height == 90 mm
}
