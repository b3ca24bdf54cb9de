# Request (music): an orchestral slapstick (the "whip") for our school band, from 6 mm
# birch ply. Two boards 320 x 60 mm, the far end's corners R10, hinged at the near end by
# a small strap hinge (two 3.2 mm screw holes in each board, 10 mm from the near end, 30 mm
# apart). On the outside of each board a D handle 120 mm long and 50 mm tall, top corners
# R15, with a finger hole 90 x 22 mm (round ends) 11 mm under its top, glued into the
# board by two 20 mm tabs; the handle runs along the board's middle from 35 mm to 155 mm.
# "SLAPSTICK" filled-engraved on one board's outside, "ST MARY'S BAND" on the other's,
# in the free part beyond the handle.

units mm
thickness 6 mm
import "std/joints.aidl"

t = 6 mm
board_l = 320 mm
board_w = 60 mm
handle_l = 120 mm
handle_h = 50 mm
handle_x = 95 mm      # the handle's middle along the board

def board(word="SLAPSTICK") -> solid {
    # x along the board from the hinged (near) end, y across
    body = RoundedRectangle(center=(board_l / 2, 0), width=board_l, height=board_w,
                            corner_radii=[0, 10, 10, 0])
    hole hinge_a { c = Circle(center=(10, -15), diameter=3.2) }
    hole hinge_b { c = Circle(center=(10, 15), diameter=3.2) }
    mortise = tab_and_slot(part="slot", length=handle_l, thickness=t, tabs=2, tab=20,
                           screw=0, rotation=0, cx=handle_x, cy=0)
    drawing label {
        w = Text(word, position=((handle_x + handle_l / 2 + board_l) / 2, 0), size=12,
                 valign="middle", font="sans:Bold", fill=true, max_width=140)
    }
}

def handle() -> solid {
    # x along the handle from its middle, y up from the board (0: the tabs' tips)
    body = RoundedRectangle(center=(0, handle_h / 2), width=handle_l, height=handle_h,
                            corner_radii=[15, 15, 0, 0])
    tabs = tab_and_slot(part="tab", length=handle_l, thickness=t, tabs=2, tab=20, screw=0,
                        rotation=180, cx=0, cy=0)
    hole grip { s = Slot(center=(0, handle_h - 11 - 11), length=90, width=22) }
}

assembly slapstick {
    board_a = board("SLAPSTICK")
    board_b = board("ST MARY'S BAND")
    handle_a = handle()
    handle_b = handle()

    # flat on the sheet
    Below(board_b, board_a, gap=6)
    AlignLeft(board_b, board_a)
    Below(handle_a, board_b, gap=6)
    AlignLeft(handle_a, board_a)
    RightOf(handle_b, handle_a, gap=6)
    AlignTop(handle_b, handle_a)

    # closed, as played: board_b underneath, board_a on it, a handle on each outside
    Place(board_b, position=(0, 0, t), face="down", up="front")
    Place(board_a, position=(0, 0, t), face="up", up="back")
    Place(handle_a, position=(handle_x, t / 2, t), face="front", up="up")
    Place(handle_b, position=(handle_x, t / 2, t), face="front", up="down")

    # the request's numbers
    assert board_a.body.width == 320 mm and board_a.body.height == 60 mm, "boards 320 x 60"
    assert board_a.hinge_b.c.center.y - board_a.hinge_a.c.center.y == 30 mm, "hinge holes"
    assert board_a.hinge_a.c.center.x - board_a.body.bb.left == 10 mm, "10 from the end"
    assert handle_a.body.width == 120 mm and handle_a.body.height == 50 mm, "handle size"
    assert handle_a.grip.s.length == 90 mm and handle_a.grip.s.width == 22 mm, "finger hole"
    assert handle_a.body.bb.top - handle_a.grip.s.bb.top == 11 mm, "11 under the top"
    assert board_a.mortise.bb.left - board_a.body.bb.left >= 35 mm - 0.5 mm,
        "handle from 35 mm"
    assert handle_x - handle_l / 2 == 35 mm and handle_x + handle_l / 2 == 155 mm,
        "handle from 35 to 155"
}
