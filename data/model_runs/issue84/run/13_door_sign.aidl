# A door sign: 200 x 70 mm with 8 mm corner radii, "MEETING ROOM" engraved
# 13 mm high centred, a 3 mm engraved border 5 mm inside the edge, and two
# 4 mm screw holes 12 mm in from the left and right ends on the centre line.
solid sign {
    plate = RoundedRectangle(center=(0, 0), width=200, height=70, corner_radius=8)
    hole screws {
        l = Circle(center=(-88, 0), diameter=4)
        r = Circle(center=(88, 0), diameter=4)
    }
    drawing engraving {
        border = RoundedRectangle(center=(0, 0), width=190, height=60, corner_radius=4)
        label = Text("MEETING ROOM", (0, 0), size=13, valign="middle")
    }
}
