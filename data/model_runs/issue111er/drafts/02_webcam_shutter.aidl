# Request: a sliding privacy shutter for a monitor's webcam, glued up from 2 mm black
# acrylic layers, each 50 x 20 with 3 mm corner radii:
# - base (taped to the bezel): a 5 mm lens window centred 9 mm left of and 2 mm below
#   the middle;
# - frame: a 34 x 14 track in the middle;
# - slider: 16 x 13.6, sliding 18 mm in the track (covers the lens at the left end);
# - cover: the same 5 mm lens window, a 3.4 mm wide slot for the knob whose ends'
#   centres are 9 mm either side of the middle, 4 mm above it; "CLOSED" and "OPEN"
#   engraved 2.5 mm high, centred under the slot's left and right ends (baseline 8.5
#   below the middle);
# - knob: a 3 mm disc cut from 4 mm acrylic, glued to the slider's middle through the slot.
# Two M2 screw holes (medium fit) at x = -21 and x = +21 on the centre line hold base,
# frame and cover in register.

units mm
thickness 2 mm
kerf 0.1 mm

import "std/fasteners.aidl"

plate_w = 50 mm
plate_h = 20 mm
lens_x = -9 mm
lens_y = -2 mm
track_w = 34 mm
track_h = 14 mm
slider_w = 16 mm
slider_h = 13.6 mm
slot_y = 4 mm
travel = track_w - slider_w

def layer() -> solid {
    body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=3 mm)
    pin_l = clearance_hole(size=2, cx=-21 mm, cy=0 mm)
    pin_r = clearance_hole(size=2, cx=21 mm, cy=0 mm)
    Fixed(body)
    Fixed(pin_l)
    Fixed(pin_r)
}

assembly shutter {
    solid base {
        plate = layer()
        hole window { c = Circle(center=(lens_x, lens_y), diameter=5 mm) }
        Fixed(window)
    }
    solid frame {
        plate = layer()
        hole track { r = Rectangle(center=(0, 0), width=track_w, height=track_h) }
        Fixed(track)
    }
    solid slider {
        body = Rectangle(center=(0, 0), width=slider_w, height=slider_h)
    }
    solid cover {
        plate = layer()
        hole window { c = Circle(center=(lens_x, lens_y), diameter=5 mm) }
        hole way { s = Slot(start=(-9 mm, slot_y), end=(9 mm, slot_y), width=3.4 mm) }
        Fixed(window)
        Fixed(way)
        drawing marks {
            closed = Text("CLOSED", position=(-9 mm, -8.5 mm), size=2.5 mm)
            open = Text("OPEN", position=(9 mm, -8.5 mm), size=2.5 mm)
        }
        Fixed(marks)
    }
    solid knob {
        thickness 4 mm
        c = Circle(center=(0, 0), diameter=3 mm)
    }

    # flat layout
    RightOf(frame, base, gap=4)
    AlignBottom(frame, base)
    RightOf(cover, frame, gap=4)
    AlignBottom(cover, frame)
    RightOf(slider, cover, gap=4)
    AlignBottom(slider, cover)
    RightOf(knob, slider, gap=4)
    AlignBottom(knob, slider)

    # 3D stack, shutter open (slider at the right end of the track)
    Place(base, position=(0, 0, 0))
    Place(frame, position=(0, 0, 2 mm))
    Place(slider, position=(travel / 2, 0, 2 mm))
    Place(cover, position=(0, 0, 4 mm))
    Place(knob, position=(travel / 2, slot_y, 4 mm))

    # the request's numbers
    assert base.plate.body.width == 50 mm and base.plate.body.height == 20 mm
    assert frame.track.r.width == 34 mm and frame.track.r.height == 14 mm
    assert slider.body.width == 16 mm and slider.body.height == 13.6 mm
    assert travel == 18 mm, "the slider slides 18 mm"
    # closed (slider at the left end, x = -travel / 2): the lens window is covered
    assert -travel / 2 - slider_w / 2 <= lens_x - 2.5 mm and
        -travel / 2 + slider_w / 2 >= lens_x + 2.5 mm and
        slider_h / 2 >= 2 mm + 2.5 mm, "slider covers the lens when closed"
    # open (slider at the right end): the window is clear
    assert travel / 2 - slider_w / 2 >= lens_x + 2.5 mm, "lens clear when open"
    # the knob (at the slider's middle, 4 above) runs the slot's full length
    assert cover.way.s.start.x == -9 mm and cover.way.s.end.x == 9 mm and travel / 2 == 9 mm
    assert cover.way.s.width == 3.4 mm
    assert distance(cover.way, cover.window) >= 1 mm, "slot clear of the lens window"
    assert slot_y + 1.5 mm <= slider_h / 2, "knob on the slider"
    # the M2 holes land in the frame's solid ends, not in the track
    assert frame.plate.pin_r.c.center.x - frame.plate.pin_r.c.radius >= track_w / 2 + 1 mm
    assert abs(frame.plate.pin_l.c.center.x) == 21 mm
}
