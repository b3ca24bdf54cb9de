# Request (holidays): a stand that shows off one special Christmas bauble (up to 80 mm) on the
# sideboard. 6 mm ply, glued.
# - An upright shaped like a shepherd's crook: a post 20 mm wide flaring to a 60 mm foot (the
#   flare 50 mm high), its crook a half circle of 30 mm radius (centre line) so the bauble hangs
#   from a 4 mm hole at the crook's end, 60 mm out from the post's centre; the crook's top
#   210 mm above the base.
# - A brace 60 mm wide x 40 mm high crossing the upright's foot at right angles (cross halving,
#   20 mm each).
# - A round base 130 mm across, its centre 30 mm out under the crook; upright and brace stand in
#   it on two 10 mm tenons each.
# - "MERRY CHRISTMAS" engraved round the front of the base, 6 mm serif, reading from the front.

import "std/joints.aidl"

thickness 6 mm
t = 6 mm

post_w = 20 mm
foot_w = 60 mm
crook_r = 30 mm
post_h = 170 mm     # where the crook starts, above the base

assembly ornament_stand {
    solid base {
        disc = Circle(center=(crook_r, 0), diameter=130)
        upright_mortise = tab_and_slot(part="slot", length=foot_w, thickness=t, tabs=2, tab=10,
                                       screw=0, rotation=0 deg, cx=0, cy=0)
        brace_mortise = tab_and_slot(part="slot", length=foot_w, thickness=t, tabs=2, tab=10,
                                     screw=0, rotation=90 deg, cx=0, cy=0)
        drawing greeting {
            ring = Circle(center=(crook_r, 0), radius=52, construction=true)
            words = Text("MERRY CHRISTMAS", along=ring, size=6, font="serif", flip=true)
        }
    }

    solid upright {
        tenon_strip = Rectangle(bottom_left=(-foot_w / 2, -t), width=foot_w, height=t)
        foot = Trapezoid(center=(0, 25), bottom_width=foot_w, top_width=post_w, height=50)
        post = Rectangle(bottom_left=(-post_w / 2, 0), width=post_w, height=post_h)
        crook = ArcSlot(center=(crook_r, post_h), radius=crook_r, start_angle=0 deg,
                        end_angle=180 deg, width=post_w)
        hole hang { c = Circle(center=(2 * crook_r, post_h), diameter=4) }
        tenons = tab_and_slot(part="tab", length=foot_w, thickness=t, tabs=2, tab=10, screw=0,
                              rotation=180 deg, cx=0, cy=-t)
        halving = cross_halving(depth=20 mm, thickness=t, rotation=180 deg, cx=0, cy=0)
    }

    solid brace {
        body = Rectangle(bottom_left=(-foot_w / 2, -t), width=foot_w, height=40 + t)
        tenons = tab_and_slot(part="tab", length=foot_w, thickness=t, tabs=2, tab=10, screw=0,
                              rotation=180 deg, cx=0, cy=-t)
        halving = cross_halving(depth=20 mm, thickness=t, cx=0, cy=40)
    }

    # flat on the sheet
    RightOf(upright, base, gap=5)
    AlignBottom(upright, base)
    RightOf(brace, upright, gap=5)
    AlignBottom(brace, base)

    # assembled: base flat, the upright in the x-z plane, the brace across it in the y-z plane
    Place(base, position=(0, 0, 0))
    Place(upright, position=(0, t / 2, t), face="front", up="up")
    Place(brace, position=(-t / 2, 0, t), face="right", up="up")

    assert upright.crook.bb.top - upright.post.bb.bottom == 210 mm, "crook top 210 above the base"
    assert upright.hang.c.center.x - upright.post.bb.center_x == 60 mm, "bauble 60 out"
    assert upright.post.bb.width == 20 mm, "post 20 wide"
    assert upright.foot.bb.width == 60 mm and upright.foot.bb.height == 50 mm, "foot 60, flare 50"
    assert base.disc.diameter == 130 mm, "base 130"
    assert base.disc.center.x - base.upright_mortise.bb.center_x == 30 mm, "base 30 out"
    assert brace.body.bb.width == 60 mm and brace.body.bb.height - t == 40 mm, "brace 60 x 40"
    # an 80 mm bauble on a 15 mm hook clears the post
    assert upright.hang.c.center.x - 40 mm - upright.post.bb.right >= 5 mm, "bauble clears post"
}
