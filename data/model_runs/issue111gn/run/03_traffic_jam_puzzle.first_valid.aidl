# Request (toys): a traffic-jam sliding-block puzzle on a 6 x 6 grid of 25 mm cells.
# A 3 mm ply base 170 x 170 (R6 corners) with the grid engraved inside the play area and
# "EXIT" engraved in the exit gap; a 6 mm ply frame glued on it, the same outline, with a
# 151 x 151 window (6 x 25 mm + 1 mm play) and a 26 mm exit gap through its right wall level
# with the third row from the top. Six 6 mm ply vehicles, 24 mm wide, each 1 mm shorter than its
# cells (cars 2 cells: 49 mm, trucks 3 cells: 74 mm), R3 corners: the red car with a filled
# arrow engraved, the others with a filled letter (A, B, C cars, P, Q trucks), 12 mm sans Bold.
# Shown in a solvable start: red car row 3 cols 1-2; A vertical col 5 rows 2-3; B vertical
# col 6 rows 4-5; C row 6 cols 2-3; truck P vertical col 3 rows 2-4; truck Q row 1 cols 4-6
# (rows and columns counted from the top left, from 1).

units mm
import "std/fasteners.aidl"

cell = 25 mm
def cx_of(c) = -62.5 mm + c * cell
def cy_of(r) = 62.5 mm - r * cell

# row, col (from 0, top left), cells, vertical (1), label
specs = [[2, 0, 2, 0, "R"], [1, 4, 2, 1, "A"], [3, 5, 2, 1, "B"], [5, 1, 2, 0, "C"],
         [1, 2, 3, 1, "P"], [0, 3, 3, 0, "Q"]]

def vehicle(cells=2, vertical=false, label="A", hero=false) -> solid {
    thickness 6 mm
    body = RoundedRectangle(center=(0, 0), width=24 if vertical else cells * cell - 1 mm,
                            height=cells * cell - 1 mm if vertical else 24, corner_radius=3)
    drawing mark {
        if hero {
            arrow = Polygon([(-14, -3), (4, -3), (4, -8), (16, 0), (4, 8), (4, 3), (-14, 3)], fill=true)
        } else {
            t = Text(label, position=(0, 0), size=12, font="sans:Bold", valign="middle", fill=true)
        }
    }
}

assembly traffic_jam {
    solid base {
        thickness 3 mm
        body = RoundedRectangle(center=(0, 0), width=170, height=170, corner_radius=6)
        drawing grid {
            for k in range(7) {
                v = Line((-75 + k * cell, -75), (-75 + k * cell, 75))
                h = Line((-75, -75 + k * cell), (75, -75 + k * cell))
            }
            exit_word = Text("EXIT", position=(80.25, cy_of(2)), size=4, rotation=-90 deg, valign="middle")
        }
    }
    solid frame {
        thickness 6 mm
        body = RoundedRectangle(center=(0, 0), width=170, height=170, corner_radius=6)
        hole window { w = Rectangle(center=(0, 0), width=6 * cell + 1 mm, height=6 * cell + 1 mm) }
        hole exit { e = Rectangle(center=(80.5, cy_of(2)), width=11, height=26) }
    }
    RightOf(base, frame, gap=10)
    AlignBottom(base, frame)
    Place(base, position=(0, 0, 0), face="up")
    Place(frame, position=(0, 0, 3), face="up")

    for i in range(6) {
        s = specs[i]
        x = cx_of(s[1]) + (0 mm if s[3] == 1 else (s[2] - 1) * cell / 2)
        y = cy_of(s[0]) - ((s[2] - 1) * cell / 2 if s[3] == 1 else 0 mm)
        v = vehicle(cells=s[2], vertical=s[3] == 1, label=s[4], hero=i == 0)
        v.bb.center == (x, y)
        Place(v, position=(x, y, 3), face="up")
    }

    assert base.body.bb.width == 170 mm and base.body.bb.height == 170 mm, "base 170 x 170"
    assert frame.window.w.width == 151 mm and frame.window.w.height == 151 mm, "151 mm window"
    assert frame.exit.e.height == 26 mm, "26 mm exit gap"
    assert abs(frame.exit.e.center.y - (frame.window.w.bb.top - 0.5 mm - 2.5 * 25 mm)) < 0.01 mm, "exit level with the third row"
    assert frame.exit.e.bb.right >= frame.body.bb.right, "exit runs through the wall"
    assert frame.exit.e.bb.left <= frame.window.w.bb.right, "exit opens into the window"
    assert len(v) == 6, "six vehicles"
    assert v[0].body.bb.width == 49 mm and v[0].body.bb.height == 24 mm, "red car 49 x 24"
    assert v[4].body.bb.height == 74 mm and v[4].body.bb.width == 24 mm, "truck P 74 long, upright"
    assert v[5].body.bb.width == 74 mm, "truck Q 74 long"
    # a Placed part is read where it is written: the red car's place is y[0]
    assert abs(y[0] - frame.exit.e.center.y) < 0.01 mm, "red car in the exit row"
}
