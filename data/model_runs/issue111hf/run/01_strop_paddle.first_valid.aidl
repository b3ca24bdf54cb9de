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
    # the handle: a round end, sides swelling in one arc each, a straight neck into the face
    solid handle {
        end_cap = Arc(start=(-15, 15), through=(0, 0), end=(15, 15))
        right_side = Arc(start=(15, 15), through=(17, 50), end=(15, 85))
        right_neck = Line((15, 85), (15, handle_len))
        top = Line((15, handle_len), (-15, handle_len))
        left_neck = Line((-15, handle_len), (-15, 85))
        left_side = Arc(start=(-15, 85), through=(-17, 50), end=(-15, 15))
    }

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
    Fillet([(15, handle_len), (-15, handle_len)], 8)
    # smooth the slight kinks where the swelling arcs meet the end and the neck
    Fillet([(15, 15), (-15, 15), (15, 85), (-15, 85)], 30)

    assert face.bb.top - handle.bb.bottom == 300 mm, "300 mm long overall"
    assert face.width == 60 mm and face.height == 200 mm, "strop face 200 x 60"
    assert face.bb.bottom - handle.bb.bottom == 100 mm, "handle 100 mm long"
    assert handle.bb.width == 34 mm, "handle 34 mm wide at its middle"
    assert handle.right_side.through.y - handle.bb.bottom == 50 mm, "widest 50 mm from the end"
    assert handle.top.length == 30 mm, "30 mm where it meets the face"
    assert hang.eye.diameter == 10 mm
    assert hang.eye.center.y - handle.bb.bottom == 14 mm, "hole 14 mm from the end"
    assert leather_line.edge.width == 54 mm and leather_line.edge.height == 194 mm
    assert distance(compound, hang) >= 3 mm, "the words clear the hole"
}
