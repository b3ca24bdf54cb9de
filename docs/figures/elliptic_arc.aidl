# Figure of docs/language.md: elliptic arcs: a lens closed by a line, an egg-shaped tab from two
# half ellipses of different ry, and an engraved arc with its ellipse's axes.
# Drawn by `python docs/make_pictures.py` to docs/images/elliptic_arc.png.

assembly arcs {
    solid lens {
        top = Ellipse(center=(0, 0), rx=30, ry=12, rotation=10 deg, start_angle=20 deg,
                      end_angle=160 deg)
        bottom = Line(start=top.end, end=top.start)
    }
    solid egg {
        upper = Ellipse(center=(60, 0), rx=14, ry=20, start_angle=0 deg, end_angle=180 deg)
        lower = Ellipse(center=(60, 0), rx=14, ry=11, start_angle=180 deg, end_angle=360 deg)
    }
    drawing mark {
        a = Ellipse(center=(100, 0), rx=16, ry=7, rotation=-30 deg, start_angle=-60 deg,
                    end_angle=200 deg)
        major = Line(start=a.center, end=a.vertex)
        minor = Line(start=a.center, end=a.co_vertex)
    }
}
