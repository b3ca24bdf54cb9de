# Request (camping): a laminated tent-peg mallet glued up from 6 mm birch ply.
# - Head 110 mm long x 55 mm tall, 4 mm round corners, built from four layers (24 mm thick): two
#   plain outer cheeks and two core layers with a 30 mm wide, 35 mm deep notch up from the middle
#   of the bottom edge that the handle's end fills.
# - Handle 260 mm long x 30 mm wide, two layers glued face to face (12 mm thick, the two cores'
#   thickness), square at the top, the bottom corners rounded 14 mm, a 6 mm lanyard hole 15 mm
#   from the bottom end; its top 35 mm sits in the head's notch.
# - "TENT PEGS" engraved 7 mm tall in the middle of one cheek.

thickness 6 mm

param t = 6 mm, min = 4 mm, max = 9 mm
hl = 110 mm
hh = 55 mm
hw = 30 mm
notch = 35 mm
handle_l = 260 mm

def cheek() -> solid {
    body = RoundedRectangle(center=(0, 0), width=hl, height=hh, corner_radius=4)
}

def core() -> solid {
    body = RoundedRectangle(center=(0, 0), width=hl, height=hh, corner_radius=4)
    hole socket { r = Rectangle(bottom_left=(-hw / 2, -hh / 2 - 1), width=hw, height=notch + 1) }
}

def handle() -> solid {
    bar = RoundedRectangle(center=(0, 0), width=hw, height=handle_l, corner_radii=[0, 0, 14, 14])
    hole lanyard { c = Circle(center=(0, -handle_l / 2 + 15), diameter=6) }
}

assembly mallet {
    solid cheek_a {
        c = cheek()
        drawing label { w = Text("TENT PEGS", (0, 0), size=7, valign="middle") }
    }
    cheek_b = cheek()
    core_a = core()
    core_b = core()
    handle_a = handle()
    handle_b = handle()

    # flat for cutting
    RightOf(cheek_b, cheek_a, gap=6)
    AlignTop(cheek_b, cheek_a)
    Below(core_a, cheek_a, gap=6)
    AlignLeft(core_a, cheek_a)
    RightOf(core_b, core_a, gap=6)
    AlignTop(core_b, core_a)
    RightOf(handle_a, cheek_b, gap=6)
    AlignTop(handle_a, cheek_a)
    RightOf(handle_b, handle_a, gap=6)
    AlignTop(handle_b, handle_a)

    # glued up: cheek, core, core, cheek; the handle's two layers in the cores' notch
    hy = -hh / 2 + notch - handle_l / 2
    Place(cheek_a, position=(0, 0, 0))
    Place(core_a, position=(0, 0, t))
    Place(core_b, position=(0, 0, 2 * t))
    Place(cheek_b, position=(0, 0, 3 * t))
    Place(handle_a, position=(0, hy, t))
    Place(handle_b, position=(0, hy, 2 * t))

    # the request's numbers
    assert cheek_a.c.body.bb.width == 110 mm and cheek_a.c.body.bb.height == 55 mm, "head 110 x 55"
    assert 4 * t == 24 mm, "head 24 thick"
    assert core_a.socket.r.width == 30 mm, "notch 30 wide"
    assert core_a.socket.r.bb.top - core_a.body.bb.bottom == 35 mm, "notch 35 deep"
    assert handle_a.bar.bb.height == 260 mm and handle_a.bar.bb.width == 30 mm, "handle 260 x 30"
    assert 2 * t == 12 mm, "handle 12 thick"
    assert handle_a.lanyard.c.center.y - handle_a.bar.bb.bottom == 15 mm, "lanyard 15 from the end"
    assert handle_a.lanyard.c.diameter == 6 mm, "6 mm lanyard hole"
}
