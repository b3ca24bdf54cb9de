# Request (music): a table-top rack that hangs a one-octave set of eight children's handbells
# (bells up to 60 mm across and 70 mm tall) by their necks, cut from 6 mm ply.
# - top board 574 x 80 mm, corners rounded 5 mm; eight U-notches 16 mm wide and 35 mm deep
#   cut from the front edge, 68 mm apart and centred along the board; behind each notch its
#   note, C D E F G A B C, engraved in filled bold serif letters 12 mm tall.
# - two end frames, trapezoids 100 mm wide at the foot and 60 mm at the top, 120 mm tall
#   up to the board's underside, each with a 30 mm round hole centred 75 mm up; two 20 mm
#   tabs on each frame's top go through slots in the board (0.1 mm oversize). The frames'
#   mid-planes stand 275 mm either side of the board's centre, centred front to back.
# - a stretcher 574 x 40 mm standing on the table under the middle of the frames, joined to
#   each frame by a cross-halving 20 mm into each piece (0.1 mm clearance).
# The bells must clear the frames and the stretcher.

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
bells = 8
pitch = 68 mm
board_l = 574 mm
board_d = 80 mm
frame_x = 275 mm
frame_h = 120 mm
notes = ["C", "D", "E", "F", "G", "A", "B", "C"]

def end_frame() -> solid {
    # the trapezoid reaches the tabs' tips (120 mm + the board's 6 mm)
    body = Trapezoid(center=(0, (frame_h + t) / 2), bottom_width=100, top_width=60,
                     height=frame_h + t)
    tabs = tab_and_slot(part="tab", length=60, thickness=t, tabs=2, tab=20, screw=0,
                        rotation=0 deg, cx=0, cy=frame_h + t)
    hole lightening {
        c = Circle(center=(0, 75), diameter=30)
    }
    halving = cross_halving(depth=20, thickness=t, clearance=0.1, rotation=180 deg, cx=0, cy=0)
    assert body.bb.height - t == 120 mm, "120 mm up to the board's underside"
    assert lightening.c.center.y - body.bb.bottom == 75 mm, "hole 75 mm up"
}

assembly handbell_rack {
    solid board {
        top = RoundedRectangle(center=(0, 0), width=board_l, height=board_d, corner_radius=5)
        hole notch {
            neck = Rectangle(corner=(-pitch * (bells - 1) / 2 - 8, -board_d / 2 - 1),
                             opposite=(-pitch * (bells - 1) / 2 + 8, -board_d / 2 + 35 - 8))
            tip = Circle(center=(-pitch * (bells - 1) / 2, -board_d / 2 + 35 - 8), diameter=16)
        }
        notches = LinearPattern(notch, bells, (pitch, 0))
        drawing names {
            for i in range(bells) {
                n = Text(notes[i], position=(-pitch * (bells - 1) / 2 + i * pitch, 18), size=12,
                         font="serif:Bold", valign="middle", fill=true)
            }
        }
        left_slots = tab_and_slot(part="slot", length=60, thickness=t, tabs=2, tab=20, screw=0,
                                  clearance=0.1, rotation=90 deg, cx=-frame_x, cy=0)
        right_slots = tab_and_slot(part="slot", length=60, thickness=t, tabs=2, tab=20,
                                   screw=0, clearance=0.1, rotation=90 deg, cx=frame_x, cy=0)

        assert top.width == 574 mm and top.height == 80 mm, "574 x 80 board"
        assert len(notches) == 8, "eight bells"
        assert notches[1].tip.center.x - notches[0].tip.center.x == 68 mm, "68 mm apart"
        assert (notches[0].tip.center.x + notches[7].tip.center.x) / 2 == top.center.x,
            "centred along the board"
        assert notches[0].tip.bb.top - top.bb.bottom == 35 mm, "notches 35 mm deep"
        assert notches[0].tip.diameter == 16 mm, "notches 16 mm wide"
        assert right_slots.slot[0].center.x - top.center.x == 275 mm, "frames 275 mm out"
        assert distance(names, notch) >= 3 mm, "notes clear the notches"
        assert names.n[0].size == 12 mm
        # a 60 mm bell hanging at a notch's tip clears the frames' inner faces
        assert (frame_x - t / 2) - (notches[7].tip.center.x + 30 mm) >= 2 mm, "bells clear"
    }

    left_frame = end_frame()
    right_frame = end_frame()

    solid stretcher {
        bar = Rectangle(center=(0, 20), width=board_l, height=40)
        left_halving = cross_halving(depth=20, thickness=t, clearance=0.1, cx=-frame_x, cy=40)
        right_halving = cross_halving(depth=20, thickness=t, clearance=0.1, cx=frame_x, cy=40)
        assert bar.height == 40 mm and bar.width == 574 mm
        # bells hang 70 mm below the board's underside, 120 mm up: they clear its top
        assert frame_h - 70 mm - bar.height >= 5 mm, "the bells clear the stretcher"
    }

    Below(stretcher, board, gap=10)
    AlignLeft(stretcher, board)
    Below(left_frame, stretcher, gap=10)
    AlignLeft(left_frame, stretcher)
    RightOf(right_frame, left_frame, gap=10)
    AlignBottom(right_frame, left_frame)
}
