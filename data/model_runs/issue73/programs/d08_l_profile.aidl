# L-bracket profile: 40 x 40 legs, 5 mm thick, 3 mm inside fillet.
solid l {
    profile = Polygon([(0, 0), (40, 0), (40, 5), (5, 5), (5, 40), (0, 40)])
    Fillet(at=profile.points[3], radius=3)
}
