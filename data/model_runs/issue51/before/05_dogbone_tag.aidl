# Dog-bone pet ID tag, 45 mm long, "REX" engraved, 4 mm ring hole at one end.

param length = 45 mm
param lobe_r = 6 mm
param lobe_dy = 5 mm
param shaft_h = 12 mm

solid tag {
    shaft = Rectangle(center=(0, 0), width=length - 2 * lobe_r, height=shaft_h)
    Fixed(shaft)

    # two round lobes at each end
    lobe_tl = Circle(center=(-(length / 2 - lobe_r), lobe_dy), radius=lobe_r)
    lobe_bl = Circle(center=(-(length / 2 - lobe_r), -lobe_dy), radius=lobe_r)
    lobe_tr = Circle(center=(length / 2 - lobe_r, lobe_dy), radius=lobe_r)
    lobe_br = Circle(center=(length / 2 - lobe_r, -lobe_dy), radius=lobe_r)
    Fixed(lobe_tl)
    Fixed(lobe_bl)
    Fixed(lobe_tr)
    Fixed(lobe_br)

    hole ring {
        c = Circle(center=(-(length / 2 - lobe_r) + 1.5, 0), diameter=4)
    }
    AlignCenterY(ring, shaft)

    drawing name {
        t = Text("REX", position=(2, 0), size=7, valign="middle")
    }
    AlignCenterY(name, shaft)
    name.bb.center_x == (ring.bb.right + shaft.right.midpoint.x) / 2
}
