# expect: E0305 3:35
solid s {
    a = Arc(center=(0, 0), radius=1e14, start_angle=0 deg, end_angle=90 deg)
}
