# Figure of docs/stdlib.md: a living hinge, a chamfered tag with a keyhole and arched text, a mounting plate and a rounded plate with a slot.
# Drawn by `python docs/make_pictures.py` to docs/images/stdlib_plates.png.
# render: --png-width 560

import "std/plates.aidl"

assembly sheet {
    solid hinge {
        body = Rectangle(center=(0, 0), width=70 mm, height=40 mm)
        Fixed(body)
        cuts = living_hinge(width=24 mm, height=40 mm, pitch=2 mm, cut=15 mm, bridge=3 mm)
        CenterInside(cuts, body)
    }
    solid tag {
        plate = chamfered_plate(width=50 mm, height=40 mm, chamfer=6 mm, cx=70 mm)
        hanger = keyhole(head=8 mm, slot_width=4 mm, length=8 mm, cx=70 mm, cy=-6 mm)
        drawing label {
            name = text_on_arc(text="WORKSHOP", radius=13 mm, size=4 mm, cx=70 mm, cy=-6 mm)
        }
        AlignCenterX(hanger, plate)
    }
    mount = mounting_plate(width=70 mm, height=34 mm, screw=4, inset=6 mm, cy=-50 mm)
    solid rail {
        r = rounded_plate(width=50 mm, height=34 mm, corner_radius=8 mm, cx=70 mm, cy=-50 mm)
        s = slot(length=30 mm, width=6 mm, cx=70 mm, cy=-50 mm)
        CenterInside(s, r)
    }
}
