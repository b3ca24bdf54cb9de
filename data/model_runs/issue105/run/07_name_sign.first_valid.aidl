# Door name sign: a 200 mm x 60 mm plate with 6 mm rounded corners and two 4 mm
# hanging holes 10 mm in from the left and right ends, centred vertically. The name
# "WORKSHOP" is engraved, 30 mm tall but never wider than 160 mm (it must fit between
# the holes with a margin), centred on the plate.
param width = 200 mm, min = 150 mm, max = 300 mm

solid sign {
    plate = RoundedRectangle(center=(0, 0), width=width, height=60, corner_radius=6)
    hole hang_l { c = Circle(center=(-90, 0), diameter=4) }
    hole hang_r { c = Circle(center=(90, 0), diameter=4) }
    At(hang_l.c.center, plate.left.midpoint, dx=10)
    At(hang_r.c.center, plate.right.midpoint, dx=-10)

    drawing name {
        t = Text("WORKSHOP", position=(0, 0), size=30, valign="middle", max_width=width - 40)
    }
    CenterInside(name, plate)
}
