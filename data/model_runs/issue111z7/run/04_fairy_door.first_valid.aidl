# Garden: a fairy door to lean on a tree trunk, 4 mm plywood, 80 mm wide and 120 mm tall:
# straight sides 80 mm tall and a round top (R40). A four-pane window 22 x 22 mm (panes
# 10 x 10 mm, 2 mm bars) centred 85 mm up; a 6 mm knob hole 10 mm in from the right edge,
# 50 mm up. Engraved: a frame line 5 mm inside the edge, vertical plank lines every 16 mm
# inside the frame (stopping 2 mm under the window), and two hinge straps 16 x 5 mm on the
# left edge, their bottoms 20 mm and 65 mm up.

thickness 4 mm

param door_w = 80 mm, min = 50 mm, max = 150 mm
param side_h = 80 mm, min = 50 mm, max = 150 mm

r = door_w / 2
frame = 5 mm
window_y = 85 mm
plank_x = [-24 mm, -8 mm, 8 mm, 24 mm]

def plank_top(x) = (window_y - 11 mm - 2 mm if abs(x) < 13 mm
                    else side_h + sqrt((r - frame) ** 2 - x ** 2))

solid door {
    outline = Hull(Rectangle(bottom_left=(-r, 0), width=door_w, height=side_h),
                   Circle(center=(0, side_h), radius=r))

    hole window {
        pane = Rectangle(center=(-6 mm, window_y - 6 mm), width=10 mm, height=10 mm)
    }
    panes = GridPattern(window, 2, 2, (12 mm, 12 mm))

    hole knob {
        c = Circle(center=(r - 10 mm, 50 mm), diameter=6 mm)
    }

    drawing engraving {
        inner = Hull(Rectangle(bottom_left=(-r + frame, frame), width=door_w - 2 * frame,
                               height=side_h - frame),
                     Circle(center=(0, side_h), radius=r - frame))
        for x in plank_x {
            plank = Line((x, frame), (x, plank_top(x)))
        }
        for y in [20 mm, 65 mm] {
            strap = Rectangle(bottom_left=(-r, y), width=16 mm, height=5 mm)
        }
    }

    assert outline.bb.width == 80 mm, "80 mm wide"
    assert outline.bb.height == 120 mm, "120 mm tall"
    assert len(panes) == 4, "four panes"
    assert panes[0].pane.width == 10 mm, "10 mm panes"
    assert panes[1].pane.bb.left - panes[0].pane.bb.right == 2 mm, "2 mm bars"
    assert (panes[0].bb.bottom + panes[3].bb.top) / 2 == 85 mm, "window centred 85 mm up"
    assert outline.bb.right - knob.c.center.x == 10 mm and knob.c.center.y == 50 mm, "knob"
    assert knob.c.diameter == 6 mm, "6 mm knob hole"
}
