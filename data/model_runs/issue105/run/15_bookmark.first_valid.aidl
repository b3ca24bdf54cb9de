# Bookmark: 45 mm wide x 160 mm tall, 5 mm corner radius; a 5 mm tassel hole 10 mm
# below the top edge, centred; a heart-ish leaf cut-out window in the upper third
# (a teardrop 20 mm wide, drawn at full size and scaled to 80 %), centred 45 mm below
# the top; the word "READ" engraved 8 mm tall, rotated to read along the length,
# centred in the lower half.
param w = 45 mm, min = 35 mm, max = 60 mm
param h = 160 mm, min = 120 mm, max = 200 mm

solid bookmark {
    body = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=5)
    hole tassel { c = Circle(center=(0, 70), diameter=5) }
    At(tassel.c.center, body.top.midpoint, dy=-10)

    hole leaf {
        drop = Hull(Circle(center=(0, 30), radius=10), Circle(center=(0, 45), radius=2))
    }
    Scale(leaf, 0.8)
    AlignCenterX(leaf, body)
    leaf.bb.center_y == body.bb.top - 45

    drawing word {
        t = Text("READ", position=(0, -40), size=8, valign="middle", rotation=90)
    }
    AlignCenterX(word, body)
    word.bb.center_y == body.bb.bottom + h / 4
}
