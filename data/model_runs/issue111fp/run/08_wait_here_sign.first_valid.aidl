# Request: a counter-top queue sign for the village pharmacy, 6 mm birch ply. Panel 300 wide
# x 220 tall, R12 corners, standing on two feet that cross it in halving joints 100 mm
# either side of the middle: each foot a trapezoid 160 long at the bottom, 60 at the top,
# 40 tall (top corners R5), slotted 20 mm down from the middle of its top; the panel slotted
# 20 mm up from its bottom edge, so its bottom sits flush with the feet's. Slots 6.2 wide.
# On the panel: "PLEASE WAIT" engraved filled, bold, 24 mm tall, centred 170 mm up; "HERE"
# cut clean through as stencil letters, bold, 56 mm tall, centred 95 mm up; an engraved
# filled border 3 mm wide whose outside runs 8 mm in from the top and sides and 26 mm up
# from the bottom (clear of the feet's slots), R6 outside corners.

import "std/joints.aidl"

thickness 6 mm

def foot() -> solid {
    body = Trapezoid(center=(0, 20), bottom_width=160, top_width=60, height=40)
    Fillet([body.top_left, body.top_right], 5)
    slot = cross_halving(depth=20 mm, thickness=6 mm, clearance=0.2 mm, cx=0, cy=40)
}

assembly queue_sign {
    solid panel {
        board = RoundedRectangle(center=(0, 110), width=300, height=220, corner_radius=12)
        slot_l = cross_halving(depth=20 mm, thickness=6 mm, clearance=0.2 mm,
                               rotation=180 deg, cx=-100, cy=0)
        slot_r = cross_halving(depth=20 mm, thickness=6 mm, clearance=0.2 mm,
                               rotation=180 deg, cx=100, cy=0)
        hole here {
            t = Text("HERE", position=(0, 95), size=56, font="sans:Bold", valign="middle",
                     stencil=true)
        }
        drawing face {
            frame = RoundedRectangle(corner=(-142, 26), opposite=(142, 212), corner_radius=6,
                                     construction=true)
            border = Shell(frame, -3, fill=true)
            line1 = Text("PLEASE WAIT", position=(0, 170), size=24, font="sans:Bold",
                         valign="middle", fill=true)
        }
    }
    foot_l = foot()
    foot_r = foot()

    # flat on the sheet: the feet under the panel
    Below(foot_l, panel, gap=8)
    AlignLeft(foot_l, panel)
    RightOf(foot_r, foot_l, gap=8)
    AlignTop(foot_r, foot_l)

    # in 3D: the panel across x at y = 0, the feet along y through its slots
    Place(panel, position=(0, 3, 0), face="front", up="up")
    Place(foot_l, position=(-100 - 3, 0, 0), face="right", up="up")
    Place(foot_r, position=(100 - 3, 0, 0), face="right", up="up")

    # the request's numbers
    assert panel.board.width == 300 mm and panel.board.height == 220 mm, "panel 300 x 220"
    assert panel.slot_r.cut.bb.center_x - panel.slot_l.cut.bb.center_x == 200 mm, "feet 200 apart"
    assert panel.slot_l.depth + foot_l.slot.depth == 40 mm, "halvings add up to the foot's height"
    assert foot_l.body.height == 40 mm and foot_l.body.bottom_width == 160 mm, "foot size"
    assert panel.face.frame.bb.bottom - panel.board.bb.bottom == 26 mm, "border 26 up"
    assert panel.board.bb.top - panel.face.frame.bb.top == 8 mm, "border 8 from the top"
    assert panel.face.frame.bb.bottom >= panel.slot_l.cut.bb.top + 3 mm, "border clear of the slots"
    assert distance(panel.here, panel.face.border) >= 8 mm, "HERE clear of the border"
    assert distance(panel.here, panel.face.line1) >= 8 mm, "HERE clear of PLEASE WAIT"
    assert panel.face.line1.bb.width <= 300 mm - 2 * 8 mm - 2 * 3 mm - 20 mm, "PLEASE WAIT fits"
}
