# A drawer label holder: a frame plate with a window and two screw holes.
solid holder {
    plate = RoundedRectangle(center=(0, 0), width=80, height=40, corner_radius=3)
    hole window { w = Rectangle(center=(0, 0), width=56, height=26) }
    hole screw { c = Circle(center=(-34, 0), diameter=3.5) }
    Mirrored(screw, about=Line((0, -10), (0, 10), construction=true))
}
