# A name plate with a logo engraved from an SVG (examples/parts/logo.svg: cubic Béziers, arcs
# and a circle, 24 mm wide by its width and viewBox).  The logo keeps its curves exactly; it
# is placed from the plate's left edge and centred in height, and the name follows it.
units mm

param name = "GREEN LAB"
param width = 100 mm, min = 70 mm, max = 240 mm, step = 1 mm
param height = 34 mm, min = 24 mm, max = 80 mm, step = 1 mm  # the logo is 20 mm tall
param corner_radius = 4 mm, min = 0.5 mm, max = height / 2 - 1 mm, step = 0.5 mm
param screw_d = 3.4 mm, min = 1.5 mm, max = 8 mm, step = 0.1 mm
# the name runs from the logo to the right screw hole: about 0.75 x its size a letter
param text_size = 7 mm, min = 2 mm, max = min(height - 6 mm, (width - 49 mm - screw_d / 2) / (0.75 * max(1, len(name)))), step = 0.5 mm

solid plate {
    body = RoundedRectangle(center=(0, 0), width=width, height=height,
                            corner_radius=corner_radius)
    Fixed(body)
    for x in [-1, 1] {
        hole screw {
            c = Circle(center=(0, 0), diameter=screw_d)
        }
        screw.c.center == (x * (width / 2 - 6 mm), 0)
    }
    drawing engrave {
        logo = Drawing2D("parts/logo.svg", id="logo")
        label = Text(name, (0, 0), size=text_size, anchor="start", valign="middle")
    }
    engrave.logo.bb.left == body.bb.left + 12
    engrave.logo.bb.center_y == body.center.y
    engrave.label.bb.left == engrave.logo.bb.right + 6
    engrave.label.position.y == body.center.y
}
