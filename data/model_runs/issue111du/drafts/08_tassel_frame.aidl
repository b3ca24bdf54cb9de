# Request (gifts): a graduation tassel display for Amara, cut from 4 mm ply. An upright plaque
# 240 x 150 mm with R10 corners, glued into a base 240 x 70 mm (R6 corners) by two 20 mm tabs
# in mortises along the base's middle. The year 2027 cut through the plaque as a stencil, 40 mm
# tall; CLASS OF above it (12 mm bold, filled) and AMARA OKAFOR below it (9 mm, filled), the
# block of text centred 25 mm right of the plaque's middle. The tassel hangs on a peg 65 mm left
# of the middle, 110 mm up: the peg sticks out 25 mm, is 10 mm tall, has a 5 mm upturned lip at
# its end (so the loop cannot slide off), and an 8 mm tall tenon through a mortise in the plaque.
# The tassel (20 mm wide) must hang clear of the text.

import "std/joints.aidl"

thickness 4 mm

param t = 4 mm, min = 3 mm, max = 6 mm
plaque_w = 240 mm
plaque_h = 150 mm
text_x = 25 mm
peg_x = -65 mm
peg_y = 110 mm
tassel_w = 20 mm

assembly tassel_frame {
    solid plaque {
        board = RoundedRectangle(bottom_left=(-plaque_w / 2, 0), width=plaque_w, height=plaque_h,
                                 corner_radius=10)
        # the tabs: material 4 mm below the board's bottom edge, cut to two tabs
        tab_strip = Rectangle(bottom_left=(-plaque_w / 2 + 10, -t), width=plaque_w - 20, height=t)
        tabs = tab_and_slot(part="tab", length=plaque_w - 20, thickness=t, tabs=2, tab=20 mm,
                            screw=0, rotation=180 deg, cx=0, cy=-t)
        hole year { y = Text("2027", position=(text_x, 55), size=40, font="sans:Bold",
                             valign="middle", stencil=true) }
        hole peg_mortise { r = Rectangle(center=(peg_x, peg_y), width=t, height=8) }
        drawing words {
            top = Text("CLASS OF", position=(text_x, 95), size=12, font="sans:Bold",
                       valign="middle", fill=true)
            name = Text("AMARA OKAFOR", position=(text_x, 18), size=9, font="sans",
                        valign="middle", fill=true)
        }
    }

    solid base {
        board = RoundedRectangle(center=(0, 0), width=plaque_w, height=70, corner_radius=6)
        mortises = tab_and_slot(part="slot", length=plaque_w - 20, thickness=t, tabs=2,
                                tab=20 mm, screw=0, cx=0, cy=0)
    }

    solid peg {
        # x: forward from the plaque's front face; y: up from the mortise's middle
        p = Polygon([(-t, -4), (0, -4), (0, -5), (25, -5), (25, 10), (20, 10), (20, 5), (0, 5),
                     (0, 4), (-t, 4)])
        Fillet([p.points[4], p.points[5]], 2)
    }

    # flat on the sheet
    Below(base, plaque, gap=10)
    AlignLeft(base, plaque)
    RightOf(peg, base, gap=10)
    AlignTop(peg, base)

    # assembled
    Place(base, position=(0, 0, 0))
    Place(plaque, position=(0, t / 2, t), face="front", up="up")
    Place(peg, position=(peg_x + t / 2, -t / 2, t + peg_y), face="left", up="up")

    assert plaque.board.width == 240 mm and plaque.board.height == 150 mm, "plaque 240 x 150"
    assert base.board.width == 240 mm and base.board.height == 70 mm, "base 240 x 70"
    assert plaque.year.y.size == 40 mm, "year 40 mm tall"
    assert peg.p.bb.right == 25 mm and peg.p.bb.height == 15 mm, "peg 25 out, 10 tall + 5 lip"
    assert plaque.peg_mortise.r.center.y - plaque.board.bb.bottom == 110 mm, "peg 110 mm up"
    assert (plaque.year.bb.left - (peg_x + tassel_w / 2) > 10 mm and
            plaque.words.bb.left - (peg_x + tassel_w / 2) > 10 mm), "the tassel hangs clear"
    assert len(base.mortises.slot) == 2, "two mortises"
}
