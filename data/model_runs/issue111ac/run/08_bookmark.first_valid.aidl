# Gifts: a personalised bookmark, cut from 1.5 mm birch veneer ply. 45 x 150 mm, top corners
# R8, a swallowtail V-notch 20 mm wide and 12 mm deep in the bottom end, a 5 mm tassel hole
# 8 mm below the top. The name "SOPHIE" cut right through as stencil letters (bold sans,
# 14 mm tall, at most 62 mm long) reading up the bookmark, centred 100 mm from the bottom. Below
# the name a lattice of 12 diamond cut-outs (4 rows x 3, 9 mm across, 12 mm apart, the lowest
# row 20 mm up).

units mm
thickness 1.5 mm

param width = 45 mm, min = 35 mm, max = 60 mm
param height = 150 mm, min = 120 mm, max = 200 mm
param notch_w = 20 mm, min = 10 mm, max = 30 mm
param notch_d = 12 mm, min = 6 mm, max = 20 mm
param pitch = 12 mm, min = 10 mm, max = 16 mm
param diamond = 9 mm, min = 6 mm, max = 10 mm

solid bookmark {
    body = RoundedRectangle(center=(0, height / 2), width=width, height=height,
                            corner_radii=[8, 8, 0, 0])
    hole tail {
        v = Triangle(a=(-notch_w / 2, -1), b=(notch_w / 2, -1), c=(0, notch_d))
    }
    hole tassel {
        c = Circle(center=(0, height - 8 mm), diameter=5 mm)
    }
    hole name {
        t = Text("SOPHIE", position=(0, 100), size=14, font="sans:Bold", rotation=90 deg,
                 valign="middle", stencil=true, max_width=62 mm)
    }
    hole diamond_hole {
        d = RegularPolygon(center=(-pitch, 20), radius=diamond / 2, sides=4)
    }
    lattice = GridPattern(diamond_hole, 4, 3, (pitch, pitch))

    # the request's own numbers
    assert body.width == 45 mm and body.height == 150 mm, "45 x 150"
    assert tail.v.c.y - body.bb.bottom == 12 mm, "notch 12 mm deep"
    assert tassel.c.diameter == 5 mm and body.bb.top - tassel.c.center.y == 8 mm, "5 mm tassel hole 8 mm below the top"
    assert name.t.size <= 14 mm and name.t.bb.height <= 62 mm, "name 14 mm tall, at most 62 long"
    assert name.t.position.y - body.bb.bottom == 100 mm, "name centred 100 mm up"
    assert len(lattice) == 12, "12 diamonds"
    assert lattice[0].d.center.y - body.bb.bottom == 20 mm, "lowest row 20 mm up"
    assert lattice[0].d.bb.width == 9 mm, "diamonds 9 mm across"
    assert lattice[11].d.bb.top < name.bb.bottom, "the lattice below the name"
    assert name.bb.top < tassel.bb.bottom, "the name below the tassel hole"
}
