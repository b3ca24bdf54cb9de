# Crafts: a lucet (a cord-braiding fork, as used for historical lacing and bag cords), cut
# from 6 mm cherry ply. 110 mm long from the handle's end to the horn tips, 60 mm across
# the horn tips. A handle 22 mm wide and 60 mm long with a round end and a 5 mm hanging hole
# 8 mm from the end; a round head 44 mm across on top of it with a 10 mm hole in its centre
# for the finished cord; two horns 10 mm thick rising from the head, spreading to round
# knobs 14 mm across whose tops are the tool's top. Every corner where horns, head and
# handle meet rounded R3. "LUCET" engraved along the handle in 7 mm serif outline letters.

units mm
thickness 6 mm

param length = 110 mm, min = 90 mm, max = 140 mm
param span = 60 mm, min = 50 mm, max = 80 mm
param handle_w = 22 mm, min = 18 mm, max = 28 mm
param handle_l = 60 mm, min = 45 mm, max = 80 mm
param head_d = 44 mm, min = 36 mm, max = 56 mm
param knob_d = 14 mm, min = 10 mm, max = 18 mm
param horn_w = 10 mm, min = 8 mm, max = 12 mm
param cord_d = 10 mm, min = 6 mm, max = 14 mm

solid lucet {
    handle = RoundedRectangle(center=(0, handle_l / 2), width=handle_w, height=handle_l,
                              corner_radius=handle_w / 2)
    head = Circle(center=(0, handle_l + 6 mm), diameter=head_d)
    for s in range(2) {
        horn = Slot(start=((2 * s - 1) * 6, handle_l + 20 mm),
                    end=((2 * s - 1) * (span / 2 - knob_d / 2), length - knob_d / 2), width=horn_w)
        knob = Circle(center=((2 * s - 1) * (span / 2 - knob_d / 2), length - knob_d / 2),
                      diameter=knob_d)
    }
    hole cord {
        c = Circle(center=(0, handle_l + 6 mm), diameter=cord_d)
    }
    hole hang {
        c = Circle(center=(0, 8), diameter=5)
    }
    drawing mark {
        w = Text("LUCET", position=(0, 32), size=7, font="serif", valign="middle",
                 rotation=90 deg)
    }
    # the word centred on the handle between the hanging hole and the head (the hole stays)
    Fixed(hang)
    mark.w.position.y == (hang.bb.top + head.bb.bottom) / 2
    Fillet(3)

    # the request's own numbers
    assert knob[0].bb.top - handle.bb.bottom == 110 mm, "110 mm long"
    assert knob[1].bb.right - knob[0].bb.left == 60 mm, "60 mm across the horn tips"
    assert handle.width == 22 mm and handle.height == 60 mm, "handle 22 x 60"
    assert head.diameter == 44 mm and cord.c.diameter == 10 mm, "44 mm head, 10 mm cord hole"
    assert knob[0].diameter == 14 mm and horn[0].width == 10 mm, "14 mm knobs, 10 mm horns"
    assert hang.c.diameter == 5 mm and hang.c.center.y - handle.bb.bottom == 8 mm, "5 mm hanging hole 8 mm from the end"
    assert mark.w.size == 7 mm, "7 mm letters"
    assert mark.bb.top < head.bb.bottom and mark.bb.bottom > hang.bb.top, "the word on the handle"
}
