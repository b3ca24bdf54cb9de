# imported from mirrored_brackets.dxf by `aidl import --infer`: edit freely
# recognised: 8 of 8 pieces of outlines and holes in 3 shapes (2 Circle, 1 Polygon)
# patterns: 1 profile, 1 equal sizes, 1 mirrored part
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
units mm
param width = 50 mm
param height = 40 mm
param wall = 6 mm
param holes_d = 5 mm
assembly plates {
    solid plate {
        # a profile of 6 corners at right angles: its faces by the edges and the walls' thickness
        body = Polygon([(50 - width, 0), (50, 0), (50, wall), (50 - width + wall, wall), (50 - width + wall, height), (50 - width, height)])
        Fixed(body)
        hole hole1 { h = Circle(center=((50 - width + 50 - width + wall) / 2, (wall + height) / 2), diameter=holes_d) }
        Fixed(hole1.h)
        hole hole2 { h = Circle(center=((50 - width + wall + 50) / 2, wall / 2), diameter=holes_d) }
        Fixed(hole2.h)
    }
    Fixed(plate)
    axis = Line((55, 0), (55, 40), construction=true)   # the mirror line
    Fixed(axis)
    plate_mirror = Mirrored(plate, about=axis)
}
