# imported from mirrored_l.dxf by `aidl import --infer`: edit freely
# recognised: 6 of 6 pieces of outlines and holes in 1 shapes (1 Polygon)
# patterns: 1 profile, 1 mirrored part
# equal within 1e-07 mm, numbers rounded within 1e-09 mm; the rest stays exact Line/Arc chains
# a part and its mirror image 10 apart: the gap a param, `gap`, about the mirror line
units mm
param gap = 20 mm  # between the part and its mirror image
param width = 50 mm
param height = 40 mm
param wall = 6 mm
assembly plates {
    solid plate {
        # a profile of 6 corners at right angles: its faces by the edges and the walls' thickness
        body = Polygon([(50 + (5 - gap / 2) + -width, 0), (50 + (5 - gap / 2), 0), (50 + (5 - gap / 2), wall), (50 + (5 - gap / 2) + -width + wall, wall), (50 + (5 - gap / 2) + -width + wall, height), (50 + (5 - gap / 2) + -width, height)])
        Fixed(body)
    }
    Fixed(plate)
    axis = Line((55, 0), (55, 40), construction=true)   # the mirror line
    Fixed(axis)
    plate_mirror = Mirrored(plate, about=axis)
}
