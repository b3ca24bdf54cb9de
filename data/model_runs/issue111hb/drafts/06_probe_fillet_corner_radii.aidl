# probe after 06's first valid: E0408 with unequal corner_radii (a); same shapes with corner_radius=60 check ok (c)
solid p {
    head = RoundedRectangle(bottom_left=(-97.5, 185), width=195, height=215, corner_radii=[70, 70, 60, 60])
    throat = Polygon([(-16, 128), (16, 128), (60, 195), (-60, 195)])
    Fillet([throat, head], 25)
}
