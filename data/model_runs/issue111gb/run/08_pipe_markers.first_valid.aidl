# Request (signs, a workshop's service pipes): four pipe identification markers, 3 mm
# two-colour engraving acrylic, to be zip-tied to the pipes.
# - Each marker 150 x 30 mm with 4 mm corner radii.
# - A filled engraved border band 1.5 mm wide, its outer edge 2 mm in from the edge
#   (2 mm corner radii outside).
# - A cable-tie slot 3 x 8 mm across the marker, centred 9 mm in from each end.
# - A filled flow arrow pointing right, 22 mm long from x = 38 to 60 mm right of the centre:
#   a 6 mm shaft and a 14 mm wide head 10 mm long.
# - The pipe's name engraved filled, bold, 9 mm tall, centred in the space between the left
#   slot and the arrow, shrunk to fit with 3 mm clear at each end:
#   "COMPRESSED AIR", "COLD WATER", "HOT WATER", "GAS".
# Laid out in a column, 5 mm apart.

units mm
thickness 3 mm

names = ["COMPRESSED AIR", "COLD WATER", "HOT WATER", "GAS"]

def pipe_label(name="GAS") -> solid {
    body = RoundedRectangle(center=(0, 0), width=150, height=30, corner_radius=4)
    hole ties {
        left = Slot(center=(-66, 0), length=8, width=3, rotation=90)
        right = Slot(center=(66, 0), length=8, width=3, rotation=90)
    }
    drawing marks {
        border = Shell(RoundedRectangle(center=(0, 0), width=146, height=26, corner_radius=2), -1.5, fill=true)
        arrow = Polygon([(38, -3), (50, -3), (50, -7), (60, 0), (50, 7), (50, 3), (38, 3)], fill=true)
        words = Text(name, position=(-13, 0), size=9, font="sans:Bold", valign="middle", fill=true,
                     max_width=92 mm)
    }
}

assembly pipe_markers {
    for i in range(4) {
        tag = pipe_label(name=names[i])
    }
    for i in range(1, 4) {
        Below(tag[i], tag[i - 1], gap=5)
        AlignLeft(tag[i], tag[i - 1])
    }

    # the request's numbers
    assert len(tag) == 4, "four markers"
    for i in range(4) {
        assert tag[i].body.width == 150 mm and tag[i].body.height == 30 mm, "150 x 30"
        assert tag[i].ties.left.center.x - tag[i].body.bb.left == 9 mm, "slot 9 in from the left end"
        assert tag[i].body.bb.right - tag[i].ties.right.center.x == 9 mm, "slot 9 in from the right end"
        assert tag[i].ties.left.length == 8 mm and tag[i].ties.left.width == 3 mm, "slots 3 x 8"
        assert tag[i].marks.arrow.bb.width == 22 mm and tag[i].marks.arrow.bb.height == 14 mm, "arrow 22 long, head 14"
        assert tag[i].marks.border.bb.left - tag[i].body.bb.left == 2 mm, "border 2 in"
        assert tag[i].marks.words.size <= 9 mm, "name at most 9 tall"
        assert tag[i].marks.words.bb.left - tag[i].ties.left.bb.right >= 3 mm, "3 clear of the slot"
        assert tag[i].marks.arrow.bb.left - tag[i].marks.words.bb.right >= 3 mm, "3 clear of the arrow"
    }
    for i in range(1, 4) {
        assert tag[i - 1].bb.bottom - tag[i].bb.top == 5 mm, "5 apart"
    }
}
