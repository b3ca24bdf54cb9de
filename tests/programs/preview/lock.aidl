# The serve tests' lock: sliding the shackle down over the key hole (shackle_y = 14 mm)
# refills the hole, so the preview must report W0501 after the picture.
units mm
param shackle_y = 30 mm, min=10 mm, max=40 mm
solid lock {
    solid body {
        b = Rectangle(center=(0, 0), width=40, height=30)
        hole key {
            k = Circle(center=(0, 8), radius=3)
        }
    }
    solid shackle {
        s = Rectangle(center=(0, shackle_y), width=30, height=8)
    }
}
