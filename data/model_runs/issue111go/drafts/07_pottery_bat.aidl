# Request (crafts): a pottery-wheel bat with removable inserts, in 1/4 in birch ply (my
# wheel head has two 3/8 in bat pins 10 in apart). A 12 in base disc with the two pin holes
# (3/8 in plus 0.01 in play) and a 1 in push-out hole in the middle; a 12 in top ring glued
# on it with the same pin holes and a 6 in opening (0.02 in over the inserts) with two key
# notches 1/2 in wide and 1/4 in deep at 3 and 9 o'clock; three 6 in inserts with matching
# keys (0.04 in narrower, 0.01 in shorter) so they cannot spin, each engraved with centring
# rings every 1/2 in from 1 in to 5 in across and its number 1, 2 or 3 by the rim.
# "12 IN BAT - PINS 10 IN" engraved round the top ring's rim, over the top.

units in
thickness 0.25 in

bat_d = 12
pin_span = 10
pin_d = 3 / 8 + 0.01
insert_d = 6
open_d = insert_d + 0.02
key_w = 0.5
key_depth = 0.25

def pins() -> hole {
    l = Circle(center=(-pin_span / 2, 0), diameter=pin_d)
    r = Circle(center=(pin_span / 2, 0), diameter=pin_d)
}

def insert(n=1) -> solid {
    disc = Circle(center=(0, 0), diameter=insert_d)
    k1 = Rectangle(center=(insert_d / 2 + (key_depth - 0.01) / 2 - 0.05, 0),
                   width=key_depth - 0.01 + 0.1, height=key_w - 0.04)
    k2 = Rectangle(center=(-insert_d / 2 - (key_depth - 0.01) / 2 + 0.05, 0),
                   width=key_depth - 0.01 + 0.1, height=key_w - 0.04)
    drawing rings {
        for i in range(9) {
            c = Circle(center=(0, 0), diameter=1 + i * 0.5)
        }
        num = Text(str(n), position=(0, -2.75), size=0.3, valign="middle")
    }
}

assembly bat {
    solid base {
        disc = Circle(center=(0, 0), diameter=bat_d)
        holes = pins()
        hole push { c = Circle(center=(0, 0), diameter=1) }
    }
    solid ring {
        disc = Circle(center=(0, 0), diameter=bat_d)
        holes = pins()
        hole opening {
            c = Circle(center=(0, 0), diameter=open_d)
            k1 = Rectangle(center=(open_d / 2 + key_depth / 2 - 0.05, 0), width=key_depth + 0.1,
                           height=key_w)
            k2 = Rectangle(center=(-open_d / 2 - key_depth / 2 + 0.05, 0), width=key_depth + 0.1,
                           height=key_w)
        }
        drawing words {
            arc = Circle(center=(0, 0), radius=5.4, construction=true)
            w = Text("12 IN BAT - PINS 10 IN", along=arc, size=0.22)
        }
    }
    one = insert(n=1)
    two = insert(n=2)
    three = insert(n=3)

    RightOf(ring, base, gap=0.2)
    AlignBottom(ring, base)
    Above(one, base, gap=0.2)
    AlignLeft(one, base)
    RightOf(two, one, gap=0.2)
    AlignBottom(two, one)
    RightOf(three, two, gap=0.2)
    AlignBottom(three, two)

    Place(base, position=(0, 0, 0))
    Place(ring, position=(0, 0, 0.25))
    Place(one, position=(0, 0, 0.25))

    assert base.disc.diameter == 12 in and ring.disc.diameter == 12 in
    assert distance(base.holes.l.center, base.holes.r.center) == 10 in, "pins 10 in apart"
    assert base.holes.l.diameter - 3 in / 8 == 0.01 in
    assert base.push.c.diameter == 1 in
    assert ring.opening.c.diameter - one.disc.diameter == 0.02 in
    assert ring.opening.k1.height == 0.5 in and ring.opening.k1.bb.right - ring.opening.c.bb.right == 0.25 in,
        "notches 1/2 in wide, 1/4 in deep"
    assert ring.opening.k1.height - one.k1.height == 0.04 in, "keys 0.04 in narrower"
    assert ring.opening.k1.bb.right - one.k1.bb.right == 0.01 in + 0.01 in, "keys 0.01 in shorter"
    assert len(one.rings.c) == 9 and one.rings.c[0].diameter == 1 in and one.rings.c[8].diameter == 5 in
}
