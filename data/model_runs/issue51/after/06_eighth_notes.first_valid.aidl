# A pair of beamed eighth notes as a Christmas-tree ornament, about 70 mm tall,
# with a hanging loop and hole on top of the beam.

param head_rx = 9 mm
param head_ry = 6 mm
param stem_w = 3 mm
param beam_t = 8 mm
param loop_r = 5 mm
param hang_d = 4 mm

solid notes {
    # note heads, tilted like printed notes; the second one sits higher
    head1 = Ellipse(center=(-14, 7), rx=head_rx, ry=head_ry, rotation=25)
    head2 = Ellipse(center=(14, 15), rx=head_rx, ry=head_ry, rotation=25)
    Fixed(head1)
    Fixed(head2)

    # stems rise from the right side of each head to the beam
    stem1 = Rectangle(bottom_left=(-8, 7), width=stem_w, height=50)
    stem2 = Rectangle(bottom_left=(20, 15), width=stem_w, height=50)
    stem1.bb.right == head1.center.x + 7.5 mm
    stem2.bb.right == head2.center.x + 7.5 mm
    stem1.bb.bottom == head1.center.y
    stem2.bb.bottom == head2.center.y

    # the slanted beam joining the stem tops
    beam = Polygon([(-8, 51), (23, 59), (23, 59 + beam_t), (-8, 51 + beam_t)])
    AlignLeft(beam, stem1)
    AlignRight(beam, stem2)
    stem1.bb.top == beam.bb.bottom + beam_t / 2
    stem2.bb.top == beam.bb.top - beam_t / 2

    # hanging loop on top of the beam, at its middle
    loop = Circle(center=(7.5, 67.5), radius=loop_r)
    loop.center.x == beam.bb.center_x
    loop.center.y == beam.bb.top - 1 mm
    hole hang {
        c = Circle(center=(7.5, 67.5), diameter=hang_d)
    }
    Concentric(hang.c, loop)
}
