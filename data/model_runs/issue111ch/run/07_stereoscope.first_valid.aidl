# Request (science): a hand-held stereoscope for the school's stereo view cards (178 x 89 mm),
# 3 mm ply, glued tabs. A lens board 180 mm wide and 110 mm tall with two 24.6 mm holes to
# press in 25 mm lenses (f = 100 mm), 63 mm apart, their centres 50 mm up, and a nose notch
# 44 mm wide and 24 mm high in the middle of its bottom edge (bottom corners rounded 8 mm).
# A card holder 190 x 110 mm whose face stands 100 mm behind the lens board's face, the card
# centred on the lenses, held by four 45-degree corner slits cutting 12 mm off each of the
# card's corners (running 1 mm past its edges). A septum between the eyes, 70 mm long behind
# the lens board and 80 mm tall, up from 30 mm. A top rail 50 mm wide overhanging the boards
# by 10 mm joins everything: the boards each put one 20 mm tab up through it, the septum two
# 15 mm tabs; the septum also puts two 15 mm tabs through the lens board. "STEREOSCOPE"
# engraved along the rail in 6 mm letters, 12 mm right of its centre line.

import "std/joints.aidl"

units mm
thickness 3 mm

t = 3 mm
H = 110 mm          # the boards' height to the rail's underside
eye = 63 mm         # between the lenses' centres
lens_z = 50 mm
view = 100 mm       # from the lens board's face to the card
sep_len = 70 mm + t # the septum from the lens board's face back
sep_bottom = 30 mm
rail_w = 50 mm
over = 10 mm
depth = view + t    # from the lens board's face to the holder's back

solid_h = H + t

def lens_board() -> solid {
    body = Rectangle(center=(0, solid_h / 2), width=180, height=solid_h)
    hole lenses {
        l = Circle(center=(-eye / 2, lens_z), diameter=24.6)
        r = Circle(center=(eye / 2, lens_z), diameter=24.6)
    }
    hole nose {
        e = Ellipse(center=(0, 0), rx=22, ry=24)
    }
    top_t = tab_and_slot(part="tab", length=180, thickness=t, tabs=1, tab=20 mm, screw=0,
                         rotation=0, cx=0, cy=solid_h)
    septum_m = tab_and_slot(part="slot", length=H - sep_bottom, thickness=t, tabs=2, tab=15 mm,
                            screw=0, rotation=90 deg, cx=0, cy=(sep_bottom + H) / 2)
    Fillet(body.bottom_left, 8)
    Fillet(body.bottom_right, 8)
}

def card_holder() -> solid {
    body = Rectangle(center=(0, solid_h / 2), width=190, height=solid_h)
    top_t = tab_and_slot(part="tab", length=190, thickness=t, tabs=1, tab=20 mm, screw=0,
                         rotation=0, cx=0, cy=solid_h)
    corners = [(1, 1), (-1, 1), (-1, -1), (1, -1)]
    cut slits {
        for i in range(4) {
            s = Line((corners[i][0] * 76, lens_z + corners[i][1] * 45.5),
                     (corners[i][0] * 90, lens_z + corners[i][1] * 31.5))
        }
    }
    Fillet(body.bottom_left, 8)
    Fillet(body.bottom_right, 8)
}

def septum() -> solid {
    body = Rectangle(bottom_left=(0, sep_bottom), width=sep_len, height=solid_h - sep_bottom)
    front_t = tab_and_slot(part="tab", length=H - sep_bottom, thickness=t, tabs=2, tab=15 mm,
                           screw=0, rotation=90 deg, cx=0, cy=(sep_bottom + H) / 2)
    top_t = tab_and_slot(part="tab", length=sep_len, thickness=t, tabs=2, tab=15 mm, screw=0,
                         rotation=0, cx=sep_len / 2, cy=solid_h)
}

def rail() -> solid {
    body = RoundedRectangle(bottom_left=(-rail_w / 2, -over), width=rail_w,
                            height=depth + 2 * over, corner_radius=5)
    front_m = tab_and_slot(part="slot", length=180, thickness=t, tabs=1, tab=20 mm, screw=0,
                           rotation=0, cx=0, cy=t / 2)
    back_m = tab_and_slot(part="slot", length=190, thickness=t, tabs=1, tab=20 mm, screw=0,
                          rotation=0, cx=0, cy=depth - t / 2)
    septum_m = tab_and_slot(part="slot", length=sep_len, thickness=t, tabs=2, tab=15 mm, screw=0,
                            rotation=90 deg, cx=0, cy=sep_len / 2)
    drawing name {
        n = Text("STEREOSCOPE", (12, depth / 2), size=6, rotation=90, valign="middle")
    }
}

assembly stereoscope {
    lens = lens_board()
    holder = card_holder()
    sep = septum()
    top = rail()

    # flat on the sheet
    RightOf(holder, lens, gap=10)
    AlignBottom(holder, lens)
    Below(sep, lens, gap=10)
    AlignLeft(sep, lens)
    RightOf(top, sep, gap=10)
    AlignTop(top, sep)

    # in 3D: x across, y from the lens board's face back, z up
    Place(lens, rotation=(90 deg, 0, 0), position=(0, t, 0))
    Place(holder, rotation=(90 deg, 0, 0), position=(0, depth, 0))
    Place(sep, rotation=(90 deg, 0, 90 deg), position=(-t / 2, 0, 0))
    Place(top, position=(0, 0, H))

    assert lens.lenses.r.center.x - lens.lenses.l.center.x == 63 mm, "lenses 63 apart"
    assert lens.lenses.l.diameter == 24.6 mm, "24.6 mm lens holes"
    assert lens.lenses.l.center.y - lens.body.bb.bottom == 50 mm, "lenses 50 up"
    assert lens.nose.e.bb.width == 44 mm and lens.nose.e.bb.top - lens.body.bb.bottom == 24 mm, "nose 44 x 24"
    assert depth - t - 0 mm == 100 mm, "card 100 mm behind the lens board's face"
    assert len(holder.slits.s) == 4, "four corner slits"
    # the slit's end runs 1 mm past the card's right edge, so read it where it crosses that edge
    assert abs(holder.slits.s[0].end.y + (holder.slits.s[0].end.x - 178 mm / 2) - (lens_z + 89 mm / 2 - 12 mm)) < 0.001 mm, "12 mm off the corner"
    assert sep_len - t == 70 mm and H - sep_bottom == 80 mm, "septum 70 x 80"
    assert top.body.bb.width == 50 mm and top.body.bb.height == depth + 20 mm, "rail 50 wide, 10 over"
}
