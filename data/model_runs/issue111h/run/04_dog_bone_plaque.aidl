# Dog kennel name plaque in the shape of a bone, 4 mm ply, 126 x 54 mm overall: a bar
# 96 x 26 mm with four 30 mm round lobes near its end corners (lobe centres at
# x = +-48 mm, y = +-12 mm from the bone's centre). The dog's name "BISCUIT" cut through
# in sans Bold as a stencil (counters held), 14 mm cap height but at most 60 mm wide,
# centred on the bone. Two 4 mm screw holes at the bar's ends (x = +-48 mm, y = 0),
# between the lobes of each pair, countersunk 8 mm.

units mm
thickness 4 mm

param name_h = 14 mm, min = 8 mm, max = 18 mm

solid bone {
    bar = Rectangle(center=(0, 0), width=96, height=26)
    lobe_tl = Circle(center=(-48, 12), diameter=30)
    lobe_bl = Circle(center=(-48, -12), diameter=30)
    lobe_tr = Circle(center=(48, 12), diameter=30)
    lobe_br = Circle(center=(48, -12), diameter=30)
    At(lobe_tl.center, bar.center, dx=-48, dy=12)
    At(lobe_bl.center, bar.center, dx=-48, dy=-12)
    At(lobe_tr.center, bar.center, dx=48, dy=12)
    At(lobe_br.center, bar.center, dx=48, dy=-12)

    hole name {
        word = Text("BISCUIT", position=(0, 0), size=name_h, valign="middle",
                    font="sans:Bold", stencil=true, max_width=60)
    }
    CenterInside(name, bar)

    hole screw_l { c = Circle(center=(-48, 0), diameter=4) }
    hole screw_r { c = Circle(center=(48, 0), diameter=4) }
    Concentric(screw_l.c, bar.left.midpoint)
    Concentric(screw_r.c, bar.right.midpoint)
    Countersink([screw_l, screw_r], diameter=8)

    assert self.bb.width == 126 mm, "bone 126 mm long"
    assert self.bb.height == 54 mm, "bone 54 mm high"
    assert bar.width == 96 mm and bar.height == 26 mm, "bar 96 x 26"
    assert lobe_tl.diameter == 30 mm, "30 mm lobes"
    assert lobe_tr.center.x - bar.center.x == 48 mm, "lobes at x = 48"
    assert lobe_tr.center.y - bar.center.y == 12 mm, "lobes at y = 12"
    assert name.bb.width <= 60 mm, "name at most 60 mm wide"
    assert name.bb.height <= 14 mm + 0.01 mm, "name at most 14 mm high"
    assert abs(name.bb.center_x - bar.center.x) < 0.01 mm, "name centred"
    assert screw_l.c.diameter == 4 mm, "4 mm screws"
    assert screw_r.c.center.x - bar.center.x == 48 mm, "screw at x = 48"
    assert name.bb.left > lobe_tl.center.x + 15 mm, "name clear of the left lobes"
    assert name.bb.right < lobe_tr.center.x - 15 mm, "name clear of the right lobes"
}
