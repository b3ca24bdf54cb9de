# Request: a birthday rosette badge for my daughter's 7th party, three layers of 3 mm acrylic
# glued together. Back (pink): a scalloped rosette, a 76 mm disc edged with 16 scallops 18 mm
# across on a 72 mm circle (90 mm across the scallops), with pleat marks engraved between the
# scallops, and two ribbon tails 22 mm wide hanging down from the middle to 95 mm, splayed 15 deg
# either side of straight down, each ending in a swallowtail notch 10 mm deep. Middle (white):
# a 60 mm disc with "BIRTHDAY GIRL" engraved round its top, 4 mm letters. Front (gold mirror):
# the age as a bold number 26 mm tall (at most 40 mm wide for two digits), glued in the middle.
# A brooch pin is glued on the back.

import "std/plates.aidl"

thickness 3 mm

param age = 7, min = 1, max = 99

tail_len = 95 mm
tail_w = 22 mm
splay = 15 deg

def tail(a) -> solid {
    band = Polygon([
        (20 mm * cos(a) - tail_w / 2 * sin(a), 20 mm * sin(a) + tail_w / 2 * cos(a)),
        (tail_len * cos(a) - tail_w / 2 * sin(a), tail_len * sin(a) + tail_w / 2 * cos(a)),
        ((tail_len - 10 mm) * cos(a), (tail_len - 10 mm) * sin(a)),
        (tail_len * cos(a) + tail_w / 2 * sin(a), tail_len * sin(a) - tail_w / 2 * cos(a)),
        (20 mm * cos(a) + tail_w / 2 * sin(a), 20 mm * sin(a) - tail_w / 2 * cos(a))])
}

assembly rosette {
    solid back {
        disc = Circle(center=(0, 0), diameter=76 mm)
        solid scallop { c = Circle(center=(36 mm, 0), diameter=18 mm) }
        scallops = CircularPattern(scallop, 16, disc.center)
        left_tail = tail(a=-90 deg - splay)
        right_tail = tail(a=-90 deg + splay)
        drawing pleats {
            mark = Line((31 mm * cos(11.25 deg), 31 mm * sin(11.25 deg)),
                        (40 mm * cos(11.25 deg), 40 mm * sin(11.25 deg)))
            marks = CircularPattern(mark, 16, (0, 0))
        }
    }

    solid middle {
        disc = Circle(center=(0, 0), diameter=60 mm)
        words = text_on_arc(text="BIRTHDAY GIRL", radius=23 mm, size=4 mm, angle=90 deg)
    }

    solid number {
        n = Text(str(age), position=(0, 0), size=26 mm, font="sans:Bold", valign="middle",
                 max_width=40 mm)
    }

    # flat for cutting, each colour its own sheet
    Fixed(back)
    RightOf(middle, back, gap=10 mm)
    RightOf(number, middle, gap=10 mm)
    AlignCenterY(middle, back.disc)
    AlignCenterY(number, back.disc)

    # glued up: back, middle on it, the number on top
    Place(back, position=(0, 0, 0))
    Place(middle, position=(0, 0, 3 mm))
    Place(number, position=(0, 0, 6 mm))

    assert len(back.scallops) == 16, "16 scallops"
    assert back.scallop.c.diameter == 18 mm, "18 mm scallops"
    assert back.disc.diameter == 76 mm and middle.disc.diameter == 60 mm, "disc sizes"
    assert number.n.size == 26 mm and number.bb.width <= 40 mm, "number 26 mm tall, <= 40 wide"
    assert back.disc.center.y - back.bb.bottom <= tail_len, "tails reach 95 mm down at most"
}
