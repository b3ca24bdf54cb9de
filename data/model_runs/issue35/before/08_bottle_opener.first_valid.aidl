# A flat bottle opener with a hanging hole: a rounded bar with a wide head at
# one end holding the cap-lifting opening (a round hole joined to a
# rectangular notch whose straight edge is the lip) and a hanging hole at
# the other end.

param length = 100 mm
param head_w = 44 mm
param handle_w = 24 mm
param hang_d = 6 mm

solid opener {
    head = RoundedRectangle(center=(0, 0), width=head_w, height=head_w, corner_radius=12)
    handle = RoundedRectangle(center=(length / 2, 0), width=length - head_w / 2,
                              height=handle_w, corner_radius=handle_w / 2)
    Fixed(head)
    AlignCenterY(handle, head)
    handle.bb.left == head.center.x
    # overall length from the head's left edge to the handle's end
    handle.bb.right - head.bb.left == length

    hole mouth {
        round = Circle(center=(4, 0), radius=12)
        lip = Rectangle(center=(-9, 0), width=10, height=16)
    }
    AlignCenterY(mouth, head)
    mouth.bb.left == head.bb.left + 6 mm

    hole hang {
        eye = Circle(center=(length - head_w / 2 - handle_w / 2, 0), diameter=hang_d)
    }
    AlignCenterY(hang, handle)
    HorizontalDistance(hang.eye.center, handle.right.midpoint, handle_w / 2)

    Fillet(2 mm)
}
