# Request (toys): a tilting marble maze for a 10 mm steel ball, 200 x 200 mm, R8 corners,
# four layers bolted with 4 M4 screws (4.5 mm holes, 8 mm in from each edge):
# - base (6 mm ply) with 5 trap holes 13 mm across and a 14 mm goal hole at the path's end;
# - two identical maze layers (6 mm ply, stacked: 12 mm deep) with a 26 mm wide serpentine
#   channel: 4 rows 40 mm apart at y = 60, 20, -20, -60, running between x = -68 and 68,
#   starting at the top left and ending at the bottom left;
# - a clear 3 mm acrylic cover engraved "MARBLE MAZE", "START" and "GOAL".
# Each trap touches one wall of the channel, so a 13 mm way stays beside it for the ball.

units mm
thickness 6 mm

param side = 200 mm, min = 180 mm, max = 300 mm
channel = 26 mm
trap_d = 13 mm
path = [(-68, 60), (68, 60), (68, 20), (-68, 20), (-68, -20), (68, -20), (68, -60), (-68, -60)]
# each trap's centre: on a row, 6.5 mm off its middle line toward one wall
traps = [(0, 66.5), (-30, 13.5), (35, 26.5), (0, -26.5), (-30, -53.5)]

def bolted(kind_label="") -> solid {
    body = RoundedRectangle(center=(0, 0), width=side, height=side, corner_radius=8)
    hole bolt { c = Circle(center=(0, 0), diameter=4.5) }
    Fixed(body)
    bolts = CornerPattern(bolt, body, inset=8)
}

def maze_layer() -> solid {
    plate = bolted()
    hole way { band = Stroke(Polyline(path), width=channel) }
}

assembly marble_maze {
    solid base {
        plate = bolted()
        hole pits {
            for p in traps {
                t = Circle(center=p, diameter=trap_d)
            }
            goal = Circle(center=(-68, -60), diameter=14)
        }
    }
    layer_a = maze_layer()
    layer_b = maze_layer()
    solid cover {
        thickness 3 mm
        plate = bolted()
        drawing words {
            title = Text("MARBLE MAZE", position=(20, 86), size=6, valign="middle")
            start = Text("START", position=(-68, 82), size=5, valign="middle")
            goal = Text("GOAL", position=(-68, -82), size=5, valign="middle")
        }
    }

    RightOf(layer_a, base, gap=10)
    RightOf(layer_b, layer_a, gap=10)
    RightOf(cover, layer_b, gap=10)
    AlignCenterY(layer_a, base)
    AlignCenterY(layer_b, base)
    AlignCenterY(cover, base)

    assert base.plate.body.width == 200 mm and base.plate.body.height == 200 mm, "200 x 200"
    assert len(traps) == 5, "5 traps"
    assert base.pits.t[0].diameter == 13 mm, "traps 13 mm"
    assert base.pits.goal.diameter == 14 mm, "goal 14 mm"
    assert len(path) == 8, "4 rows: 8 points"
    assert path[0][1] - path[2][1] == 40 mm, "rows 40 apart"
    assert channel - trap_d >= 10 mm + 2 mm, "the ball passes a trap with room"
    assert layer_a.way.band.bb.width == 68 mm * 2 + 26 mm, "channel 26 wide between x -68 and 68"
}
