# Sport: the number ring round a 340 mm dartboard, 3 mm black acrylic.
# A ring 460 mm across outside, 342 mm across inside (1 mm clearance round the board).
# The 20 numbers in dartboard order, 20 at the top then clockwise 1, 18, 4, 13, 6, 10, 15,
# 2, 17, 3, 19, 7, 16, 8, 11, 14, 9, 12, 5, each centred on its sector's middle (18 deg
# apart) at radius 198 mm, upright, sans Bold 24 mm tall, engraved filled.
# Four 5 mm screw holes countersunk 10 mm at radius 198, at 45, 135, 225 and 315 deg
# (between the numbers).

units mm
thickness 3 mm

numbers = [20, 1, 18, 4, 13, 6, 10, 15, 2, 17, 3, 19, 7, 16, 8, 11, 14, 9, 12, 5]

solid ring {
    rim = Circle(center=(0, 0), diameter=460)
    hole board {
        c = Circle(center=(0, 0), diameter=342)
    }
    Concentric(board.c, rim)

    drawing digits {
        for i in range(20) {
            t = Text(str(numbers[i]), position=polar((0, 0), 198, 90 deg - i * 18 deg), size=24,
                     font="sans:Bold", valign="middle", fill=true)
        }
    }

    hole screw {
        c = Circle(center=polar((0, 0), 198, 45 deg), diameter=5)
    }
    screws = CircularPattern(screw, 4, rim.center)
    Countersink(screws, diameter=10)

    assert rim.diameter == 460 mm and board.c.diameter == 342 mm, "ring 460 / 342"
    assert len(digits.t) == 20, "20 numbers"
    assert distance(digits.t[0].position, rim.center) == 198 mm, "numbers at R198"
    assert distance(screw.c.center, rim.center) == 198 mm, "screws at R198"
    assert len(screws) == 4, "four screws"
}
