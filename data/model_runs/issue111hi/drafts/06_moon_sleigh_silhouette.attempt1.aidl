# Request (holidays): a Christmas window silhouette in 3 mm black acrylic, one
# piece: a crescent moon 280 mm across (a 140 mm disc bitten by a 125 mm circle
# whose centre is 60 mm right of and 30 mm above the moon's), with Santa in his
# sleigh crossing the lower part of the crescent and one reindeer leaping ahead
# of him through the bitten-out part, joined to the sleigh by a 3 mm harness.
# The sleigh has a curled front, a sack at the back and a runner on two struts;
# the reindeer has a body, neck, head, antlers, four legs 4 mm thick and a
# tail. A 6 mm hole near the top of the crescent takes a suction-cup hook.

thickness 3 mm

solid silhouette {
    solid moon {
        disc = Circle(center=(0, 0), radius=140)
        hole bite {
            c = Circle(center=(60, 30), radius=125)
        }
    }

    solid sleigh {
        body = Spline([(-100, -8), (-98, -40), (-85, -48), (-35, -48), (-18, -38), (-12, -20),
                       (-20, -12), (-28, -22), (-45, -30), (-70, -28), (-78, -12), (-90, -5)],
                      closed=true, corners=[0, 11])
        runner = Stroke(Spline([(-108, -58), (-60, -58), (-15, -58), (0, -50), (2, -40), (-6, -36)]),
                        width=3)
        strut_back = Stroke(Line((-85, -46), (-85, -58)), width=3)
        strut_front = Stroke(Line((-40, -46), (-40, -58)), width=3)
        sack = Circle(center=(-95, -5), radius=12)
        santa_body = Ellipse(center=(-72, -15), rx=12, ry=16)
        santa_head = Circle(center=(-72, 6), radius=8)
        hat = Polygon([(-81, 10), (-63, 10), (-58, 24)])
    }

    solid reindeer {
        body = Ellipse(center=(75, 25), rx=28, ry=11, rotation=15)
        neck = Stroke(Line((95, 32), (110, 50)), width=9)
        head = Ellipse(center=(116, 54), rx=10, ry=6, rotation=-20)
        antler_a = Stroke(Polyline([(110, 58), (104, 74), (96, 82)]), width=3)
        antler_b = Stroke(Line((105, 70), (112, 80)), width=3)
        fore_a = Stroke(Polyline([(95, 25), (110, 15), (122, 20)]), width=4)
        fore_b = Stroke(Polyline([(90, 20), (100, 8), (112, 6)]), width=4)
        hind_a = Stroke(Polyline([(55, 18), (40, 10), (28, 12)]), width=4)
        hind_b = Stroke(Polyline([(58, 20), (48, 5), (36, 0)]), width=4)
        tail = Circle(center=(48, 22), radius=5)
    }

    harness = Stroke(Line((-15, -25), (70, 22)), width=3)

    hole hang {
        c = Circle(center=(-55, 115), diameter=6)
    }

    assert moon.disc.diameter == 280 mm, "moon 280 mm across"
    assert harness.bb.width > 0 mm, "the harness is there"
    assert distance(hang.c.center, moon.disc.center) + 3 mm <= 140 mm - 8 mm, "hook hole 8 mm in from the rim"
    assert distance(hang.c.center, moon.bite.c.center) - 3 mm >= 125 mm + 8 mm, "hook hole 8 mm clear of the bite"
    assert self.bb.width <= 300 mm and self.bb.height <= 300 mm, "fits a 300 mm window pane"
}
