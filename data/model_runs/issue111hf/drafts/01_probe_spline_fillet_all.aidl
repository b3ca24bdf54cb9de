# Request (workshop): a leather strop paddle for honing chisels and knives, cut from 6 mm
# birch ply. 300 mm long overall: a strop face 200 x 60 mm with 6 mm corner radii, and a
# handle 100 mm long below it, 30 mm wide near its rounded end, swelling to 34 mm at its
# middle (50 mm from the end) and 30 mm where it meets the face, with 8 mm rounded
# shoulders where handle and face meet. A 10 mm hanging hole centred 14 mm from the
# handle's end. Engraved: a line 3 mm inside the face's edge to line up the leather strip
# (54 x 194 mm), and "GREEN 0.5 µm" (the compound loaded on the leather) in filled bold
# letters 7 mm tall, reading along the handle, centred between the hole and the face.

units mm
thickness 6 mm

param face_w = 60 mm, min = 40 mm, max = 80 mm
param face_h = 200 mm, min = 120 mm, max = 260 mm
param handle_len = 100 mm, min = 80 mm, max = 130 mm

solid paddle {
    face = RoundedRectangle(center=(0, handle_len + face_h / 2), width=face_w, height=face_h,
                            corner_radius=6)
    # the handle's right half, from the end on the axis up into the face
    grip = Spline(mirror([(0, 0), (11, 2), (15, 10), (17, 50), (15, handle_len),
                          (14, handle_len + 15), (0, handle_len + 15)], about="y"),
                  closed=true)

    hole hang {
        eye = Circle(center=(0, 14), diameter=10)
    }

    drawing leather_line {
        edge = RoundedRectangle(center=(0, handle_len + face_h / 2), width=face_w - 6,
                                height=face_h - 6, corner_radius=3)
    }

    drawing compound {
        t = Text("GREEN 0.5 µm", position=(0, (19 + handle_len) / 2), size=7, font="sans:Bold",
                 valign="middle", rotation=90 deg, fill=true)
    }

    # rounded shoulders where the handle meets the face
    Fillet(8)

    assert face.bb.top - grip.points[0].y == 300 mm, "300 mm long overall"
    assert face.width == 60 mm and face.height == 200 mm, "strop face 200 x 60"
    assert face.bb.bottom - grip.points[0].y == 100 mm, "handle 100 mm long"
    assert grip.points[3].x - grip.points[-3].x == 34 mm, "handle 34 mm wide at its middle"
    assert grip.points[3].y - grip.points[0].y == 50 mm, "widest 50 mm from the end"
    assert hang.eye.diameter == 10 mm
    assert hang.eye.center.y - grip.points[0].y == 14 mm, "hole 14 mm from the end"
    assert leather_line.edge.width == 54 mm and leather_line.edge.height == 194 mm
    assert distance(compound, hang) >= 3 mm, "the words clear the hole"
}
