# Wall-mounted toothbrush holder plate: 120 x 50 mm, corner radius 6 mm, three round
# holes 18 mm across on a 36 mm pitch, centred, plus two 4 mm screw holes 8 mm from
# each end, at the plate's mid-height.
param hole_d = 18 mm, min = 12 mm, max = 24 mm
solid holder {
    body = RoundedRectangle(center=(0, 0), width=120, height=50, corner_radius=6)
    hole brush {
        c = Circle(center=(-36, 0), diameter=hole_d)
    }
    holes = LinearPattern(brush, 3, (36, 0))
    AlignCenterY(brush, body)
    At(holes[1].c.center, body.center)
    hole screw {
        s = Circle(center=(-52, 0), diameter=4)
    }
    AlignCenterY(screw, body)
    HorizontalDistance(body.left.midpoint, screw.s.center, 8)
    other = Mirrored(screw, about=Line((0, -30), (0, 30), construction=true))
}
