# Request (gifts): "A pair of interlocking jigsaw-piece keyrings for an anniversary, one for each of
# us, from 3 mm walnut ply (laser kerf 0.15 mm). Each piece is a 45 mm square with R3 corners.
# Knobs are a 12 mm round head on a 6 mm neck, the head's centre 8 mm beyond the edge; sockets are
# the same shape 0.1 mm larger all round, the head's centre 8 mm inside the edge. Piece A: a knob
# on its right edge (it locks into piece B's left socket), a socket in its top edge, a knob on its
# bottom edge; ANNA and 2021 fill-engraved; a 5 mm key-ring hole in its top left corner. Piece B:
# a socket in its left edge, a knob on its top edge, a socket in its bottom edge; TOM and 2021
# engraved; the key-ring hole in its top right corner. Engravings at least 2 mm from any hole or
# socket and from the piece's edge. Show the two pieces locked together."

thickness 3 mm
kerf 0.15 mm
S = 45 mm
head = 12 mm
neck = 6 mm
reach = 8 mm       # head centre beyond (knob) or inside (socket) the edge
fit = 0.1 mm
ring = 5 mm

assembly pair {
    solid a {
        body = RoundedRectangle(center=(0, 0), width=S, height=S, corner_radius=3)
        # knob on the right edge
        r_neck = Rectangle(corner=(S / 2 - 1 mm, -neck / 2), opposite=(S / 2 + reach, neck / 2))
        r_head = Circle(center=(S / 2 + reach, 0), diameter=head)
        # knob on the bottom edge
        b_neck = Rectangle(corner=(-neck / 2, -S / 2 + 1 mm), opposite=(neck / 2, -S / 2 - reach))
        b_head = Circle(center=(0, -S / 2 - reach), diameter=head)
        # socket in the top edge
        hole t_sock {
            n = Rectangle(corner=(-neck / 2 - fit, S / 2 + 1 mm), opposite=(neck / 2 + fit, S / 2 - reach))
            h = Circle(center=(0, S / 2 - reach), diameter=head + 2 * fit)
        }
        hole key {
            c = Circle(center=(-S / 2 + 7.5 mm, S / 2 - 7.5 mm), diameter=ring)
        }
        drawing words {
            name = Text("ANNA", position=(0, -3), size=7, font="sans:Bold", valign="middle", fill=true)
            year = Text("2021", position=(0, -13), size=4, font="sans:Bold", valign="middle", fill=true)
        }
    }

    solid b {
        body = RoundedRectangle(center=(0, 0), width=S, height=S, corner_radius=3)
        # knob on the top edge
        t_neck = Rectangle(corner=(-neck / 2, S / 2 - 1 mm), opposite=(neck / 2, S / 2 + reach))
        t_head = Circle(center=(0, S / 2 + reach), diameter=head)
        # socket in the left edge: piece A's knob locks in here
        hole l_sock {
            n = Rectangle(corner=(-S / 2 - 1 mm, -neck / 2 - fit), opposite=(-S / 2 + reach, neck / 2 + fit))
            h = Circle(center=(-S / 2 + reach, 0), diameter=head + 2 * fit)
        }
        # socket in the bottom edge
        hole b_sock {
            n = Rectangle(corner=(-neck / 2 - fit, -S / 2 - 1 mm), opposite=(neck / 2 + fit, -S / 2 + reach))
            h = Circle(center=(0, -S / 2 + reach), diameter=head + 2 * fit)
        }
        hole key {
            c = Circle(center=(S / 2 - 7.5 mm, S / 2 - 7.5 mm), diameter=ring)
        }
        drawing words {
            name = Text("TOM", position=(0, 10), size=7, font="sans:Bold", valign="middle", fill=true)
            year = Text("2021", position=(0, 0), size=4, font="sans:Bold", valign="middle", fill=true)
        }
    }

    # FIX after the first valid program: W0531 (from `aidl render`, not `aidl check`): drawn locked
    # together, the two parts share A's right edge, so the kerf round each eats into the other.
    # Flat: the parts 10 mm apart for cutting; locked together in the assembled view by Place.
    RightOf(b, a, gap=10)
    AlignCenterY(b.body, a.body)
    Place(a, position=(0, 0, 0))
    Place(b, position=(S, 0, 0))

    # the request's numbers
    assert a.body.width == 45 mm and b.body.height == 45 mm, "45 mm squares"
    assert a.r_head.diameter == 12 mm and a.r_neck.bb.height == 6 mm, "12 mm head on a 6 mm neck"
    assert a.r_head.center.x - a.body.bb.right == 8 mm, "knob head 8 mm beyond the edge"
    assert b.body.bb.left + 8 mm == b.l_sock.h.center.x, "socket head 8 mm inside the edge"
    assert b.l_sock.h.diameter - a.r_head.diameter == 2 * 0.1 mm, "socket 0.1 larger all round"
    assert b.l_sock.n.bb.height - a.r_neck.bb.height == 2 * 0.1 mm, "socket neck 0.1 larger all round"
    assert (a.r_head.center.x - a.body.center.x) - (b.l_sock.h.center.x - b.body.center.x) == S, "A's knob sits in B's socket when B is placed 45 mm to the right"
    assert a.r_head.center.y - a.body.center.y == b.l_sock.h.center.y - b.body.center.y, "knob and socket level"
    assert b.body.bb.left - a.r_head.bb.right >= 0.15 mm, "flat: the parts apart by more than the kerf"
    assert a.key.c.diameter == 5 mm and b.key.c.diameter == 5 mm, "5 mm key-ring holes"
    assert a.key.c.center.x < a.body.center.x and a.key.c.center.y > a.body.center.y, "A's hole top left"
    assert b.key.c.center.x > b.body.center.x and b.key.c.center.y > b.body.center.y, "B's hole top right"
    # engravings clear of holes, sockets and edges
    assert distance(a.words, a.t_sock) >= 2 mm and distance(a.words, a.key) >= 2 mm, "A's words clear"
    assert a.words.bb.left - a.body.bb.left >= 2 mm and a.words.bb.bottom - a.body.bb.bottom >= 2 mm, "A's words off the edge"
    assert distance(b.words, b.l_sock) >= 2 mm and distance(b.words, b.b_sock) >= 2 mm, "B's words clear of the sockets"
    assert distance(b.words, b.key) >= 2 mm, "B's words clear of the key-ring hole"
    assert b.body.bb.top - b.words.bb.top >= 2 mm and b.body.bb.right - b.words.bb.right >= 2 mm, "B's words off the edge"
    assert distance(a.key, a.t_sock) >= 2 mm and distance(b.key, b.body.bb.top_right) >= 2 mm, "rings clear"
}
