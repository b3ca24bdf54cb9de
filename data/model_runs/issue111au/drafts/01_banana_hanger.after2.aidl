# Request: a banana hanger for the kitchen worktop, cut from 6 mm birch plywood,
# two parts. The base is a disc 150 mm across. The upright is a post 70 mm wide
# at its foot tapering to 24 mm at its top, where it curls forward into a hook
# 16 mm wide with a round opening 40 mm across for the banana stem; the top of
# the hook stands 280 mm above the base. The upright stands in the base on two
# glued tabs 20 mm wide (through the 6 mm base) in matching slots, placed so the
# hook's opening hangs straight over the middle of the disc. "BANANAS" is
# engraved up the post.

import "std/joints.aidl"

units mm
thickness 6 mm

param ply = 6 mm, min = 3 mm, max = 9 mm
param base_d = 150 mm, min = 120 mm, max = 220 mm
param foot_w = 70 mm, min = 50 mm, max = 100 mm
param top_w = 24 mm, min = 18 mm, max = 40 mm
param band = 16 mm, min = 10 mm, max = 24 mm
param opening = 40 mm, min = 30 mm, max = 60 mm
param tall = 280 mm, min = 200 mm, max = 350 mm

hook_r = opening / 2 + band / 2          # radius of the hook band's centre line
post_h = tall - hook_r - band / 2        # the straight post, base to hook centre

assembly banana_hanger {
    solid base {
        disc = Circle(center=(0, 0), diameter=base_d)
        # slots for the upright's tabs: its foot's middle is one hook radius
        # behind the disc's centre, so the hook's opening is over the centre
        slots = tab_and_slot(part="slot", length=foot_w, thickness=ply, tabs=2,
                             tab=20 mm, screw=0, cx=-hook_r, cy=0 mm)
    }

    solid upright {
        post = Trapezoid(center=(0, post_h / 2), bottom_width=foot_w, top_width=top_w,
                         height=post_h)
        # the strip below the shoulder that becomes the two tabs
        foot = Rectangle(center=(0, -ply / 2), width=foot_w, height=ply)
        tabs = tab_and_slot(part="tab", length=foot_w, thickness=ply, tabs=2,
                            tab=20 mm, screw=0, rotation=180 deg, cx=0 mm, cy=-ply)
        # the hook curls forward (+x) from the post's top and down again
        hook = ArcSlot(center=(hook_r, post_h), radius=hook_r, start_angle=-40 deg,
                       end_angle=180 deg, width=band)
        drawing label {
            word = Text("BANANAS", position=(0, post_h * 0.45), size=12, rotation=90,
                        valign="middle")
        }
        # FIX after the first valid program: Fillet(3) rounded every corner,
        # the tabs' inside corners too (the shoulder would stand 3 mm proud of
        # the base); round only the neck where the hook leaves the post
        Fillet([hook, post], 1.9)   # W0406: the 4 mm ledge leaves room for 1.9
        Fillet([post.top_left, post.top_right], 1)
    }

    RightOf(upright, base, gap=20)

    assert base.disc.diameter == 150 mm, "base is 150 mm across"
    assert upright.post.bottom_width == 70 mm, "post is 70 mm wide at the foot"
    assert upright.post.top_width == 24 mm, "post is 24 mm wide at the top"
    assert upright.hook.width == 16 mm, "hook band is 16 mm wide"
    assert 2 * upright.hook.radius - upright.hook.width == 40 mm, "hook opening 40 mm"
    assert upright.hook.bb.top - upright.post.bb.bottom == 280 mm, "hook top 280 mm above the base"
    assert upright.foot.bb.bottom == upright.post.bb.bottom - 6 mm, "tabs go through the 6 mm base"
}
