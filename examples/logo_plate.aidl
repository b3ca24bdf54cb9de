# A name plate with a logo engraved from an SVG (examples/parts/logo.svg: cubic Béziers, arcs
# and a circle, 24 mm wide by its width and viewBox).  The logo keeps its curves exactly; it
# is placed from the plate's left edge and centred in height, and the name follows it.
units mm

param name = "GREEN LAB"

solid plate {
    body = RoundedRectangle(center=(0, 0), width=100, height=34, corner_radius=4)
    Fixed(body)
    for x in [-44, 44] {
        hole screw {
            c = Circle(center=(0, 0), diameter=3.4)
        }
        screw.c.center == (x, 0)
    }
    drawing engrave {
        logo = Drawing2D("parts/logo.svg", id="logo")
        label = Text(name, (0, 0), size=7, anchor="start", valign="middle")
    }
    engrave.logo.bb.left == body.bb.left + 12
    engrave.logo.bb.center_y == body.center.y
    engrave.label.bb.left == engrave.logo.bb.right + 6
    engrave.label.position.y == body.center.y
}
