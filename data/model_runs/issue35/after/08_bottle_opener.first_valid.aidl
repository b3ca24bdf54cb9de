# bottle opener with a hanging hole
param length = 100 mm
param head_d = 46 mm
param handle_w = 24 mm
solid opener {
    solid head { disc = Circle(center=(0, 0), diameter=head_d) }
    solid handle {
        grip = RoundedRectangle(center=(length / 2, 0), width=length, height=handle_w, corner_radius=handle_w / 2 - 1)
        hole hang { eye = Circle(center=(length - handle_w / 2, 0), diameter=7) }
        AlignCenterY(hang, grip)
        HorizontalDistance(hang.eye.center, grip.right.midpoint, handle_w / 2)
    }
    hole mouth {
        round = Circle(center=(0.05 * head_d, 0), radius=0.27 * head_d)
        lip = Rectangle(center=(-0.24 * head_d, 0), width=0.22 * head_d, height=0.4 * head_d)
    }
    Fixed(head)
    AlignCenterY(handle.grip, head)
    handle.bb.left == head.disc.center.x
    mouth.bb.left == head.bb.left + 0.15 * head_d
    AlignCenterY(mouth, head)
}
