# Kid's stencil: a 160 x 80 mm sheet, corner radius 6, with the stencil letters "ABC"
# 40 mm tall cut out, centred, and a 6 mm hanging hole 8 mm from the top-left corner.
solid stencil {
    body = RoundedRectangle(center=(0, 0), width=160, height=80, corner_radius=6)
    hole letters {
        t = Text("ABC", position=(0, 0), size=40, valign="middle", stencil=true)
    }
    CenterInside(letters, body)
    hole hang {
        c = Circle(center=(-72, 32), diameter=6)
    }
    At(hang.c.center, body.top_left, dx=8, dy=-8)
}
