# Plant label: a stake 16 mm wide and 100 mm long ending in a 20 mm long point at the
# bottom, under a head 60 mm wide x 24 mm tall with 4 mm rounded corners; the name
# "BASIL" engraved 9 mm tall in the middle of the head.
param name_size = 9 mm, min = 5 mm, max = 14 mm

solid label {
    head = RoundedRectangle(center=(0, 0), width=60, height=24, corner_radius=4)
    stake = Rectangle(center=(0, -60), width=16, height=100)
    point = Triangle(center=(0, -120), base=16, height=20, rotation=180)

    Below(stake, head)
    AlignCenterX(stake, head)
    Below(point, stake)
    AlignCenterX(point, stake)

    drawing name {
        t = Text("BASIL", position=(0, 0), size=name_size, valign="middle")
    }
    CenterInside(name, head)
}
