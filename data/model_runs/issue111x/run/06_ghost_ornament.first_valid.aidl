# Holidays: a Halloween ghost ornament, 3 mm poplar, 80 mm wide x 110 mm tall. A round
# head (a half circle of R40 on top), straight sides 60 mm down to a wavy hem of four
# half-circle tails R10 hanging down (20 mm each, the whole 80 mm). Two oval eyes cut
# through (12 mm wide x 18 mm tall) 14 mm either side of the centre line, their centres
# 38 mm below the top; a 12 mm round "oo" mouth centred, its centre 65 mm below the top;
# a 4 mm hanging hole centred, its centre 6 mm below the top.

thickness 3 mm

solid ghost {
    head = Arc(center=(0, 70), start=(40, 70), end=(-40, 70))
    left = Line((-40, 70), (-40, 10))
    for i in range(4) {
        tail = Arc(center=(-30 + i * 20, 10), start=(-40 + i * 20, 10), end=(-20 + i * 20, 10))
    }
    right = Line((40, 10), (40, 70))

    hole eyes {
        l = Ellipse(center=(-14, 72), rx=6, ry=9)
        r = Ellipse(center=(14, 72), rx=6, ry=9)
    }
    hole mouth {
        c = Circle(center=(0, 45), diameter=12)
    }
    hole hang {
        c = Circle(center=(0, 104), diameter=4)
    }
}

assert ghost.bb.width == 80 mm and ghost.bb.height == 110 mm, "80 x 110"
assert ghost.head.radius == 40 mm, "head R40"
assert len(ghost.tail) == 4, "four tails"
assert ghost.tail[0].radius == 10 mm, "tails R10"
assert ghost.left.length == 60 mm and ghost.right.length == 60 mm, "sides 60 mm"
assert ghost.eyes.l.bb.width == 12 mm and ghost.eyes.l.bb.height == 18 mm, "eyes 12 x 18"
assert ghost.eyes.r.center.x - ghost.head.center.x == 14 mm, "eyes 14 off the centre line"
assert ghost.bb.top - ghost.eyes.l.center.y == 38 mm, "eyes 38 below the top"
assert ghost.mouth.c.diameter == 12 mm, "12 mm mouth"
assert ghost.bb.top - ghost.mouth.c.center.y == 65 mm, "mouth 65 below the top"
assert ghost.bb.top - ghost.hang.c.center.y == 6 mm, "hang hole 6 below the top"
