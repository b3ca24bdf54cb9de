# Headphone cable winder, H shape: 70 mm tall x 50 mm wide overall; two uprights 14 mm
# wide, a 22 mm tall crossbar between them, all outer corners rounded 4 mm, a 3 mm slit
# 10 mm deep into the top of the left upright to hold the plug cable.
solid winder {
    left = Rectangle(center=(-18, 0), width=14, height=70)
    right = Rectangle(center=(18, 0), width=14, height=70)
    bar = Rectangle(center=(0, 0), width=22, height=22)
    RightOf(bar, left)
    LeftOf(bar, right)
    AlignCenterY(bar, left)
    AlignCenterY(right, left)
    hole slit {
        s = Rectangle(center=(-18, 30), width=3, height=10)
    }
    AlignCenterX(slit, left)
    AlignTop(slit, left)
    Fillet([left, right], 4)
}
