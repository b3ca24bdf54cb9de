# Board-game spinner, 3 mm plywood, two parts. The dial: a 100 mm disc with a 4 mm center
# hole, split into six equal sectors by engraved lines from 7 mm to 40 mm out from the
# center (one line pointing straight up); the numbers 1 to 6 engraved 10 mm tall, upright,
# centered 28 mm out in the middle of each sector, counting clockwise from the top right; a
# rim band of six engraved arcs at radius 45 mm, one per sector, each stopping 5 deg short of
# the dividing lines. The pointer: 70 mm long overall, a 10 mm wide bar with a round tail and
# a triangular head 20 mm wide and 18 mm long at the tip end, a 4.5 mm pivot hole on its axis
# 25 mm from the tail. The pointer laid 5 mm right of the dial.
units mm
thickness 3 mm

param sectors = 6, min = 2, max = 12
step = 360 deg / sectors

assembly spinner {
    solid dial {
        disc = Circle(center=(0, 0), diameter=100)
        hole pivot {
            c = Circle(center=(0, 0), diameter=4)
        }
        drawing marks {
            for k in range(sectors) {
                div = Line(polar((0, 0), 7, 90 deg + k * step), polar((0, 0), 40, 90 deg + k * step))
                num = Text(str(k + 1), position=polar((0, 0), 28, 90 deg - (k + 0.5) * step),
                           size=10, valign="middle")
                rim = Arc(center=(0, 0), radius=45, start_angle=90 deg + k * step + 5 deg,
                          end_angle=90 deg + (k + 1) * step - 5 deg)
            }
        }
        Concentric(pivot.c, disc)
    }

    solid pointer {
        bar = Slot(start=(5, 0), end=(54, 0), width=10)
        head = Triangle(center=(61, 0), base=20, height=18, rotation=-90 deg)
        hole pin {
            c = Circle(center=(25, 0), diameter=4.5)
        }
    }
    LeftOf(dial, pointer, gap=5)
    AlignCenterY(pointer, dial)

    assert dial.disc.diameter == 100 mm, "dial 100 mm"
    assert dial.pivot.c.diameter == 4 mm, "4 mm center hole"
    assert len(dial.marks.div) == 6 and len(dial.marks.num) == 6 and len(dial.marks.rim) == 6, "six sectors"
    assert dial.marks.div[0].length == 33 mm, "lines from 7 to 40 mm"
    assert dial.marks.num[0].size == 10 mm, "numbers 10 mm"
    assert dial.marks.rim[0].radius == 45 mm, "rim arcs at 45 mm"
    assert pointer.bb.width == 70 mm, "pointer 70 mm long"
    assert pointer.head.bb.height == 20 mm and pointer.head.bb.width == 18 mm, "head 20 wide, 18 long"
    assert pointer.bar.width == 10 mm, "bar 10 mm wide"
    assert pointer.pin.c.center.x - pointer.bb.left == 25 mm, "pivot 25 mm from the tail"
    assert pointer.pin.c.diameter == 4.5 mm, "4.5 mm pivot hole"
    assert pointer.bb.left - dial.bb.right == 5 mm, "laid 5 mm apart"
}
