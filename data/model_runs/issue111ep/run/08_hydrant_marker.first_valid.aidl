# Request (signs): a fire hydrant indicator plate (the yellow "H" sign) for the private
# hydrant at our farm gate, cut from 3 mm yellow-on-black laser laminate, engraved through
# the yellow to the black. The plate is 150 x 190 mm with R8 corners. Engraved filled: a
# border 6 mm wide, 5 mm in from the edge; an H 100 mm wide and 130 mm tall, centred, with
# 20 mm legs and a 14 mm crossbar; the main's size "100" (mm) above the crossbar and the
# distance "3.5" (metres) below it, in 18 mm bold digits centred between the legs. Two 5 mm
# screw holes on the centre line, 10 mm inside the border's inner edge, top and bottom.

units mm
thickness 3 mm
kerf 0.1 mm

param main_mm = 100, min=50, max=300
param dist_m = 3.5, min=0.5, max=99

plate_w = 150 mm
plate_h = 190 mm
border_in = 5 mm
border_w = 6 mm
h_w = 100 mm
h_h = 130 mm
leg = 20 mm
bar = 14 mm
digits = 18 mm

solid sign {
    plate = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=8)
    inner_edge = plate_h / 2 - border_in - border_w
    hole top_screw { c = Circle(center=(0, inner_edge - 10), diameter=5) }
    hole bottom_screw { c = Circle(center=(0, -(inner_edge - 10)), diameter=5) }
    drawing face {
        edge = RoundedRectangle(center=(0, 0), width=plate_w - 2 * (border_in + border_w),
                                height=plate_h - 2 * (border_in + border_w), corner_radius=3,
                                construction=true)
        border = Shell(edge, border_w, fill=true)
        left_leg = Rectangle(center=(-(h_w - leg) / 2, 0), width=leg, height=h_h, fill=true)
        right_leg = Rectangle(center=((h_w - leg) / 2, 0), width=leg, height=h_h, fill=true)
        crossbar = Rectangle(center=(0, 0), width=h_w - 2 * leg, height=bar, fill=true)
        size_no = Text(str(main_mm), position=(0, (bar / 2 + h_h / 2) / 2), size=digits,
                       font="sans:Bold", valign="middle", fill=true)
        dist_no = Text(str(dist_m), position=(0, -(bar / 2 + h_h / 2) / 2), size=digits,
                       font="sans:Bold", valign="middle", fill=true)
    }

    # the request's numbers
    assert plate.width == 150 mm and plate.height == 190 mm
    assert plate.bb.top - face.border.bb.top == 5 mm
    assert face.left_leg.width == 20 mm and face.crossbar.height == 14 mm
    assert face.right_leg.bb.right - face.left_leg.bb.left == 100 mm
    assert face.left_leg.height == 130 mm
    assert face.size_no.size == 18 mm and face.dist_no.size == 18 mm
    assert top_screw.c.diameter == 5 mm
    assert (plate.bb.top - 5 mm - 6 mm) - top_screw.c.center.y == 10 mm
    # the digits fit between the legs and clear the crossbar and the legs' ends
    assert face.size_no.bb.left - face.left_leg.bb.right >= 3 mm
    assert face.right_leg.bb.left - face.size_no.bb.right >= 3 mm
    assert face.size_no.bb.bottom - face.crossbar.bb.top >= 3 mm
    assert face.crossbar.bb.bottom - face.dist_no.bb.top >= 3 mm
    assert face.size_no.bb.top <= face.left_leg.bb.top
    assert face.dist_no.bb.bottom >= face.left_leg.bb.bottom
    # the screw holes stay off the H and the border
    assert top_screw.c.bb.bottom - face.left_leg.bb.top >= 3 mm
    assert face.border.bb.top - border_w - top_screw.c.bb.top >= 3 mm
}
