# Request (crafts): a wall hanger for a finished quilt, 6 mm birch ply, cut on a 900 x 600 mm
# bed, so the 1200 mm back board is made of two 600 mm halves joined in the middle by a
# glued flat sliding dovetail (2 tails, 12 mm deep, 10 deg, 0.1 mm clearance).
# - Back board 1200 x 90 mm, its four outer corners rounded R20. Two keyholes (10 mm head,
#   5 mm shank, 12 mm long, pointing up) 300 mm either side of the middle, 68 mm up.
# - The quilt's top edge is pinched under two clamp bars 580 x 40 mm (R6 corners), level with
#   the board's bottom edge, 10 mm either side of the middle joint and 10 mm in from the
#   board's ends. Each bar has two M5 clearance holes 20 mm up, 150 mm and 450 mm from the
#   middle; the board has M5 nut traps (hex nuts glued in) behind them, for M5 thumb screws.
# - On the bars, engraved filled (serif bold italic, 16 mm), centred between each bar's
#   bolts: "Made with love" on the left, "by Nan · 2026" on the right.

import "std/joints.aidl"
import "std/fasteners.aidl"
import "std/plates.aidl"

thickness 6 mm

t = 6 mm

half_len = 600 mm
board_h = 90 mm
tail_d = 12 mm
bar_len = 580 mm
bar_h = 40 mm
bolt_y = 20 mm
bolt_x = [150 mm, 450 mm]
quilt = 5 mm

assembly hanger {
    solid back_l {
        body = RoundedRectangle(bottom_left=(-half_len, 0), width=half_len, height=board_h,
                                corner_radii=[20, 0, 0, 20])
        band = Rectangle(bottom_left=(0, 0), width=tail_d, height=board_h)
        tails = dovetail(part="tail", length=board_h, depth=tail_d, tails=2, angle=10 deg,
                         rotation=-90 deg, cx=0, cy=board_h / 2)
        hang = keyhole(head=10 mm, slot_width=5 mm, length=12 mm, cx=-300 mm, cy=68 mm)
        for i in range(2) {
            nut = nut_trap(size=5, cx=-bolt_x[i], cy=bolt_y)
        }
        Fixed(body)
    }
    solid back_r {
        body = RoundedRectangle(bottom_left=(0, 0), width=half_len, height=board_h,
                                corner_radii=[0, 20, 20, 0])
        sockets = dovetail(part="socket", length=board_h, depth=tail_d, tails=2, angle=10 deg,
                           clearance=0.1 mm, rotation=-90 deg, cx=0, cy=board_h / 2)
        hang = keyhole(head=10 mm, slot_width=5 mm, length=12 mm, cx=300 mm, cy=68 mm)
        for i in range(2) {
            nut = nut_trap(size=5, cx=bolt_x[i], cy=bolt_y)
        }
        Fixed(body)
    }
    solid bar_l {
        body = RoundedRectangle(bottom_left=(-half_len + 10 mm, 0), width=bar_len, height=bar_h,
                                corner_radius=6)
        for i in range(2) {
            bolt = clearance_hole(size=5, cx=-bolt_x[i], cy=bolt_y)
        }
        drawing words {
            t = Text("Made with love", position=(-(bolt_x[0] + bolt_x[1]) / 2, bolt_y), size=16,
                     font="serif:Bold Italic", valign="middle", fill=true)
        }
        Fixed(body)
    }
    solid bar_r {
        body = RoundedRectangle(bottom_left=(10 mm, 0), width=bar_len, height=bar_h,
                                corner_radius=6)
        for i in range(2) {
            bolt = clearance_hole(size=5, cx=bolt_x[i], cy=bolt_y)
        }
        drawing words {
            t = Text("by Nan · 2026", position=((bolt_x[0] + bolt_x[1]) / 2, bolt_y), size=16,
                     font="serif:Bold Italic", valign="middle", fill=true)
        }
        Fixed(body)
    }

    # flat on the sheet
    RightOf(back_r, back_l, gap=10)
    AlignBottom(back_r, back_l)
    Below(bar_l, back_l, gap=10)
    AlignLeft(bar_l, back_l)
    RightOf(bar_r, bar_l, gap=10)
    AlignBottom(bar_r, bar_l)

    # assembled: the wall at y = +6 mm, the quilt 5 mm thick between board and bars
    Place(back_l, position=(0, t, 0), face="front", up="up")
    Place(back_r, position=(0, t, 0), face="front", up="up")
    Place(bar_l, position=(0, -quilt, 0), face="front", up="up")
    Place(bar_r, position=(0, -quilt, 0), face="front", up="up")
    AllowOverlap(back_l, back_r)

    # the request's numbers (as written, in the hanger's frame)
    assert back_r.body.bb.right - back_l.body.bb.left == 1200 mm, "board 1200 long"
    assert back_l.body.bb.width == 600 mm and back_r.body.bb.width == 600 mm, "two 600 halves"
    assert back_l.body.bb.height == 90 mm, "board 90 high"
    assert back_l.band.bb.width == 12 mm, "tails 12 deep"
    assert bar_l.body.bb.width == 580 mm and bar_l.body.bb.height == 40 mm, "bars 580 x 40"
    assert bar_r.body.bb.left - back_r.body.bb.left == 10 mm, "bar 10 from the joint"
    assert back_r.body.bb.right - bar_r.body.bb.right == 10 mm, "bar 10 from the end"
    assert bar_l.body.bb.left - back_l.body.bb.left == 10 mm, "bar 10 from the end"
    assert back_l.body.bb.right - bar_l.body.bb.right == 10 mm, "bar 10 from the joint"
    assert bar_r.bolt[0].c.center.x == back_r.nut[0].hex.center.x, "bolt over its nut"
    assert bar_r.bolt[1].c.center.x == back_r.nut[1].hex.center.x, "bolt over its nut"
    assert bar_l.bolt[1].c.center.x == back_l.nut[1].hex.center.x, "bolt over its nut"
    assert bar_r.bolt[1].c.center.x - back_r.body.bb.left == 450 mm, "bolt 450 from the middle"
    assert bar_r.bolt[0].c.center.y - bar_r.body.bb.bottom == 20 mm, "bolts 20 up"
    assert back_r.hang.head_hole.center.x - back_r.body.bb.left == 300 mm, "keyholes 300 out"
    assert back_r.hang.head_hole.center.y - back_r.body.bb.bottom == 68 mm, "keyholes 68 up"
    assert back_r.hang.bb.bottom >= bar_r.body.bb.top + 5 mm, "keyholes above the bars"
    assert back_r.hang.bb.top <= back_r.body.bb.top - 3 mm, "keyholes inside the board"
    assert distance(bar_l.words, bar_l.bolt) >= 8 mm, "words clear of the thumb screws"
    assert distance(bar_r.words, bar_r.bolt) >= 8 mm, "words clear of the thumb screws"
    assert bar_r.words.bb.height <= bar_h - 6 mm, "words within the bar"
}
