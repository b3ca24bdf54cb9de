# Dog-bone pet tag: a 32 x 12 mm bar with two 12 mm round lobes at each end
# (lobe centers at the bar's end lines, 5 mm above and below its center line),
# so the bone is 44 x 22 mm overall; a 3.5 mm ring hole at the left end's
# center; the name "BISCUIT" engraved, 4 mm tall, centered on the bar.

param name_size = 4 mm, min = 3 mm, max = 4.5 mm

solid tag {
    bar = Rectangle(center=(0, 0), width=32, height=12)
    tl = Circle(center=(-16, 5), diameter=12)
    bl = Circle(center=(-16, -5), diameter=12)
    tr = Circle(center=(16, 5), diameter=12)
    br = Circle(center=(16, -5), diameter=12)
    At(tl.center, bar.left.midpoint, dy=5)
    At(bl.center, bar.left.midpoint, dy=-5)
    At(tr.center, bar.right.midpoint, dy=5)
    At(br.center, bar.right.midpoint, dy=-5)

    hole ring { c = Circle(center=(-16, 0), diameter=3.5) }
    At(ring.c.center, bar.left.midpoint)

    drawing name {
        t = Text("BISCUIT", position=(0, 0), size=name_size, valign="middle")
    }
    CenterInside(name, bar)

    assert self.bb.width == 44 mm and self.bb.height == 22 mm, "bone 44 x 22 mm"
    assert name.bb.left - ring.bb.right >= 2 mm and name.bb.right <= bar.bb.right - 2 mm, "name clear of ring hole, inside the bar"
}
