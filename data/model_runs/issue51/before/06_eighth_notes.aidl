# A pair of beamed eighth notes as a Christmas-tree ornament, about 70 mm tall,
# with a hanging hole in a round tab above the beam.

param head_rx = 8.5 mm
param head_ry = 6 mm
param stem_w = 3.5 mm
param spacing = 30 mm       # head to head, along x
param rise = 8 mm           # the second note sits higher
param stem_len = 50 mm
param beam_t = 8 mm
param hang_d = 4 mm

solid notes {
    head1 = Ellipse(center=(0, 0), rx=head_rx, ry=head_ry, rotation=20)
    head2 = Ellipse(center=(spacing, rise), rx=head_rx, ry=head_ry, rotation=20)
    Fixed(head1)
    Fixed(head2)

    # stems rise from the right side of each head
    stem1 = Rectangle(center=(head_rx - stem_w / 2, stem_len / 2), width=stem_w, height=stem_len)
    stem2 = Rectangle(center=(spacing + head_rx - stem_w / 2, rise + stem_len / 2), width=stem_w, height=stem_len)
    stem1.bottom.midpoint.y == head1.center.y
    stem2.bottom.midpoint.y == head2.center.y
    stem1.right.midpoint.x == head1.bb.right - 0.5 mm
    stem2.right.midpoint.x == head2.bb.right - 0.5 mm

    # the beam joins the stem tops, slanting up like the heads
    beam = Polygon([(0, 0), (spacing + stem_w, rise), (spacing + stem_w, rise + beam_t), (0, beam_t)])
    AlignLeft(beam, stem1)
    AlignTop(beam, stem1)

    # round tab with the hanging hole, on top of the beam's middle
    solid tab {
        ring = Circle(center=(15, 62), radius=hang_d / 2 + 3)
        hole hang {
            c = Circle(center=(15, 62), diameter=hang_d)
        }
        Concentric(hang.c, ring)
    }
    AlignCenterX(tab, beam)
    tab.ring.center.y == beam.bb.top - rise / 2
}
