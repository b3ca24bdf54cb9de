# Pegboard screwdriver holder, 3 mm plywood, for 1/4 in pegboard (1/4 in holes on a 1 in grid).
# Three parts: a shelf and two identical side brackets.
# Shelf: 160 x 50 mm (50 mm deep from the back edge against the board to the front), front
# corners rounded R5, back corners sharp. A row of six 10 mm screwdriver holes 20 mm apart,
# centred left-right and front-back. Two mortise slots 3.2 x 20.2 mm (for the brackets'
# tenons, 0.2 mm clearance in length) running front-back, centred front-back, their centres
# 5 in apart (on the pegboard's 1 in grid: both brackets hang in holes), centred left-right.
# (Fix: the first request put them 10 mm in from the sides, 140 mm apart: off the grid.)
# Bracket (back edge at x = 0 against the board, front toward +x): a web 60 mm tall with a
# 50 mm top edge under the shelf, a 10 mm tall front face and a diagonal down to a 12 mm foot
# at the back; a tenon 20 x 3 mm centred on the top edge. On the back edge: a top hook, a tab
# 5 mm tall, its top 5 mm below the top edge, reaching 1/4 in + 0.5 mm back through the board,
# then a 5 mm wide finger down 10 mm below the tab behind the board; and 1 in below the tab a
# straight peg 6 mm long, 5 mm tall.
# Layout for cutting: the brackets side by side 80 mm apart, the shelf above them.
units mm
thickness 3 mm

reach = 0.25 in + 0.5 mm

assembly pegboard_holder {
    solid bracket {
        web = Polygon([(0, 0), (12, 0), (50, 50), (50, 60), (0, 60)])
        tenon = Rectangle(bottom_left=(15, 60), width=20, height=3)
        tab = Rectangle(bottom_left=(-reach, 50), width=reach, height=5)
        finger = Rectangle(bottom_left=(-reach - 5, 40), width=5, height=15)
        peg = Rectangle(bottom_left=(-6, 50 - 1 in), width=6, height=5)
    }
    brackets = LinearPattern(bracket, 2, (80, 0))

    solid shelf {
        board = RoundedRectangle(center=(60, 120), width=160, height=50,
                                 corner_radii=[0, 0, 5, 5])
        hole tool {
            c = Circle(center=(60 - 50, 120), diameter=10)
        }
        tools = LinearPattern(tool, 6, (20, 0))
        hole mortise {
            left = Rectangle(center=(60 - 2.5 in, 120), width=3.2, height=20.2)
            right = Rectangle(center=(60 + 2.5 in, 120), width=3.2, height=20.2)
        }
    }

    # the request's numbers
    assert shelf.board.width == 160 mm and shelf.board.height == 50 mm, "shelf size"
    assert len(shelf.tools) == 6 and shelf.tool.c.diameter == 10 mm, "six 10 mm holes"
    assert shelf.tools[1].c.center.x - shelf.tools[0].c.center.x == 20 mm, "20 mm apart"
    assert abs((shelf.tools[0].c.center.x + shelf.tools[5].c.center.x) / 2 - shelf.board.center.x) < 0.001 mm, "centred"
    assert shelf.tool.c.center.y == shelf.board.center.y, "centred front-back"
    assert abs(shelf.mortise.right.center.x - shelf.mortise.left.center.x - 5 in) < 0.001 mm, "on the 1 in grid"
    assert abs((shelf.mortise.right.center.x + shelf.mortise.left.center.x) / 2 - shelf.board.center.x) < 0.001 mm, "slots centred"
    assert shelf.mortise.left.width == 3.2 mm and shelf.mortise.left.height == 20.2 mm, "slot size"
    assert shelf.mortise.left.height - bracket.tenon.width == 0.2 mm, "0.2 mm clearance"
    assert bracket.web.bb.height == 60 mm and bracket.web.bb.width == 50 mm, "web 60 x 50"
    assert bracket.tenon.width == 20 mm and bracket.tenon.height == 3 mm, "tenon"
    assert abs(bracket.tenon.center.x - 50 mm / 2) < 0.001 mm, "tenon centred on the top edge"
    assert bracket.web.bb.top - bracket.tab.bb.top == 5 mm and bracket.tab.height == 5 mm, "tab"
    assert abs(bracket.tab.width - (0.25 in + 0.5 mm)) < 0.001 mm, "tab reach"
    assert bracket.tab.bb.bottom - bracket.finger.bb.bottom == 10 mm, "finger 10 mm down"
    assert bracket.finger.width == 5 mm, "finger 5 mm wide"
    assert abs(bracket.tab.bb.center_y - bracket.peg.bb.center_y - 1 in) < 0.001 mm, "1 in grid"
    assert bracket.peg.width == 6 mm and bracket.peg.height == 5 mm, "peg"
    assert brackets[1].web.bb.left - bracket.web.bb.left == 80 mm, "80 mm apart"
}
