# Request: a golf divot repair tool with a ball marker, cut from 4 mm acrylic (2 parts). The
# tool is 70 mm long from the top of its round 30 mm head to the prong tips: a body tapering
# from the head to two prongs 30 mm long, 8 mm wide at the root (centres 14 mm apart) and
# 3 mm wide at the rounded tips (centres 12 mm apart); every corner rounded 1.5 mm. A 12.6 mm
# hole in the middle of the head takes a 12.7 mm magnet pressed in. Below the head a small
# golf flag is engraved (a 10 mm pole and a filled pennant). The ball marker is a 24 mm disc
# engraved with the golfer's initials "JM" (filled bold, 10 mm); it sits on the magnet by a
# steel washer glued under it.

thickness 4 mm

HEAD_D = 30 mm
LEN = 70 mm
PRONG = 30 mm

assembly divot_kit {
    solid tool {
        body = Hull(Circle(center=(0, LEN - HEAD_D / 2), diameter=HEAD_D),
                    Circle(center=(-7, PRONG), radius=4),
                    Circle(center=(7, PRONG), radius=4))
        left = Hull(Circle(center=(-7, PRONG), radius=4), Circle(center=(-6, 1.5), radius=1.5))
        right = Hull(Circle(center=(7, PRONG), radius=4), Circle(center=(6, 1.5), radius=1.5))
        hole magnet {
            c = Circle(center=(0, LEN - HEAD_D / 2), diameter=12.6 mm)
        }
        drawing flag {
            pole = Line((-2, 29), (-2, 39))
            pennant = Triangle((-2, 39), (-2, 35), (4, 37), fill=true)
        }
        Fillet(1.5 mm)

        assert body.bb.top - left.bb.bottom == 70 mm, "70 mm long"
        assert body.bb.width == 30 mm, "30 mm head"
        assert magnet.c.diameter == 12.6 mm, "12.6 mm magnet hole"
        assert PRONG - left.bb.bottom == 30 mm, "30 mm prongs (root centre to tip)"
        assert flag.pole.length == 10 mm, "10 mm pole"
    }

    solid marker {
        disc = Circle(center=(0, 0), diameter=24 mm)
        drawing initials {
            t = Text("JM", position=(0, 0), size=10, font="sans:Bold", fill=true, valign="middle")
        }
        assert disc.diameter == 24 mm, "24 mm marker"
    }

    RightOf(marker, tool, gap=6)
    AlignTop(marker, tool)

    Place(tool, position=(0, 0, 0))
    Place(marker, position=(0, LEN - HEAD_D / 2, 4 mm))
}
