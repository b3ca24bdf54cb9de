# Request: a Passover seder plate, two glued layers of 4 mm ply, 330 mm across. The top layer
# has six 80 mm round openings (the bottom layer shows through, so each is a shallow dish for
# one of the six foods) centred on a 100 mm radius, the first at the top and then every 60
# degrees anticlockwise: MAROR, BEITZAH, KARPAS, CHAZERET, CHAROSET, ZEROA. Each name is
# engraved in 7 mm letters following the rim just outside its dish, upright to a reader at
# the edge (the lower three read the right way up from below). A Star of David engraved in
# the middle, two 30 mm-radius triangles; an engraved ring 8 mm inside the rim. The bottom
# layer is a plain 330 mm disc.

thickness 4 mm

plate_d = 330 mm
dish_d = 80 mm
dish_r = 100 mm
names = ["MAROR", "BEITZAH", "KARPAS", "CHAZERET", "CHAROSET", "ZEROA"]
label = 7 mm

assembly seder {
    solid base {
        disc = Circle(center=(0, 0), diameter=plate_d)
    }
    solid top {
        disc = Circle(center=(0, 0), diameter=plate_d)
        hole dish {
            c = Circle(center=(0, dish_r), diameter=dish_d)
        }
        dishes = CircularPattern(dish, 6, disc.center)
        # FIX after the first valid program: the names (150 to 157 mm out) ran under the
        # ring at 157 mm (W0513 x 6); they now stand 6 mm outside the dishes, 146 to 153 mm.
        drawing names_ring {
            upper = Circle(center=(0, 0), radius=dish_r + dish_d / 2 + 6 mm, construction=true)
            lower = Circle(center=(0, 0), radius=dish_r + dish_d / 2 + 6 mm + label,
                           construction=true)
            for k in range(6) {
                if k == 2 or k == 3 or k == 4 {
                    n = Text(names[k], along=lower, angle=90 deg + k * 60 deg, size=label,
                             flip=true)
                } else {
                    n = Text(names[k], along=upper, angle=90 deg + k * 60 deg, size=label)
                }
            }
            rim = Circle(center=(0, 0), radius=plate_d / 2 - 8 mm)
            up = RegularPolygon(center=(0, 0), radius=30, sides=3, rotation=90 deg)
            down = RegularPolygon(center=(0, 0), radius=30, sides=3, rotation=270 deg)
        }
    }
    RightOf(top, base, gap=10)
    AlignCenterY(top, base)
    Place(base, position=(0, 0, 0))
    Place(top, position=(0, 0, 4 mm))

    assert top.disc.diameter == 330 mm and base.disc.diameter == 330 mm, "330 mm plate"
    assert len(top.dishes) == 6, "six dishes"
    assert top.dish.c.diameter == 80 mm, "80 mm dishes"
    assert distance(top.dish.c.center, top.disc.center) == 100 mm, "on a 100 mm radius"
    assert top.dish.c.center.y - top.disc.center.y == 100 mm, "the first at the top"
    assert len(top.names_ring.n) == 6, "six names"
}
