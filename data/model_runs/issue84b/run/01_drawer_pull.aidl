# Drawer pull: an arched D-pull 120 mm wide and 40 mm tall: a 12 mm flange strip
# along the bottom carries two 4.5 mm screw holes at 96 mm centres; above it an
# arched grip with an 80 x 16 mm hand opening (6 mm corner radius).

param width = 120 mm
param height = 40 mm
param centres = 96 mm

solid pull {
    flange = Rectangle(center=(0, 6), width=width, height=12)
    arch = Ellipse(center=(0, 12), rx=width / 2, ry=height - 12)
    hole cut_below { r = Rectangle(center=(0, -20), width=width + 10, height=40) }
    hole opening {
        r = RoundedRectangle(center=(0, 21), width=80, height=16, corner_radius=6)
    }
    hole screws {
        a = Circle(center=(-centres / 2, 6), diameter=4.5)
        b = Circle(center=(centres / 2, 6), diameter=4.5)
    }
}
