# Figure of docs/language.md: a plate with a Star hole and an ArcSlot hole.
# Drawn by `python docs/make_pictures.py` to docs/images/star_arcslot.png.

solid plate {
    body = Rectangle(center=(0, 0), width=80, height=50)
    hole star { s = Star(center=(-20, 0), points=5, outer_radius=12, inner_radius=5) }
    hole slot { a = ArcSlot(center=(15, -5), radius=15, start_angle=20 deg, end_angle=160 deg, width=5) }
}
