# A cable comb: 90 x 30 mm plate, 6 U-slots 5 mm wide and 16 mm deep open at
# the top edge, pitch 12 mm, and two 3.4 mm mounting holes at the bottom.
param slots = 6
param pitch = 12 mm

solid comb {
    plate = RoundedRectangle(center=(0, 0), width=90, height=30, corner_radius=3)
    hole teeth {
        for i in range(slots) {
            s = Slot(start=(-(slots - 1) * pitch / 2 + i * pitch, 4), end=(-(slots - 1) * pitch / 2 + i * pitch, 20), width=5)
        }
    }
    hole mount_l { c = Circle(center=(-38, -9), diameter=3.4) }
    hole mount_r { c = Circle(center=(38, -9), diameter=3.4) }
}
