# Request: a table-saw spline jig in 6 mm MDF, for cutting key slots across the
# corners of mitred picture frames and small boxes. The work sits corner-down in a
# 90-degree V cradle (each side at 45 degrees) and the jig rides along the rip fence.
# - Two support boards 342 x 110 form the V. Their top faces are the work surface;
#   the V's apex (of the work surface) is 40 mm above the saw table, and each board's
#   lower edge stops 10 mm (along the flank) short of the apex, leaving the blade a gap.
# - Two end plates 326 wide x 160 tall, with the V notch cut in their top edge. Each
#   board rests in a 110 wide, 6 deep recess on a flank and is locked by 3 tabs 15 wide
#   standing up from the flank through mortises in the board. The end plates stand
#   15 mm in from the board ends (their outer faces 15 mm from each board end).
# - A fence plate 360 x 220 that rides the fence; each end plate joins it by 2 tabs
#   30 wide through mortises, tabs flush with its outer face. A hand hole 110 x 32
#   centred 30 mm below its top edge.
# - "45° SPLINE JIG" engraved 8 mm high on the end plates under the apex.
# Kerf 0.15 mm. Glued joints (no screws).

units mm
t = 6 mm
thickness t
kerf 0.15 mm

import "std/joints.aidl"

apex = 40 mm          # work-surface apex above the table
plate_h = 160 mm      # end plate height
board_w = 110 mm      # support board width (along the flank)
blade_gap = 10 mm     # apex to each board's lower edge, along the flank
span = 300 mm         # between the end plates' inner faces
overhang = 15 mm      # board end past the end plate's outer face
board_l = span + 2 * t + 2 * overhang
fence_l = 360 mm
fence_h = 220 mm
r2 = sqrt(2)

# where the board's middle (along the flank) is, measured along the flank from the apex
mid_s = blade_gap + board_w / 2

def end_plate() -> solid {
    # V notch: apex at (0, apex), flanks at 45 deg up to the top edge
    outline = Polygon([(-160 - t, 0), (160, 0), (160, plate_h), (plate_h - apex, plate_h),
                       (0, apex), (-(plate_h - apex), plate_h), (-160 - t, plate_h)])
    # 3 tabs on each flank, standing up through the board (tips on the work surface)
    right_tabs = tab_and_slot(part="tab", length=board_w, thickness=t, tabs=3, tab=15 mm,
                              screw=0, rotation=45 deg, cx=mid_s / r2, cy=apex + mid_s / r2)
    left_tabs = tab_and_slot(part="tab", length=board_w, thickness=t, tabs=3, tab=15 mm,
                             screw=0, rotation=-45 deg, cx=-mid_s / r2, cy=apex + mid_s / r2)
    # 2 tabs on the left edge into the fence plate
    fence_tabs = tab_and_slot(part="tab", length=plate_h, thickness=t, tabs=2, tab=30 mm,
                              screw=0, rotation=90 deg, cx=-160 - t, cy=plate_h / 2)
    drawing label {
        words = Text("45° SPLINE JIG", position=(0, 18), size=8)
    }
    assert len(right_tabs.gap) == 4, "3 tabs on the flank"
}

def board() -> solid {
    body = Rectangle(center=(0, board_w / 2), width=board_l, height=board_w)
    # the end plates' flank tabs come up through these (end plate middle: span/2 + t/2)
    near = tab_and_slot(part="slot", length=board_w, thickness=t, tabs=3, tab=15 mm,
                        screw=0, rotation=90 deg, cx=-(span / 2 + t / 2), cy=board_w / 2)
    far = tab_and_slot(part="slot", length=board_w, thickness=t, tabs=3, tab=15 mm,
                       screw=0, rotation=90 deg, cx=span / 2 + t / 2, cy=board_w / 2)
}

def fence_plate() -> solid {
    body = Rectangle(center=(0, fence_h / 2), width=fence_l, height=fence_h)
    near = tab_and_slot(part="slot", length=plate_h, thickness=t, tabs=2, tab=30 mm,
                        screw=0, rotation=90 deg, cx=-(span / 2 + t / 2), cy=plate_h / 2)
    far = tab_and_slot(part="slot", length=plate_h, thickness=t, tabs=2, tab=30 mm,
                       screw=0, rotation=90 deg, cx=span / 2 + t / 2, cy=plate_h / 2)
    hole grip {
        s = Slot(center=(0, fence_h - 30 mm), length=110 mm, width=32 mm)
    }
}

assembly spline_jig {
    end_a = end_plate()
    end_b = end_plate()
    board_r = board()
    board_l2 = board()
    fence = fence_plate()

    # flat layout for cutting
    RightOf(end_b, end_a, gap=10)
    AlignBottom(end_b, end_a)
    Above(board_r, end_a, gap=10)
    AlignLeft(board_r, end_a)
    Above(board_l2, board_r, gap=10)
    AlignLeft(board_l2, board_r)
    RightOf(fence, board_r, gap=10)
    AlignBottom(fence, board_r)

    # 3D: x along the fence, y across (fence side -y), z up
    Place(end_a, position=(-(span / 2 + t), 0, 0), face="right", up="up")
    Place(end_b, position=(span / 2, 0, 0), face="right", up="up")
    # boards: top face on the work surface of each flank
    Place(board_r, position=(0, (blade_gap + t) / r2, apex + (blade_gap - t) / r2),
          rotation=(45 deg, 0, 0))
    Place(board_l2, position=(0, -(blade_gap + t) / r2, apex + (blade_gap - t) / r2),
          rotation=(45 deg, 0, 180 deg))
    Place(fence, position=(0, -160 - t, 0), face="back", up="up")

    # the request's numbers
    assert board_r.body.width == 342 mm and board_r.body.height == 110 mm
    assert end_a.outline.bb.width == 326 mm and end_a.outline.bb.height == 160 mm
    assert fence.body.width == 360 mm and fence.body.height == 220 mm
    assert fence.body.bb.top - fence.grip.s.center.y == 30 mm, "hand hole 30 below the top"
    assert fence.grip.s.length == 110 mm and fence.grip.s.width == 32 mm
    assert len(board_r.near.slot) == 3 and len(fence.far.slot) == 2, "3 tabs per board end, 2 per fence joint"
    assert board_r.far.slot[2].bb.right <= board_r.body.bb.right - overhang, "end plate 15 in from the board end"
    assert board_r.body.bb.right - (board_r.far.slot[0].bb.center_x + t / 2) == 15 mm,
        "outer face of the end plate 15 mm from the board end"
}
