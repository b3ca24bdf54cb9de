# Dog-bone pet ID tag, 45 mm long, with "REX" engraved and a 4 mm ring hole.

param length = 45 mm
param lobe_r = 6 mm
param lobe_dy = 5 mm
param shaft_h = 12 mm

solid bone {
    shaft = Rectangle(center=(0, 0), width=length - 2 * lobe_r, height=shaft_h)
    Fixed(shaft)

    # two round lobes at each end
    lobe_lt = Circle(center=(-(length / 2 - lobe_r), lobe_dy), radius=lobe_r)
    lobe_lb = Circle(center=(-(length / 2 - lobe_r), -lobe_dy), radius=lobe_r)
    lobe_rt = Circle(center=(length / 2 - lobe_r, lobe_dy), radius=lobe_r)
    lobe_rb = Circle(center=(length / 2 - lobe_r, -lobe_dy), radius=lobe_r)
    Coincident(lobe_lt.center, shaft.top_left)
    Coincident(lobe_rt.center, shaft.top_right)
    Coincident(lobe_lb.center, shaft.bottom_left)
    Coincident(lobe_rb.center, shaft.bottom_right)

    # ring hole in the left end, between its two lobes
    hole ring {
        c = Circle(center=(-14, 0), diameter=4)
    }
    AlignCenterY(ring, shaft)
    ring.c.center.x == shaft.bb.left + 2.5 mm

    drawing name {
        t = Text("REX", position=(3, 0), size=7, valign="middle")
    }
    AlignCenterY(name, shaft)
    # the name is centered between the ring hole and the right end
    name.bb.center_x == (ring.bb.right + self.bb.right) / 2
}
