# Request (toys): an arch bridge for a wooden toy railway (the common 40 mm track), 6 mm ply.
# Deck: the track 200 long x 40 wide, two guide grooves 6 mm wide engraved filled along its whole
# length, their centres 25 mm apart (measured off my track), a female connector at the left end
# (a 12.5 mm round socket, its centre 12 mm in from the end, opened to the end by a 6.5 mm neck)
# and a male connector at the right end (an 11.5 mm round peg, its centre 13 mm beyond the end,
# on a 6 mm neck). The deck sits between two side panels on three 20 mm tabs along each long side
# (glued, into mortises). Side panels 200 long x 90 tall, top corners R5, with a half-elliptic
# arch from the bottom edge, 140 span and 45 high, the deck's mid-thickness 64 mm above the
# bottom (to meet my risers), and a parapet above the deck with five 24 x 12 windows, 38 mm
# apart, their centres 79 mm above the bottom.

units mm
thickness 6 mm

import "std/joints.aidl"

span_l = 200 mm
track_w = 40 mm
groove_w = 6 mm
groove_c = 25 mm
side_h = 90 mm
deck_y = 64 mm
arch_span = 140 mm
arch_rise = 45 mm

assembly train_bridge {
    solid deck {
        # the track plus a 6 mm tab strip each side
        body = Rectangle(center=(0, 0), width=span_l, height=track_w + 12)
        for s in [-1, 1] {
            j = tab_and_slot(part="tab", length=span_l, thickness=6 mm, tabs=3, tab=20 mm,
                             screw=0, rotation=(0 deg if s > 0 else 180 deg), cx=0,
                             cy=s * (track_w / 2 + 6))
        }
        # male connector on the right end
        solid peg {
            neck = Rectangle(center=(span_l / 2 + 4, 0), width=10, height=6)
            head = Circle(center=(span_l / 2 + 13, 0), diameter=11.5)
        }
        # female connector on the left end
        hole socket {
            neck = Rectangle(center=(-span_l / 2 + 4, 0), width=10, height=6.5)
            round = Circle(center=(-span_l / 2 + 12, 0), diameter=12.5)
        }
        drawing grooves {
            for s in [-1, 1] {
                g = Rectangle(center=(0, s * groove_c / 2), width=span_l, height=groove_w,
                              fill=true)
            }
        }
    }

    def side() -> solid {
        body = RoundedRectangle(center=(0, side_h / 2), width=span_l, height=side_h,
                                corner_radii=[5, 5, 0, 0])
        hole arch { e = Ellipse(center=(0, 0), rx=arch_span / 2, ry=arch_rise) }
        m = tab_and_slot(part="slot", length=span_l, thickness=6 mm, tabs=3, tab=20 mm,
                         screw=0, cx=0, cy=deck_y)
        for i in range(5) {
            hole window { w = Rectangle(center=((i - 2) * 38, 79), width=24, height=12) }
        }
    }
    near = side()
    far = side()

    # flat on the sheet
    Above(near, deck, gap=20)
    Above(far, near, gap=10)
    AlignLeft(near, deck)
    AlignLeft(far, deck)

    # assembled: the deck level at 61..67, the sides standing along its long edges
    Place(deck, position=(0, 0, deck_y - 3))
    Place(near, position=(0, -track_w / 2, 0), face="front", up="up")
    Place(far, position=(0, track_w / 2, 0), face="back", up="up")

    # the request's numbers
    assert deck.body.bb.width == 200 mm, "deck 200 long"
    assert deck.j[1].gap[0].bb.bottom - deck.j[0].gap[0].bb.top == 40 mm, "track 40 wide"
    assert deck.grooves.g[1].center.y - deck.grooves.g[0].center.y == 25 mm, "grooves 25 apart"
    assert deck.grooves.g[0].height == 6 mm, "grooves 6 wide"
    assert deck.peg.head.center.x - deck.body.bb.right == 13 mm, "peg 13 beyond the end"
    assert deck.socket.round.center.x - deck.body.bb.left == 12 mm, "socket 12 in"
    assert near.body.bb.width == 200 mm and near.body.bb.height == 90 mm, "sides 200 x 90"
    assert near.arch.e.rx * 2 == 140 mm and near.arch.e.ry == 45 mm, "arch 140 x 45"
    assert near.m.slot[0].bb.center_y - near.body.bb.bottom == 64 mm, "deck 64 up"
    assert near.window[1].w.center.x - near.window[0].w.center.x == 38 mm, "windows 38 apart"
    assert near.window[0].w.center.y - near.body.bb.bottom == 79 mm, "windows 79 up"
}
