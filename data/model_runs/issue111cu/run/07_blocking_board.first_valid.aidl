# Request (crafts): a granny-square blocking board, 6 mm MDF: a 300 x 300 mm board (6 mm
# corner radii) with an 11 x 11 grid of 6.1 mm holes on a 25 mm pitch, centred, for 6 mm
# dowels to stretch squares over. Engraved guide lines halfway between the holes (10 each way,
# spanning the hole grid), a centimetre ruler along the bottom edge from 0 to 28 cm starting
# 10 mm in from the left edge (ticks every 5 mm: 8 mm long at whole cm, 4 mm at half; the
# numbers 0, 5, 10, 15, 20, 25, 4 mm tall, above their ticks), and the title "GRANNY SQUARE
# BLOCKING BOARD" 6 mm tall centred in the top margin.

thickness 6 mm

SIDE = 300 mm
N = 11
PITCH = 25 mm
grid_half = (N - 1) * PITCH / 2

solid board {
    plate = RoundedRectangle(center=(0, 0), width=SIDE, height=SIDE, corner_radius=6)
    hole peg { c = Circle(center=(-grid_half, -grid_half), diameter=6.1) }
    pegs = GridPattern(peg, N, N, PITCH)
    drawing guides {
        for k in range(N - 1) {
            across = Line((-grid_half, -grid_half + (k + 0.5) * PITCH),
                          (grid_half, -grid_half + (k + 0.5) * PITCH))
            up = Line((-grid_half + (k + 0.5) * PITCH, -grid_half),
                      (-grid_half + (k + 0.5) * PITCH, grid_half))
        }
    }
    drawing ruler {
        for i in range(57) {
            tick = Line((-SIDE / 2 + 10 mm + i * 5 mm, -SIDE / 2),
                        (-SIDE / 2 + 10 mm + i * 5 mm, -SIDE / 2 + (8 mm if i % 2 == 0 else 4 mm)))
        }
        for j in range(6) {
            num = Text(str(j * 5), position=(-SIDE / 2 + 10 mm + j * 50 mm, -SIDE / 2 + 10 mm),
                       size=4, valign="bottom")
        }
    }
    drawing title {
        t = Text("GRANNY SQUARE BLOCKING BOARD", position=(0, (SIDE / 2 + grid_half) / 2),
                 size=6, valign="middle")
    }
    Fixed(plate)

    assert plate.bb.width == 300 mm and plate.bb.height == 300 mm, "300 x 300"
    assert len(pegs) == 121, "11 x 11 holes"
    assert pegs[1].c.center.x - pegs[0].c.center.x == 25 mm, "25 mm pitch"
    assert pegs[11].c.center.y - pegs[0].c.center.y == 25 mm, "25 mm pitch in rows"
    assert pegs[0].c.diameter == 6.1 mm, "6.1 mm holes"
    assert (pegs[0].c.center.x + pegs[120].c.center.x) / 2 == plate.center.x, "grid centred"
    assert len(guides.across) == 10 and len(guides.up) == 10, "10 guide lines each way"
    assert ruler.tick[0].start.x - plate.bb.left == 10 mm, "ruler 10 mm in"
    assert ruler.tick[56].start.x - ruler.tick[0].start.x == 280 mm, "0 to 28 cm"
    assert ruler.tick[2].end.y - ruler.tick[2].start.y == 8 mm, "whole cm 8 mm"
    assert ruler.tick[1].end.y - ruler.tick[1].start.y == 4 mm, "half cm 4 mm"
}
