# Request (workshop): a tall resaw fence for my bandsaw, cut from 9 mm birch ply.
# - Face 400 mm long x 160 mm high, standing on the table; its bottom edge finger-jointed
#   (40 mm fingers) to the front edge of a base 400 x 110 mm that lies behind it.
# - Three right-triangle gussets behind the face, 90 mm along the base x 140 mm up the face,
#   one in the middle and one 160 mm each side of it; each has one 40 mm glued tenon into a
#   mortise in the base and one into a mortise in the face.
# - Two 8.5 mm x 50 mm slots through the base, 80 mm each side of the middle, for the M8
#   T-bolts that clamp it in the table's mitre slot.
# - Two 90 x 28 mm hand holes in the face, 80 mm each side of the middle, their centres 120 mm
#   above the table.
# - "RESAW" engraved on the back of the face, 12 mm letters. Every part fits my 600 x 400 bed.

import "std/joints.aidl"

t = 9 mm
thickness t

# gusset drawn with the table at y = 0 and the face's front at x = 0: the tenon strips are
# the 9 mm along each leg; the corner where face and base meet is notched away
def gusset() -> solid {
    body = Polygon([(9, 0), (99, 0), (99, 9), (9, 149), (0, 149), (0, 9), (9, 9)])
    foot = tab_and_slot(part="tab", length=90 mm, thickness=t, tabs=1, tab=40 mm, screw=0,
                        rotation=180 deg, cx=54 mm, cy=0 mm)
    back = tab_and_slot(part="tab", length=140 mm, thickness=t, tabs=1, tab=40 mm, screw=0,
                        rotation=90 deg, cx=0 mm, cy=79 mm)
}

assembly fence {
    # the face, drawn with the table at y = -80
    solid face {
        body = Rectangle(center=(0, 0), width=400, height=160)
        fingers = finger_edge(length=400 mm, thickness=t, finger=40 mm, start="tab",
                              rotation=180 deg, cx=0 mm, cy=-80 mm)
        for i in range(3) {
            m = tab_and_slot(part="slot", length=140 mm, thickness=t, tabs=1, tab=40 mm,
                             screw=0, rotation=90 deg, cx=(i - 1) * 160 mm, cy=-1 mm)
        }
        hole hands {
            for i in range(2) {
                h = Slot(center=((2 * i - 1) * 80, 40), length=90, width=28)
            }
        }
        drawing label {
            word = Text("RESAW", position=(80, -30), size=12, valign="middle")
        }
    }

    # the base, its front edge at y = -55
    solid base {
        body = Rectangle(center=(0, 0), width=400, height=110)
        fingers = finger_edge(length=400 mm, thickness=t, finger=40 mm, start="gap",
                              rotation=180 deg, cx=0 mm, cy=-55 mm)
        for i in range(3) {
            m = tab_and_slot(part="slot", length=90 mm, thickness=t, tabs=1, tab=40 mm,
                             screw=0, rotation=90 deg, cx=(i - 1) * 160 mm, cy=-1 mm)
        }
        hole bolts {
            for i in range(2) {
                s = Slot(center=((2 * i - 1) * 80, 20), length=50, width=8.5, rotation=90)
            }
        }
    }

    for i in range(3) {
        g = gusset()
        Place(g, position=((i - 1) * 160 mm - t / 2, -55 mm, 0 mm), face="right", up="up")
    }

    Place(base, position=(0, 0, 0))
    Place(face, position=(0, -55 mm, 80 mm), face="back", up="up")

    # flat layout for cutting
    Above(base, face, gap=10 mm)
    AlignLeft(base, face)
    RightOf(g[0], face, gap=10 mm)
    AlignBottom(g[0], face)
    RightOf(g[1], g[0], gap=10 mm)
    AlignBottom(g[1], face)
    AlignLeft(g[2], g[0])
    Above(g[2], g[0], gap=10 mm)

    # the request's numbers
    assert face.body.width == 400 mm and face.body.height == 160 mm, "face 400 x 160"
    assert base.body.width == 400 mm and base.body.height == 110 mm, "base 400 x 110"
    assert len(g) == 3, "three gussets"
    assert g[0].bb.width == 90 mm + t and g[0].bb.height == 140 mm + t,
        "gusset legs 90 along the base, 140 up the face (plus the tenon strips)"
    assert face.m[2].slot[0].bb.center_x - face.m[1].slot[0].bb.center_x == 160 mm,
        "gussets 160 mm apart"
    assert base.m[1].slot[0].bb.center_x - base.m[0].slot[0].bb.center_x == 160 mm,
        "gussets 160 mm apart on the base"
    assert face.m[0].slot[0].bb.height == 40 mm and base.m[0].slot[0].bb.height == 40 mm,
        "40 mm mortises"
    # the tenons meet their mortises
    assert abs((g[0].back.gap[0].bb.center_y + g[0].back.gap[1].bb.center_y) / 2 - g[0].bb.bottom
               - (face.m[0].slot[0].bb.center_y - face.body.bb.bottom)) < 0.01 mm,
        "face tenon at its mortise's height"
    assert abs((g[0].foot.gap[0].bb.center_x + g[0].foot.gap[1].bb.center_x) / 2 - g[0].bb.left
               - (base.m[0].slot[0].bb.center_y - base.body.bb.bottom)) < 0.01 mm,
        "foot tenon at its mortise's depth"
    assert base.bolts.s[1].center.x - base.bolts.s[0].center.x == 160 mm, "bolt slots 80 each side"
    assert base.bolts.s[0].width == 8.5 mm and base.bolts.s[0].length == 50 mm, "8.5 x 50 slots"
    assert face.hands.h[1].center.x - face.hands.h[0].center.x == 160 mm, "hand holes 80 each side"
    assert face.hands.h[0].center.y - face.body.bb.bottom == 120 mm, "hand holes 120 above the table"
    assert face.hands.h[0].length == 90 mm and face.hands.h[0].width == 28 mm, "90 x 28 hand holes"
    assert face.bb.width <= 600 mm and face.bb.height <= 400 mm, "face fits the bed"
    assert base.bb.width <= 600 mm and base.bb.height <= 400 mm, "base fits the bed"
}
