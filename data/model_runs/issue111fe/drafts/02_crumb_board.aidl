# Request (kitchen): a bread board that keeps the crumbs, in 6 mm birch ply (oiled).
# - tray: an open finger-jointed box 380 x 260 x 40 mm outside, 20 mm fingers, "BREAD"
#   engraved filled (16 mm letters) in the middle of the front wall.
# - slatted top: 450 x 260, R12 corners, lying on the tray's walls and overhanging 35 mm at
#   each end, with a 80 x 16 hand-hold slot in the middle of each overhang; 15 crumb slots
#   6 x 190 at 22 mm pitch, centred, let the crumbs through.
# - two locating cleats 300 x 20 standing on edge under the top, each glued with two 30 mm
#   tenons through mortises in the top (0.2 mm clearance), 0.5 mm inside the tray's long walls
#   so the top cannot slide off.

units mm
thickness 6 mm

import "std/joints.aidl"

t = 6 mm
tray_l = 380 mm
tray_d = 260 mm
tray_h = 40 mm
inner_half_d = tray_d / 2 - t        # 124: the long walls' inside faces
cleat_y = inner_half_d - 0.5 mm - t / 2   # the cleats' mid-planes
cleat_l = 300 mm
cleat_h = 20 mm
slots = 15
pitch = 22 mm

def cleat() -> solid {
    body = Rectangle(center=(0, 0), width=300, height=26)
    tenons = tab_and_slot(part="tab", length=300 mm, thickness=6 mm, tabs=2, tab=30 mm,
                          screw=0, cx=0 mm, cy=13 mm)
}

assembly bread_board {
    tray = finger_box(length=tray_l, depth=tray_d, height=tray_h, thickness=t, finger=20 mm,
                      closed=false)
    drawing label {
        word = Text("BREAD", position=(0, 0), size=16, font="sans:Bold", valign="middle",
                    fill=true)
    }
    CenterInside(label, tray.front)
    CutInto(label, tray.front)

    solid top {
        board = RoundedRectangle(center=(0, 0), width=450, height=260, corner_radius=12)
        hole crumbs {
            for i in range(slots) {
                s = Slot(center=((i - (slots - 1) / 2) * pitch, 0), length=190, width=6,
                         rotation=90)
            }
        }
        hole grips {
            left = Slot(center=(-(tray_l / 2 + 35 mm / 2), 0), length=80, width=16,
                        rotation=90)
            right = Slot(center=(tray_l / 2 + 35 mm / 2, 0), length=80, width=16,
                         rotation=90)
        }
        back_mortise = tab_and_slot(part="slot", length=300 mm, thickness=6 mm, tabs=2,
                                    tab=30 mm, screw=0, clearance=0.2 mm, cx=0 mm,
                                    cy=cleat_y)
        front_mortise = tab_and_slot(part="slot", length=300 mm, thickness=6 mm, tabs=2,
                                     tab=30 mm, screw=0, clearance=0.2 mm, cx=0 mm,
                                     cy=-cleat_y)
    }

    back_cleat = cleat()
    front_cleat = cleat()

    # 3D: the top on the walls, the cleats hanging under it, tenons flush with its face
    Place(top, position=(0, 0, tray_h))
    Place(back_cleat, position=(0, cleat_y + t / 2, tray_h + t - 13 mm), face="front",
          up="up")
    Place(front_cleat, position=(0, -cleat_y + t / 2, tray_h + t - 13 mm), face="front",
          up="up")

    # on the sheet: the top right of the tray's net, the cleats under the top
    RightOf(top, tray, gap=10)
    AlignTop(top, tray)
    Below(back_cleat, top, gap=10)
    AlignLeft(back_cleat, top)
    Below(front_cleat, back_cleat, gap=10)
    AlignLeft(front_cleat, top)

    # the request's numbers
    assert tray.front.bb.width == 380 mm, "tray 380 long outside"
    assert tray.left.bb.height == 260 mm, "tray 260 deep outside"
    assert tray.front.bb.height == 40 mm, "tray 40 high"
    assert top.board.bb.width == 450 mm and top.board.bb.height == 260 mm, "top 450 x 260"
    assert (top.board.bb.width - tray_l) / 2 == 35 mm, "35 mm overhang each end"
    assert top.grips.left.center.x - top.board.bb.left == 35 mm / 2, "grip mid-overhang"
    assert top.grips.left.length == 80 mm and top.grips.left.width == 16 mm, "grips 80 x 16"
    assert len(top.crumbs.s) == 15, "15 crumb slots"
    assert top.crumbs.s[1].center.x - top.crumbs.s[0].center.x == 22 mm, "22 mm pitch"
    assert top.crumbs.s[0].length == 190 mm and top.crumbs.s[0].width == 6 mm, "6 x 190"
    assert abs(top.crumbs.s[0].center.x + top.crumbs.s[14].center.x) < 0.001 mm, "centred"
    assert top.crumbs.bb.right < tray_l / 2 - t, "crumbs fall inside the tray"
    assert top.crumbs.bb.top < cleat_y - t / 2 - 2 mm, "crumb slots clear of the cleats"
    assert inner_half_d - (cleat_y + t / 2) == 0.5 mm, "cleats 0.5 inside the walls"
    assert back_cleat.body.bb.width == 300 mm and back_cleat.body.bb.height - t == 20 mm,
        "cleats 300 x 20 below the top"
    assert tray_h - t > cleat_h, "cleats clear of the tray's bottom"
}
