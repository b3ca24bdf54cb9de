# Request (electronics): a sloped-front desktop case for a small Arduino synth, 3 mm ply.
# Outside 200 mm wide, 160 mm deep; the back is 60 mm tall and the front 25 mm, with a
# sloping top panel between them. Two identical side profiles; the bottom, front, back and
# top panels have tabs through mortises in the sides, glued, except the bottom, which is
# held by M3 screws and captive nuts so it comes off for service.
# Top panel: a 16x2 LCD window 71.2 x 24.2 mm with four M3 holes on 75 x 31 mm centres,
# four pots (7.2 mm holes, 40 mm apart) labelled VOL, CUT, RES, RATE, four 12.5 mm push
# buttons labelled 1-4 under them, a 6.5 mm toggle hole labelled POWER, and the title
# "MINI SYNTH" engraved filled.
# Back panel: an 11.2 mm DC jack hole (9V), a 12.5 x 11.5 mm USB-B cut-out, and two MIDI DIN
# sockets (15.5 mm hole, two M3 holes 22.6 mm apart), labelled. Front panel: a 6.2 mm
# headphone jack labelled PHONES. Bottom: five 60 x 5 mm vent slots.

units mm
thickness 3 mm
import "std/joints.aidl"

# FIX after the first valid program: W0530 x 8 was right: with the panels flush to the sides'
# edges every mortise was an open notch and the bottom's screw holes broke out of the edge.
# The box now stands M = 3 mm inside the side profiles, so each mortise is closed.
T = 3 mm
M = 3 mm         # material left round the mortises
W = 200 mm       # outside width
D = 160 mm       # outside depth
HB = 60 mm       # back height
HF = 25 mm       # front height
a = atan((HB - HF) / D)                 # slope of the top
L = sqrt(D ** 2 + (HB - HF) ** 2)       # the slope's length
LT = (D - 2 * M) / cos(a) - T * tan(a)          # top panel: front face to the back panel's face
HFP = HF + M * tan(a) - (M + T) / cos(a) - (M + T)           # front panel height
HBP = HF + (D - M - T) * tan(a) - (M + T) / cos(a) - (M + T)   # back panel height
Y0 = HF + M * tan(a) - M / cos(a)       # height of the top panel's front outer corner (at x = M)

def side() -> solid {
    body = Polygon([(0, 0), (D, 0), (D, HB), (0, HF)])
    bot = tab_and_slot(part="slot", length=D - 2 * M, thickness=T, tabs=3, tab=15 mm, screw=3,
                       rotation=0, cx=D / 2, cy=M + T / 2)
    fr = tab_and_slot(part="slot", length=HFP, thickness=T, tabs=1, tab=8 mm, screw=0,
                      rotation=90 deg, cx=M + T / 2, cy=M + T + HFP / 2)
    bk = tab_and_slot(part="slot", length=HBP, thickness=T, tabs=2, tab=10 mm, screw=0,
                      rotation=90 deg, cx=D - M - T / 2, cy=M + T + HBP / 2)
    tp = tab_and_slot(part="slot", length=LT, thickness=T, tabs=3, tab=15 mm, screw=0,
                      rotation=a, cx=M + cos(a) * LT / 2 + sin(a) * T / 2,
                      cy=Y0 + sin(a) * LT / 2 - cos(a) * T / 2)
}

# a panel between the sides: tabs on its left and right edges
def panel(h=50 mm, tabs=2, tab=10 mm, screw=0) -> solid {
    body = Rectangle(center=(0, 0), width=W, height=h)
    jl = tab_and_slot(part="tab", length=h, thickness=T, tabs=tabs, tab=tab, screw=screw,
                      rotation=90 deg, cx=-W / 2, cy=0)
    jr = tab_and_slot(part="tab", length=h, thickness=T, tabs=tabs, tab=tab, screw=screw,
                      rotation=-90 deg, cx=W / 2, cy=0)
}

assembly console {
    left = side()
    right = side()

    bottom = panel(h=D - 2 * M, tabs=3, tab=15 mm, screw=3)
    hole vents {
        v = Slot(center=(0, -40), length=60, width=5, rotation=0)
    }
    vent_row = LinearPattern(vents, 5, (0, 20))
    AlignCenterX(vents, bottom.body)
    vents.v.center.y == bottom.body.center.y - 40 mm
    CutInto(vents, bottom)

    front = panel(h=HFP, tabs=1, tab=8 mm)
    hole phones { c = Circle(center=(70, 0), diameter=6.2) }
    drawing front_label { t = Text("PHONES", position=(62, 0), size=4, anchor="end", valign="middle") }
    Rigid(phones, front_label)
    CutInto(phones, front)
    CutInto(front_label, front)
    phones.c.center.x == front.body.center.x + 70 mm
    AlignCenterY(phones, front.body)

    back = panel(h=HBP, tabs=2, tab=10 mm)
    hole back_holes {
        dc = Circle(center=(-70, -2), diameter=11.2)
        usb = Rectangle(center=(-40, -2), width=12.5, height=11.5)
        for k in range(2) {
            din = Circle(center=(10 + 45 * k, -2), diameter=15.5)
            m_l = Circle(center=(10 + 45 * k - 11.3, -2), diameter=3.4)
            m_r = Circle(center=(10 + 45 * k + 11.3, -2), diameter=3.4)
        }
    }
    drawing back_labels {
        l_dc = Text("9V", position=(-70, 14), size=4, valign="middle")
        l_usb = Text("USB", position=(-40, 14), size=4, valign="middle")
        l_in = Text("MIDI IN", position=(10, 14), size=4, valign="middle")
        l_out = Text("MIDI OUT", position=(55, 14), size=4, valign="middle")
    }
    Rigid(back_holes, back_labels)
    back_holes.dc.center.x == back.body.center.x - 70 mm
    back_holes.dc.center.y == back.body.center.y - 2 mm
    CutInto(back_holes, back)
    CutInto(back_labels, back)

    top = panel(h=LT, tabs=3, tab=15 mm)
    hole controls {
        lcd = Rectangle(center=(-40, 45), width=71.2, height=24.2)
        lcd_m1 = Circle(center=(-40 - 37.5, 45 - 15.5), diameter=3.4)
        lcd_m2 = Circle(center=(-40 + 37.5, 45 - 15.5), diameter=3.4)
        lcd_m3 = Circle(center=(-40 - 37.5, 45 + 15.5), diameter=3.4)
        lcd_m4 = Circle(center=(-40 + 37.5, 45 + 15.5), diameter=3.4)
        for i in range(4) {
            pot = Circle(center=(-60 + 40 * i, 5), diameter=7.2)
            btn = Circle(center=(-60 + 40 * i, -40), diameter=12.5)
        }
        power = Circle(center=(60, 38), diameter=6.5)
    }
    drawing top_labels {
        title = Text("MINI SYNTH", position=(45, 64), size=8, font="sans:Bold", valign="middle",
                     fill=true)
        names = ["VOL", "CUT", "RES", "RATE"]
        for i in range(4) {
            pl = Text(names[i], position=(-60 + 40 * i, -10), size=4, valign="middle")
            bl = Text(str(i + 1), position=(-60 + 40 * i, -56), size=4, valign="middle")
        }
        pw = Text("POWER", position=(60, 28), size=4, valign="middle")
    }
    Rigid(controls, top_labels)
    controls.lcd.center.x == top.body.center.x - 40 mm
    controls.lcd.center.y == top.body.center.y + 45 mm
    CutInto(controls, top)
    CutInto(top_labels, top)

    # flat layout for cutting
    RightOf(right, left, gap=6)
    AlignBottom(right, left)
    Below(bottom, left, gap=6)
    AlignLeft(bottom, left)
    RightOf(top, bottom, gap=6)
    AlignTop(top, bottom)
    Below(back, bottom, gap=6)
    AlignLeft(back, bottom)
    Below(front, back, gap=6)
    AlignLeft(front, back)

    # 3D: x across (left to right), y from the front (0) to the back (D), z up
    Place(left, position=(-W / 2, 0, 0), face="right", up="up")
    Place(right, position=(W / 2 - T, 0, 0), face="right", up="up")
    Place(bottom, position=(0, D / 2, M), face="up", up="back")
    Place(front, position=(0, M + T, M + T + HFP / 2), face="front", up="up")
    Place(back, position=(0, D - M - T, M + T + HBP / 2), face="back", up="up")
    Place(top, position=(0, M + cos(a) * LT / 2 + T * sin(a), Y0 + sin(a) * LT / 2 - T * cos(a)),
          face=(0, -sin(a), cos(a)), up=(0, cos(a), sin(a)))

    # the request's numbers
    assert left.body.bb.width == 160 mm, "160 deep"
    assert left.body.bb.height == 60 mm, "back 60 tall"
    assert bottom.bb.width == 200 mm, "200 wide outside"
    assert top.body.bb.width == 200 mm, "200 wide outside"
    assert controls.pot[1].center.x - controls.pot[0].center.x == 40 mm, "pots 40 apart"
    assert len(controls.pot) == 4 and len(controls.btn) == 4, "four pots, four buttons"
    assert controls.lcd.width == 71.2 mm and controls.lcd.height == 24.2 mm, "LCD window"
    assert controls.lcd_m2.center.x - controls.lcd_m1.center.x == 75 mm, "LCD holes 75 apart"
    assert controls.lcd_m3.center.y - controls.lcd_m1.center.y == 31 mm, "LCD holes 31 apart"
    assert back_holes.m_r[0].center.x - back_holes.m_l[0].center.x == 22.6 mm, "DIN screws 22.6"
    assert len(vent_row) == 5, "five vent slots"
    assert distance(controls, top.jl) >= 2 mm, "controls clear of the left tabs"
    assert distance(controls, top.jr) >= 2 mm, "controls clear of the right tabs"
}
