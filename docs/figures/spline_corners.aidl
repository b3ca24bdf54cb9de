# Figure of docs/language.md: Spline corners: a leaf with a pointed tip and stem, and an
# outline written once for its right half and mirrored (mirror()), pointed at two corners.
# Drawn by `python docs/make_pictures.py` to docs/images/spline_corners.png.

half = [(50, -25), (62, -20), (66, -4), (58, 2), (64, 14), (58, 26), (50, 30)]

assembly corners {
    solid leaf {
        body = Spline([(0, -28), (14, -10), (12, 12), (0, 30), (-12, 12), (-14, -10)],
                      closed=true, corners=[0, 3])
    }
    solid bottle {
        axis = Line((50, -30), (50, 30), construction=true)
        body = Spline(mirror(half, about=axis), closed=true, corners=[3, 9])
    }
}
