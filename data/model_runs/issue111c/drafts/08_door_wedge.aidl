# Door stop wedge, stacked from 6 mm layers: each layer is a right-angled wedge
# 140 mm long and 30 mm high at its thick end, the thin end cut off at 3 mm
# high (a flat nose, not a sharp tip); a 12 mm hole 20 mm in from the thick
# end and 12 mm up, to hang it on a hook; two 4 mm dowel holes 40 mm and
# 80 mm from the thick end, 6 mm up from the base. Three layers, laid out
# 5 mm apart.
thickness 6 mm

def layer() -> solid {
    body = Polygon([(0, 0), (140, 0), (140, 3), (0, 30)])
    hole hang {
        c = Circle(center=(20, 12), diameter=12)
    }
    hole dowel1 {
        c = Circle(center=(40, 6), diameter=4)
    }
    hole dowel2 {
        c = Circle(center=(80, 6), diameter=4)
    }
}

assembly wedge {
    for i in range(3) {
        l = layer()
    }
    Above(l[1], l[0], gap=5)
    Above(l[2], l[1], gap=5)
    AlignLeft(l[1], l[0])
    AlignLeft(l[2], l[0])
}

assert len(wedge.l) == 3, "three layers"
assert wedge.l[0].body.bb.width == 140 mm and wedge.l[0].body.bb.height == 30 mm, "140 x 30"
assert wedge.l[0].hang.c.center.x - wedge.l[0].body.bb.left == 20 mm, "hang hole 20 mm in"
assert wedge.l[0].dowel2.c.center.x - wedge.l[0].body.bb.left == 80 mm, "dowel at 80 mm"
assert wedge.l[0].dowel1.c.center.y - wedge.l[0].body.bb.bottom == 6 mm, "dowel 6 mm up"
