# Request (pets): a wave-shaped cat scratcher lounger built from corrugated cardboard ribs
# (4 mm) threaded on two 10 mm dowels between two 6 mm ply end plates.
# - Rib: 450 mm long, flat bottom, 120 mm tall at both ends, a smooth dip to 60 mm in the
#   middle (passing 110 mm at 60 mm from each end and 75 mm at 150 mm from each end); two
#   10.2 mm dowel holes 30 mm up, 60 mm in from each end. About 60 ribs are cut for a 240 mm
#   wide lounger (one rib is drawn).
# - End plates (two): the rib's profile grown by 10 mm round the top and ends but standing on
#   the same floor line (flat bottom flush with the ribs), the same two dowel holes; one of
#   them has the cat's name "MISO" cut through as bold stencil letters 22 mm high, centred
#   between the dowel holes, 40 mm up (middle of the letters).

units mm

param rib_len = 450 mm, min = 350 mm, max = 600 mm
end_h = 120 mm
mid_h = 60 mm
dowel_d = 10.2 mm
grow = 10 mm

# the top curve from the left end to the right, raised by g and its ends moved out by g
# (an Offset of a Spline is refused: E0108, so the grown outline is a Spline of its own)
def top_pts(g) = [(-g, end_h + g), (60, 110 + g), (150, 75 + g), (rib_len / 2, mid_h + g),
                  (rib_len - 150, 75 + g), (rib_len - 60, 110 + g), (rib_len + g, end_h + g)]

def profile(g=0 mm, name="") -> solid {
    # the outline: floor line, right end, the curve back, left end (corners sharp)
    p = Spline([(-g, 0), (rib_len + g, 0)] + [top_pts(g)[6 - i] for i in range(7)],
               closed=true, corners=[0, 1, 2, 8])
    hole dowels {
        a = Circle(center=(60, 30), diameter=dowel_d)
        b = Circle(center=(rib_len - 60, 30), diameter=dowel_d)
    }
    if name != "" {
        hole letters {
            t = Text(name, position=(rib_len / 2, 40), size=22, font="sans:Bold",
                     valign="middle", stencil=true)
        }
    }
}

assembly cat_scratcher {
    solid rib_part {
        thickness 4 mm
        rib = profile()
    }
    solid named_end {
        thickness 6 mm
        plate = profile(g=grow, name="MISO")
    }
    solid plain_end {
        thickness 6 mm
        plate = profile(g=grow)
    }
    Fixed(rib_part)
    Above(named_end, rib_part, gap=15)
    AlignLeft(named_end, rib_part)
    Above(plain_end, named_end, gap=15)
    AlignLeft(plain_end, named_end)

    # the request's numbers (read off the rib's own points)
    assert rib_part.rib.p.points[1].x - rib_part.rib.p.points[0].x == 450 mm, "450 long"
    assert rib_part.rib.p.points[2].y - rib_part.rib.p.points[1].y == 120 mm, "120 at the ends"
    assert rib_part.rib.p.points[5].y - rib_part.rib.p.points[0].y == 60 mm, "60 in the middle"
    assert (rib_part.rib.dowels.a.center.x - rib_part.rib.p.points[0].x == 60 mm and
            rib_part.rib.dowels.a.center.y - rib_part.rib.p.points[0].y == 30 mm),
        "dowels 60 in, 30 up"
    assert named_end.plate.p.points[2].y - named_end.plate.p.points[1].y == 130 mm,
        "ends grown 10 mm"
    assert named_end.plate.p.points[1].x - named_end.plate.p.points[0].x == 470 mm,
        "ends grown 10 mm each way"
    assert (named_end.plate.letters.t.bb.left > named_end.plate.dowels.a.center.x + 10 mm and
            named_end.plate.letters.t.bb.right < named_end.plate.dowels.b.center.x - 10 mm),
        "the name between the dowels"
    assert named_end.plate.letters.t.bb.top < named_end.plate.p.points[5].y, "under the dip"
}
