# Desk nameplate: 150 x 40 mm plate with 8 mm corner radius; the name
# "DR. MARGARET HAMILTON" engraved, at most 130 mm wide, size up to 10 mm, centred.
param width = 150 mm, min = 100 mm, max = 250 mm
solid plate {
    body = RoundedRectangle(center=(0, 0), width=width, height=40, corner_radius=8)
    drawing name {
        t = Text("DR. MARGARET HAMILTON", position=(0, 0), size=10, valign="middle", max_width=width - 20)
    }
    CenterInside(name, body)
}
