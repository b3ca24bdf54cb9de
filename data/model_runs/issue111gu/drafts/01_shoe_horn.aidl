# Request: a long-handled shoe horn for my dad, who can't bend down any more. 3 mm birch ply,
# 420 mm long overall. The spoon at the bottom is 70 mm wide with a round toe and narrows
# in a straight taper to the 32 mm handle 150 mm up from the toe; the handle ends in a
# 40 mm round knob with a 10 mm hanging hole, its centre 20 mm below the top. A living
# hinge 40 mm wide x 80 mm tall in the spoon (cuts running lengthwise), its bottom 22 mm
# above the toe, lets the spoon curl round the heel. "DAD" engraved filled, 12 mm high,
# along the handle reading from the spoon up, centred 280 mm above the toe.

units mm
thickness 3 mm
import "std/plates.aidl"

param length = 420 mm, min = 350 mm, max = 500 mm
spoon_w = 70 mm
handle_w = 32 mm
knob_d = 40 mm
taper_end = 150 mm

solid shoe_horn {
    spoon = Hull(Circle(center=(0, spoon_w / 2), radius=spoon_w / 2),
                 Point(handle_w / 2, taper_end), Point(-handle_w / 2, taper_end))
    handle = Rectangle(bottom_left=(-handle_w / 2, taper_end - 10),
                       width=handle_w, height=length - knob_d / 2 - taper_end + 10)
    knob = Circle(center=(0, length - knob_d / 2), diameter=knob_d)
    hole hang {
        c = Circle(center=(0, length - 20), diameter=10)
    }
    hinge = living_hinge(width=40, height=80, cx=0, cy=22 + 40)
    drawing name {
        t = Text("DAD", position=(0, 280), size=12, rotation=90, font="sans:Bold",
                 valign="middle", fill=true)
    }
    Fillet(6)

    assert knob.top.y - spoon.bb.bottom == 420 mm, "420 mm overall"
    assert spoon.bb.width == 70 mm, "spoon 70 mm wide"
    assert handle.width == 32 mm, "handle 32 mm wide"
    assert knob.diameter == 40 mm and hang.c.diameter == 10 mm, "knob 40, hole 10"
    assert knob.top.y - hang.c.center.y == 20 mm, "hole centre 20 mm below the top"
    assert hinge.bb.bottom - spoon.bb.bottom >= 21 mm, "hinge starts 22 mm above the toe"
    assert hinge.bb.top - hinge.bb.bottom <= 80 mm, "hinge 80 mm tall"
    assert name.t.position.y - spoon.bb.bottom == 280 mm, "name centred 280 mm up"
    assert distance(name, hang) >= 5 mm, "name clear of the hanging hole"
}
