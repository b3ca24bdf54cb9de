# probe after 06's first valid: the same with corner_radius=60: checks ok
solid p {
    head = RoundedRectangle(bottom_left=(-97.5, 185), width=195, height=215, corner_radius=60)
    throat = Polygon([(-16, 128), (16, 128), (60, 195), (-60, 195)])
    Fillet([throat, head], 25)
}
