# L shelf bracket, cut flat from 6 mm plywood: a vertical wall arm 120 x 20 mm
# and a horizontal shelf arm 100 x 20 mm meeting at the top-left corner, and a
# 12 mm wide diagonal gusset from the wall arm's center line 20 mm above its
# bottom to the shelf arm's center line 10 mm from its tip. Two 4.5 mm
# countersunk screw holes in each arm: in the wall arm 25 mm and 75 mm below
# the top, in the shelf arm 40 mm and 65 mm from the wall side.

thickness 6 mm

solid bracket {
    shelf = Rectangle(center=(50, -10), width=100, height=20)
    wall = Rectangle(center=(10, -60), width=20, height=120)
    At(wall.top_left, shelf.top_left)

    gusset = Slot(start=(10, -100), end=(90, -10), width=12)
    At(gusset.start, wall.bottom_left, dx=10, dy=20)
    At(gusset.end, shelf.bottom_right, dx=-10, dy=10)

    hole wall_screws {
        a = Circle(center=(10, -25), diameter=4.5)
        b = Circle(center=(10, -75), diameter=4.5)
    }
    hole shelf_screws {
        a = Circle(center=(40, -10), diameter=4.5)
        b = Circle(center=(65, -10), diameter=4.5)
    }
    At(wall_screws.a.center, wall.top_left, dx=10, dy=-25)
    At(wall_screws.b.center, wall.top_left, dx=10, dy=-75)
    At(shelf_screws.a.center, shelf.top_left, dx=40, dy=-10)
    At(shelf_screws.b.center, shelf.top_left, dx=65, dy=-10)
    Countersink([wall_screws, shelf_screws], diameter=9 mm)
    AllowOverlap(shelf, wall, gusset)  # the triangular window inside the gusset is meant

    assert wall.bb.height == 120 mm and shelf.bb.width == 100 mm, "arm lengths"
    assert self.bb.width == 100 mm and self.bb.height == 120 mm, "overall L size"
}
