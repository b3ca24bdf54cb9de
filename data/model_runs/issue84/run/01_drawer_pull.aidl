# A flat drawer pull: 128 x 22 mm bar with rounded ends, two M4 clearance
# holes at 96 mm centres, and a 60 x 8 mm finger slot between them.
param length = 128 mm
param width = 22 mm
param spacing = 96 mm

solid pull {
    bar = RoundedRectangle(center=(0, 0), width=length, height=width, corner_radius=width / 2)
    hole left_screw { c = Circle(center=(-spacing / 2, 0), diameter=4.5) }
    hole right_screw { c = Circle(center=(spacing / 2, 0), diameter=4.5) }
    hole grip { s = Slot(center=(0, 0), length=60, width=8) }
}
