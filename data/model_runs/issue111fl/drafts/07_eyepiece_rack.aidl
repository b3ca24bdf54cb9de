# Request: a rack for telescope eyepieces on the observing table, 6 mm ply, five parts. Top and
# bottom plates 272 x 140, the top 70 above the table. In the top plate: a back row of three
# 51.5 mm holes for 2-inch barrels (x = -80, 0, 80; 28 behind the centre line) and a front
# row of six 32.5 mm holes for 1.25-inch barrels (x = -100 to 100, 40 apart; 32 in front),
# each labelled with its focal length engraved in front of it (2-inch: 40, 31, 2X; 1.25-inch:
# 32, 25, 17, 12, 9, 6). Two end walls at x = -127 and 127 (centres) and a back wall whose
# back face is 5 mm in from the plates' back edge, all tenoned through both plates (glued);
# the back wall joins the end walls with finger joints at the back corners. The front is
# open. "EYEPIECES" engraved on the right end wall's outer face.

units mm
thickness 6 mm
import "std/joints.aidl"

T = 6 mm
H = 70 mm
PL = 272 mm
PD = 140 mm
EX = 127 mm                      # the end walls' middles
BY = PD / 2 - 5 mm - T / 2       # the back wall's middle
W_FRONT = -63 mm                 # the end walls' front edge
W_BACK = BY + T / 2              # the end walls' back edge, the back wall's back face
W_D = W_BACK - W_FRONT
INNER = 2 * EX - T               # the back wall between the end walls' inner faces

def plate(top=true) -> solid {
    slab = Rectangle(center=(0, 0), width=PL, height=PD)
    back = tab_and_slot(part="slot", length=INNER, thickness=T, tabs=3, tab=40 mm, screw=0,
                        cx=0 mm, cy=BY)
    end_l = tab_and_slot(part="slot", length=W_D, thickness=T, tabs=2, tab=25 mm, screw=0,
                         rotation=90 deg, cx=-EX, cy=W_FRONT + W_D / 2)
    end_r = tab_and_slot(part="slot", length=W_D, thickness=T, tabs=2, tab=25 mm, screw=0,
                         rotation=90 deg, cx=EX, cy=W_FRONT + W_D / 2)
    if top {
        for x in [-80 mm, 0, 80 mm] {
            hole big { c = Circle(center=(x, 28 mm), diameter=51.5 mm) }
        }
        for i in range(6) {
            hole small { c = Circle(center=(-100 mm + i * 40 mm, -32 mm), diameter=32.5 mm) }
        }
        drawing labels {
            BIG = ["40", "31", "2X"]
            SMALL = ["32", "25", "17", "12", "9", "6"]
            for k in range(3) {
                b = Text(BIG[k], position=(-80 mm + k * 80 mm, -8 mm), size=4 mm)
            }
            for k in range(6) {
                s = Text(SMALL[k], position=(-100 mm + k * 40 mm, -60 mm), size=4 mm)
            }
        }
    }
}

# an end wall, drawn on its side: x is the world's y, y is height above the table
def end_wall(title=false) -> solid {
    body = Rectangle(bottom_left=(W_FRONT, 0), width=W_D, height=H)
    low = tab_and_slot(part="tab", length=W_D, thickness=T, tabs=2, tab=25 mm, screw=0,
                       rotation=180 deg, cx=W_FRONT + W_D / 2, cy=0 mm)
    high = tab_and_slot(part="tab", length=W_D, thickness=T, tabs=2, tab=25 mm, screw=0,
                        cx=W_FRONT + W_D / 2, cy=H)
    corner = finger_edge(length=H - 2 * T, thickness=T, finger=10 mm, start="gap",
                         rotation=-90 deg, cx=W_BACK, cy=H / 2)
    if title {
        drawing name { t = Text("EYEPIECES", position=(0, H / 2), size=10 mm, valign="middle") }
    }
}

assembly rack {
    bottom = plate(top=false)
    top = plate(top=true)
    left = end_wall()
    right = end_wall(title=true)

    # drawn facing the front: x along the rack, y height above the table
    solid back {
        body = Polygon([(-INNER / 2, 0), (INNER / 2, 0), (INNER / 2, T), (EX + T / 2, T),
                        (EX + T / 2, H - T), (INNER / 2, H - T), (INNER / 2, H), (-INNER / 2, H),
                        (-INNER / 2, H - T), (-EX - T / 2, H - T), (-EX - T / 2, T), (-INNER / 2, T)])
        low = tab_and_slot(part="tab", length=INNER, thickness=T, tabs=3, tab=40 mm, screw=0,
                           rotation=180 deg, cx=0 mm, cy=0 mm)
        high = tab_and_slot(part="tab", length=INNER, thickness=T, tabs=3, tab=40 mm, screw=0,
                            cx=0 mm, cy=H)
        f_l = finger_edge(length=H - 2 * T, thickness=T, finger=10 mm, start="tab",
                          rotation=90 deg, cx=-EX - T / 2, cy=H / 2)
        f_r = finger_edge(length=H - 2 * T, thickness=T, finger=10 mm, start="tab",
                          rotation=-90 deg, cx=EX + T / 2, cy=H / 2)
    }

    # flat, for cutting
    RightOf(top, bottom, gap=10 mm)
    AlignBottom(top, bottom)
    Above(back, bottom, gap=10 mm)
    AlignLeft(back, bottom)
    Above(left, back, gap=10 mm)
    AlignLeft(left, back)
    RightOf(right, left, gap=10 mm)
    AlignBottom(right, left)

    # assembled
    Place(bottom, position=(0, 0, 0), face="up")
    Place(top, position=(0, 0, H - T), face="up")
    Place(left, position=(-EX - T / 2, 0, 0), face="right", up="up")
    Place(right, position=(EX - T / 2, 0, 0), face="right", up="up")
    Place(back, position=(0, BY + T / 2, 0), face="front", up="up")

    assert top.slab.bb.width == 272 mm and top.slab.bb.height == 140 mm, "plates 272 x 140"
    assert len(top.big) == 3 and top.big[0].c.diameter == 51.5 mm, "three 2-inch holes"
    assert len(top.small) == 6 and top.small[0].c.diameter == 32.5 mm, "six 1.25-inch holes"
    assert top.small[5].c.center.x - top.small[0].c.center.x == 200 mm, "-100 to 100"
    assert left.body.bb.height == 70 mm, "top 70 above the table"
    assert top.slab.bb.top - top.back.slot[0].bb.top == 5 mm, "back face 5 in from the back edge"
    assert top.end_r.slot[0].bb.center_x - top.end_l.slot[0].bb.center_x == 254 mm, "end walls at -127 and 127"
    assert distance(top.big[0].c.center, top.back.slot[0].bb.center) >= 25.75 mm + 3 mm, "2-inch holes clear the back wall"
}
