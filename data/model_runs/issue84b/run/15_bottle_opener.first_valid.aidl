# Bottle opener the size of a credit card (85.6 x 54 mm, 3 mm corner radius),
# cut from 2 mm steel: a cap window 30 x 12 mm with 3 mm round corners, 10 mm
# below the top edge, centred; an 8 mm keyring hole in the bottom right corner
# 8 mm from both edges; "CHEERS" engraved 8 mm high at the bottom left.

thickness 2 mm

solid opener {
    card = RoundedRectangle(center=(0, 0), width=85.6, height=54, corner_radius=3)
    hole window {
        w = RoundedRectangle(center=(0, 27 - 10 - 6), width=30, height=12, corner_radius=3)
    }
    hole ring { c = Circle(center=(42.8 - 8, -27 + 8), diameter=8) }
    drawing label {
        t = Text("CHEERS", (-42.8 + 8, -27 + 8), size=8, anchor="start", valign="middle")
    }
}
