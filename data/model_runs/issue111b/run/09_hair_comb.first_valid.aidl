# Hair comb, 3 mm acrylic, 120 x 45 mm overall: a spine 120 x 15 mm along the top (R6 top
# corners, square bottom corners) and 24 teeth below it, each 2.5 mm wide with a round tip,
# 30 mm long from the spine's bottom edge, at 5 mm pitch centered on the comb (gaps 2.5 mm).
# A 5 mm hanging hole in the spine, centered 8 mm from its right end and 7.5 mm above its
# bottom edge.

units mm
thickness 3 mm

param teeth = 24, min = 10, max = 30
param pitch = 5 mm, min = 4 mm, max = 8 mm
param tooth_w = 2.5 mm, min = 1.5 mm, max = 4 mm
param tooth_l = 30 mm, min = 15 mm, max = 40 mm

solid comb {
    spine = RoundedRectangle(bottom_left=(-60, 0), width=120, height=15, corner_radii=[6, 6, 0, 0])
    for i in range(teeth) {
        tooth = Slot(start=((i - (teeth - 1) / 2) * pitch, tooth_w / 2),
                     end=((i - (teeth - 1) / 2) * pitch, -tooth_l + tooth_w / 2), width=tooth_w)
    }
    hole hang {
        c = Circle(center=(52, 7.5), diameter=5)
    }

    assert abs(self.bb.width - 120 mm) < 0.001 mm and abs(self.bb.height - 45 mm) < 0.001 mm, "comb 120 x 45"
    assert len(tooth) == 24, "24 teeth"
    assert abs(tooth[1].start.x - tooth[0].start.x - 5 mm) < 0.001 mm, "5 mm pitch"
    assert abs(spine.bb.bottom - tooth[0].bb.bottom - 30 mm) < 0.001 mm, "teeth 30 mm long"
    assert abs(tooth[0].width - 2.5 mm) < 0.001 mm, "teeth 2.5 mm wide"
    assert abs(spine.bb.right - hang.c.center.x - 8 mm) < 0.001 mm, "hole 8 mm from the end"
}
