# NEMA 23 motor mounting plate: 80 mm x 80 mm, 5 mm corner radius; a 38.5 mm pilot
# bore for the motor boss in the centre; four 5.2 mm screw holes on the motor's
# 47.14 mm square bolt pattern; two vertical adjustment slots for the frame,
# 6.5 mm wide x 20 mm long, centred vertically, 6 mm in from the left and right edges.
param side = 80 mm, min = 70 mm, max = 120 mm

solid plate {
    body = RoundedRectangle(center=(0, 0), width=side, height=side, corner_radius=5)

    hole pilot {
        c = Circle(center=(0, 0), diameter=38.5)
    }
    CenterInside(pilot, body)

    pattern = Rectangle(center=(0, 0), width=47.14, height=47.14, construction=true)
    Concentric(pattern, body)
    hole screw {
        c = Circle(center=(0, 0), diameter=5.2)
    }
    CornerPattern(screw, pattern)

    hole adjust_l {
        s = Slot(center=(-34, 0), length=20, width=6.5, rotation=90)
    }
    hole adjust_r {
        s = Slot(center=(34, 0), length=20, width=6.5, rotation=90)
    }
    AlignCenterY(adjust_l, body)
    AlignCenterY(adjust_r, body)
    adjust_l.bb.left == body.bb.left + 6
    adjust_r.bb.right == body.bb.right - 6
}
