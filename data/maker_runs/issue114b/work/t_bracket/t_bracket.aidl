# imported from t_bracket.dxf by `aidl import --infer`: edit freely
# recognised: 10 of 10 pieces of outlines and holes in 3 shapes (2 Circle, 1 Polygon)
# patterns: 1 profile, 1 mirrored pair
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# 2 holes mirrored about the centre line, nearer the side edges than it: each kept from its own edge (`holes_inset`), the far one too
units mm
param width = 100 mm
param height = 60 mm
param stem_width = 20 mm  # centred
param wall = 15 mm
param holes_d = 5 mm
param holes_inset = 12 mm  # from the edges
solid plate {
    # a profile of 8 corners at right angles: its faces by the edges and the walls' thickness
    body = Polygon([(width / 2 - stem_width / 2, 0), (width / 2 + stem_width / 2, 0), (width / 2 + stem_width / 2, height - wall), (width, height - wall), (width, height), (0, height), (0, height - wall), (width / 2 - stem_width / 2, height - wall)])
    Fixed(body)
    # mirrored about the centre line
    for s in [-1, 1] {
        hole holes { h = Circle(center=(width / 2 + s * (width / 2 - holes_inset), (height - wall + height) / 2), diameter=holes_d) }
        Fixed(holes.h)
    }
}
