# Request: a screen-printing frame for A4 prints, in 9 mm birch ply: four bars 40 mm wide
# making a frame 340 x 460 outside (260 x 380 inside: the A4 sheet, 210 x 297, with at least
# 25 mm of ink well all round). The long bars run the full 460; the short bars sit between
# them, each end locked by one flat dovetail 10 mm deep (0.1 mm clearance) and glued. On
# the top face: a centre mark (an 8 mm line) on the inner edge of each bar for registration,
# and "A4" (sans bold, 14 mm, filled) on the top bar. With it a squeegee handle: two plates
# 250 x 70 (R10 corners) that clamp a 250 mm rubber blade along their bottom edge with four
# M4 bolts 12 mm up from that edge (at 33 and 100 mm either side of the middle), and a hand
# slot 100 x 25 through both, 12 mm above the middle.

units mm
thickness 9 mm

import "std/joints.aidl"
import "std/fasteners.aidl"

OUT_W = 340 mm
OUT_H = 460 mm
BAR = 40 mm
DT = 10 mm
IN_X = OUT_W / 2 - BAR          # 130: inner edge of the long bars
IN_Y = OUT_H / 2 - BAR          # 190: inner edge of the short bars
MID_Y = OUT_H / 2 - BAR / 2     # 210: the short bars' centre line

def squeegee_plate() -> solid {
    body = RoundedRectangle(center=(0, 0), width=250, height=70, corner_radius=10)
    hole hand { s = Slot(center=(0, 12), length=100, width=25) }
    for x in [-100 mm, -33 mm, 33 mm, 100 mm] {
        bolt = clearance_hole(size=4, cx=x, cy=-35 + 12)
    }
}

assembly screen_frame {
    solid left_bar {
        body = Rectangle(center=(-(OUT_W / 2 - BAR / 2), 0), width=BAR, height=OUT_H)
        top_socket = dovetail(part="socket", length=BAR, depth=DT, tails=1, clearance=0.1 mm,
                              rotation=90 deg, cx=-IN_X, cy=MID_Y)
        bot_socket = dovetail(part="socket", length=BAR, depth=DT, tails=1, clearance=0.1 mm,
                              rotation=90 deg, cx=-IN_X, cy=-MID_Y)
        drawing mark { m = Line((-IN_X, 0), (-IN_X - 8, 0)) }
    }
    solid right_bar {
        body = Rectangle(center=(OUT_W / 2 - BAR / 2, 0), width=BAR, height=OUT_H)
        top_socket = dovetail(part="socket", length=BAR, depth=DT, tails=1, clearance=0.1 mm,
                              rotation=-90 deg, cx=IN_X, cy=MID_Y)
        bot_socket = dovetail(part="socket", length=BAR, depth=DT, tails=1, clearance=0.1 mm,
                              rotation=-90 deg, cx=IN_X, cy=-MID_Y)
        drawing mark { m = Line((IN_X, 0), (IN_X + 8, 0)) }
    }
    solid top_bar {
        body = Rectangle(center=(0, MID_Y), width=2 * IN_X + 2 * DT, height=BAR)
        left_tail = dovetail(part="tail", length=BAR, depth=DT, tails=1, clearance=0.1 mm,
                             rotation=90 deg, cx=-IN_X, cy=MID_Y)
        right_tail = dovetail(part="tail", length=BAR, depth=DT, tails=1, clearance=0.1 mm,
                              rotation=-90 deg, cx=IN_X, cy=MID_Y)
        drawing mark {
            m = Line((0, IN_Y), (0, IN_Y + 8))
            a4 = Text("A4", position=(0, MID_Y + 4), size=14, font="sans:Bold", valign="middle",
                      fill=true)
        }
    }
    solid bottom_bar {
        body = Rectangle(center=(0, -MID_Y), width=2 * IN_X + 2 * DT, height=BAR)
        left_tail = dovetail(part="tail", length=BAR, depth=DT, tails=1, clearance=0.1 mm,
                             rotation=90 deg, cx=-IN_X, cy=-MID_Y)
        right_tail = dovetail(part="tail", length=BAR, depth=DT, tails=1, clearance=0.1 mm,
                              rotation=-90 deg, cx=IN_X, cy=-MID_Y)
        drawing mark { m = Line((0, -IN_Y), (0, -IN_Y - 8)) }
    }

    blade_a = squeegee_plate()
    blade_b = squeegee_plate()
    blade_a.bb.center == (340, 100)
    blade_b.bb.center == (340, -100)

    assert right_bar.body.bb.right - left_bar.body.bb.left == 340 mm, "340 wide outside"
    assert left_bar.body.bb.height == 460 mm, "460 tall outside"
    assert right_bar.body.bb.left - left_bar.body.bb.right == 260 mm, "260 inside"
    assert top_bar.body.bb.bottom - bottom_bar.body.bb.top == 380 mm, "380 inside"
    assert (260 mm - 210 mm) / 2 >= 25 mm and (380 mm - 297 mm) / 2 >= 25 mm, "25 mm ink well"
    assert blade_a.body.bb.width == 250 mm and blade_a.body.bb.height == 70 mm, "plates 250 x 70"
    assert blade_a.body.bb.width < right_bar.body.bb.left - left_bar.body.bb.right,
        "the squeegee fits inside the frame"
    assert len(blade_a.bolt) == 4, "four M4 bolts"
    assert blade_a.bolt[0].c.center.y - blade_a.body.bb.bottom == 12 mm, "bolts 12 up"
}
