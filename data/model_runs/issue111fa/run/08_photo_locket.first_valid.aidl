# Request: a swivel photo locket as a gift, three hearts of 3 mm cherry ply glued and
# pinned. Each heart 40 mm wide and 38 mm tall (two R11 lobes 18 mm apart, their centres
# 5 mm above the middle, a point 22 mm below it).
# - Back: the heart plus a bail on top (a 6 mm neck to a R5 ring 24 mm above the middle,
#   a 2.5 mm chain hole in it); "2026" engraved (5 mm single stroke) on its outside face,
#   centred 4 mm below the middle.
# - Middle: the heart with a round 22 mm photo opening centred 2 mm below the middle.
# - Front (the cover): the heart with "A + J" engraved filled, serif italic 7 mm, centred
#   6 mm below the middle; it turns on a 2 mm brass pin to uncover the photo.
# The pin goes through all three, at the upper left lobe as seen from the front: 12 mm left
# of and 9 mm above the middle. At least 3 mm of wood round the pin hole.

thickness 3 mm

assembly locket {
    solid back {
        left = Hull(Circle(center=(-9, 5), radius=11), Point(0, -22))
        right = Hull(Circle(center=(9, 5), radius=11), Point(0, -22))
        neck = Rectangle(center=(0, 16), width=6, height=12)
        ring = Circle(center=(0, 24), radius=5)
        hole chain {
            c = Circle(center=(0, 24), diameter=2.5)
        }
        # seen from the front the pin is at (-12, 9); the back is turned face down (its
        # engraving outward), so in its own drawing the pin is at (+12, 9)
        hole pin {
            c = Circle(center=(12, 9), diameter=2)
        }
        drawing year {
            t = Text("2026", position=(0, -4), size=5, valign="middle")
        }
        Rigid(self)
    }

    solid middle {
        left = Hull(Circle(center=(-9, 5), radius=11), Point(0, -22))
        right = Hull(Circle(center=(9, 5), radius=11), Point(0, -22))
        hole photo {
            c = Circle(center=(0, -2), diameter=22)
        }
        hole pin {
            c = Circle(center=(-12, 9), diameter=2)
        }
        Rigid(self)
    }

    solid front {
        left = Hull(Circle(center=(-9, 5), radius=11), Point(0, -22))
        right = Hull(Circle(center=(9, 5), radius=11), Point(0, -22))
        hole pin {
            c = Circle(center=(-12, 9), diameter=2)
        }
        drawing initials {
            t = Text("A + J", position=(0, -6), size=7, font="serif:Italic", valign="middle",
                     fill=true)
        }
        Rigid(self)
    }

    RightOf(middle, back, gap=4)
    AlignBottom(middle, back)
    RightOf(front, middle, gap=4)
    AlignBottom(front, middle)

    # stacked, seen from above (the front): the back face down so its year reads from behind
    Place(back, position=(0, 0, 3), face="down", up="back")
    Place(middle, position=(0, 0, 3), face="up")
    Place(front, position=(0, 0, 6), face="up")

    assert front.right.bb.right - front.left.bb.left == 40 mm, "40 wide"
    assert front.left.bb.top - front.left.bb.bottom == 38 mm, "38 tall"
    # the middle: 5 mm under the lobes' centres, 11 + 5 under a lobe's top
    assert back.ring.center.y - (back.left.bb.top - 11 mm - 5 mm) == 24 mm, "ring 24 above the middle"
    assert sqrt((12 - 9) ** 2 + (9 - 5) ** 2) * 1 mm + 2 mm / 2 + 3 mm <= 11 mm, "3 mm of wood round the pin"
    assert middle.photo.c.diameter == 22 mm, "22 mm photo"
    assert distance(middle.pin, middle.photo) >= 3 mm, "3 mm between pin and photo"
    assert front.initials.bb.width <= 24 mm, "initials fit the cover"
}
