# A spray-paint stencil: HELLO cut out of a 200 x 70 mm sheet, the letters'
# islands (the O's middle) held by bridges so nothing falls out.
units mm

solid stencil {
    sheet = RoundedRectangle(center=(0, 0), width=200, height=70, corner_radius=5)
    hole letters {
        word = Text("HELLO", position=(0, 0), size=36, valign="middle", stencil=true)
    }
    hole hang { c = Circle(center=(-90, 26), radius=3) }
}
