# Request (garden / indoor seedlings): "A stand that hangs my 560 mm LED grow-light bar over
# two seed trays on the potting bench. Two end frames, 300 mm wide and 380 mm tall, from 6 mm
# ply, each an arch: a 220 mm wide window open at the bottom with 30 mm rounded top corners, so
# the legs are 40 mm wide. A 640 mm x 70 mm beam drops into cross-halving slots in the frames'
# tops (frames 600 mm apart, centre to centre), flush on top. Two 6 mm holes in the beam,
# 500 mm apart, for the light's hanging cords. Engrave a height scale on each frame's left
# leg: a tick every 50 mm from 50 to 300 mm above the bench, numbered."

import "std/joints.aidl"

thickness 6 mm

param frame_w = 300 mm, min = 250 mm, max = 400 mm
param frame_h = 380 mm, min = 300 mm, max = 500 mm
param beam_len = 640 mm, min = 560 mm, max = 800 mm
param beam_h = 70 mm, min = 50 mm, max = 100 mm
param spacing = 600 mm, min = 500 mm, max = 760 mm
param window_w = 220 mm, min = 160 mm, max = 260 mm
param cord_pitch = 500 mm, min = 300 mm, max = 560 mm

def end_frame() -> solid {
    body = Rectangle(center=(0, 0), width=frame_w, height=frame_h)
    hole window {
        w = RoundedRectangle(center=(0, -frame_h / 2 + 300 mm - 155 mm), width=window_w,
                             height=310 mm, corner_radii=[30 mm, 30 mm, 0, 0])
    }
    # the beam drops in from the top: a slot half the beam's height deep
    top_slot = cross_halving(depth=beam_h / 2, thickness=6 mm, cx=0 mm, cy=frame_h / 2)
    drawing scale {
        for i in range(6) {
            tick = Line((-frame_w / 2, -frame_h / 2 + (i + 1) * 50 mm),
                        (-frame_w / 2 + 10 mm, -frame_h / 2 + (i + 1) * 50 mm))
            num = Text(str((i + 1) * 50), position=(-frame_w / 2 + 22 mm,
                       -frame_h / 2 + (i + 1) * 50 mm), size=5, valign="middle")
        }
    }
}

assembly grow_light_stand {
    left_frame = end_frame()
    right_frame = end_frame()

    solid beam {
        bar = Rectangle(center=(0, 0), width=beam_len, height=beam_h)
        # slots from the bottom edge, up into the beam, over each frame
        left_slot = cross_halving(depth=beam_h / 2, thickness=6 mm, rotation=180 deg,
                                  cx=-spacing / 2, cy=-beam_h / 2)
        right_slot = cross_halving(depth=beam_h / 2, thickness=6 mm, rotation=180 deg,
                                   cx=spacing / 2, cy=-beam_h / 2)
        hole cords {
            a = Circle(center=(-cord_pitch / 2, 12 mm), diameter=6 mm)
            b = Circle(center=(cord_pitch / 2, 12 mm), diameter=6 mm)
        }
    }

    # flat layout for cutting: frames side by side, the beam above them
    RightOf(right_frame, left_frame, gap=10 mm)
    AlignBottom(right_frame, left_frame)
    Above(beam, left_frame, gap=10 mm)
    AlignLeft(beam, left_frame)

    # assembled: frames stand facing +x, 600 mm apart; the beam across their tops
    Place(left_frame, position=(-spacing / 2 - 3 mm, 0, frame_h / 2), face="right", up="up")
    Place(right_frame, position=(spacing / 2 - 3 mm, 0, frame_h / 2), face="right", up="up")
    Place(beam, position=(0, 3 mm, frame_h - beam_h / 2), face="front", up="up")

    assert left_frame.body.bb.width == 300 mm, "frames 300 mm wide"
    assert left_frame.body.bb.height == 380 mm, "frames 380 mm tall"
    assert beam.bar.bb.width == 640 mm, "beam 640 mm long"
    assert beam.bar.bb.height == 70 mm, "beam 70 mm tall"
    assert left_frame.window.bb.width == 220 mm, "window 220 mm wide"
    assert (frame_w - window_w) / 2 == 40 mm, "legs 40 mm wide"
    assert left_frame.top_slot.depth + beam.left_slot.depth == 70 mm, "halvings add up to the beam: flush on top"
    assert beam.right_slot.cut.bb.center_x - beam.left_slot.cut.bb.center_x == 600 mm, "frames 600 mm apart"
    assert beam.cords.b.center.x - beam.cords.a.center.x == 500 mm, "cord holes 500 mm apart"
    assert len(left_frame.scale.tick) == 6, "ticks at 50 ... 300 mm"
}
