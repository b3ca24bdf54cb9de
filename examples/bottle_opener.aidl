# A flat bottle opener: a round head with the cap-lifting cut-out (a round
# opening with a straight lip), a handle with grip slots made by a loop, a
# hanging hole at the end, and an engraved label.
# Try: --set length=140  --set head_d=56  --set grips=6

param length = 110 mm  # from the head's center to the end of the handle
param head_d = 48 mm
param handle_w = 26 mm
param grips = 4

solid opener {
    solid head {
        disc = Circle(center=(0, 0), diameter=head_d)
    }

    solid handle {
        grip = RoundedRectangle(center=(length / 2, 0), width=length, height=handle_w,
                                corner_radius=handle_w / 2 - 1)
        hole hang {
            eye = Circle(center=(length - handle_w / 2, 0), diameter=7)
        }
        # the hanging hole is centered in the handle's rounded end
        AlignCenterY(hang, grip)
        HorizontalDistance(hang.eye.center, grip.right.midpoint, handle_w / 2)

        # finger-grip slots across the handle
        hole slots {
            for i in range(grips) {
                s = Slot(center=(0.45 * length + i * 10 mm, 0), length=0.45 * handle_w,
                         width=4, rotation=90)
            }
        }
        AlignCenterY(slots, grip)
        slots.s[0].center.x == grip.bb.left + 0.45 * length
    }

    # the opening: a round hole merged with a rectangular notch whose straight
    # outer edge is the lip that catches the bottle cap
    hole mouth {
        round = Circle(center=(0.05 * head_d, 0), radius=0.27 * head_d)
        lip = Rectangle(center=(-0.24 * head_d, 0), width=0.22 * head_d, height=0.4 * head_d)
    }

    drawing label {
        word = Text("OPEN", ((0.32 * head_d + 0.45 * length - 2 mm) / 2, -2.5), size=5)
    }

    # the handle starts at the head's center, on its axis
    AlignCenterY(handle.grip, head)
    handle.bb.left == head.disc.center.x
    # the lip leaves a bridge of 0.15 * head_d to the head's rim
    mouth.bb.left == head.bb.left + 0.15 * head_d
    AlignCenterY(mouth, head)
    AlignCenterY(label, handle)
    # the label sits halfway between the opening and the first grip slot
    label.bb.center_x == (mouth.bb.right + handle.slots.bb.left) / 2
}
