# Request (home): a backplate for my wireless doorbell push on a rough brick wall, cut from
# 5 mm acrylic. 70 mm wide, 160 mm tall, a semicircular top (radius 35 mm), the bottom corners
# rounded 4 mm. The button (34 x 84 mm) sticks on with tape, centred across, its bottom 20 mm
# above the plate's bottom: engrave its place as an outline 1 mm bigger all round (36 x 86,
# corner radius 6 mm). The house number "27" engraved filled, bold sans, 24 mm tall, centred
# between the button's outline and the top screw. "PLEASE RING" engraved 5 mm tall under the
# button. Two No. 8 screws (4.5 mm holes, 90 deg countersinks 9 mm across): one 12 mm below
# the top, one hidden behind the button, 40 mm above the bottom.

units mm
thickness 5 mm

param w = 70 mm, min = 60, max = 90
param h = 160 mm, min = 140, max = 200

solid plate {
    lower = RoundedRectangle(bottom_left=(-w / 2, 0), width=w, height=h - w / 2,
                             corner_radii=[0, 0, 4, 4])
    arch = Circle(center=(0, h - w / 2), radius=w / 2)

    hole screws {
        upper = Circle(center=(0, h - 12), diameter=4.5)
        low = Circle(center=(0, 40), diameter=4.5)
    }
    Countersink(screws, diameter=9 mm)

    drawing guide {
        outline = RoundedRectangle(center=(0, 62), width=36, height=86, corner_radius=6)
    }
    drawing number {
        n = Text("27", (0, 126), size=24, font="sans:Bold", fill=true, valign="middle")
    }
    drawing ring {
        t = Text("PLEASE RING", (0, 9.5), size=5, valign="middle")
    }

    AlignCenterX(number, lower)
    AlignCenterX(ring, lower)
    number.bb.center_y == (guide.bb.top + screws.upper.center.y) / 2
    ring.bb.center_y == (lower.bb.bottom + guide.bb.bottom) / 2
}

assert abs(plate.bb.width - 70 mm) < 0.01 mm, "70 mm wide"
assert abs(plate.bb.height - 160 mm) < 0.01 mm, "160 mm tall"
assert abs(plate.arch.radius - 35 mm) < 0.01 mm, "semicircular top, radius 35"
assert abs(plate.guide.bb.width - 36 mm) < 0.01 mm and abs(plate.guide.bb.height - 86 mm) < 0.01 mm,
    "button outline 36 x 86"
assert abs(plate.guide.bb.bottom - plate.bb.bottom - 19 mm) < 0.01 mm, "button bottom 20 mm up, outline 1 mm bigger"
assert abs(plate.bb.top - plate.screws.upper.center.y - 12 mm) < 0.01 mm, "top screw 12 mm below the top"
assert abs(plate.screws.low.center.y - plate.bb.bottom - 40 mm) < 0.01 mm, "low screw 40 mm above the bottom"
assert plate.number.bb.bottom > plate.guide.bb.top + 2 mm, "number clear of the button"
assert plate.number.bb.top < plate.screws.upper.center.y - 4.5 mm - 2 mm, "number clear of the screw head"
assert plate.ring.bb.width < plate.bb.width - 10 mm, "PLEASE RING fits across"
