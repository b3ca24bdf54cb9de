# Request (pets): a tabletop T-perch for a cockatiel, in 6 mm plywood, glued together.
# A round base 240 mm across; the upright post is 40 mm wide and stands 250 mm clear between
# the base and the perch bar, held by a 24 mm tenon through a mortise in the middle of the base
# and carrying the bar on a 20 mm tenon through a mortise in the bar's middle. The perch bar is
# 220 mm long x 30 mm wide with fully rounded ends and lies flat; grip lines are engraved across
# it every 10 mm, from 20 mm to 100 mm each side of the middle, 20 mm long. The base has a
# 78 mm hole for a seed cup, its centre 70 mm behind the post, and the bird's name "KIWI" in
# bold letters 14 mm tall engraved (filled) 70 mm in front of the post.
# For the assembled view: the base on the table, the post upright, the bar on top.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
base_d = 240 mm
post_w = 40 mm
post_clear = 250 mm
post_h = post_clear + 2 * t        # with a tenon at each end
bar_len = 220 mm
bar_w = 30 mm

assembly t_perch {
    solid base {
        disc = Circle(center=(0, 0), diameter=base_d)
        post_mortise = tab_and_slot(part="slot", length=post_w, thickness=t, tabs=1, tab=24,
                                    screw=0, cx=0 mm, cy=0 mm)
        hole cup {
            c = Circle(center=(0, 70), diameter=78)
        }
        drawing name {
            word = Text("KIWI", position=(0, -70), size=14, valign="middle",
                        font="sans:Bold", fill=true)
        }
    }

    solid post {
        body = Rectangle(center=(0, 0), width=post_w, height=post_h)
        foot = tab_and_slot(part="tab", length=post_w, thickness=t, tabs=1, tab=24, screw=0,
                            rotation=180 deg, cx=0 mm, cy=-post_h / 2)
        head = tab_and_slot(part="tab", length=post_w, thickness=t, tabs=1, tab=20, screw=0,
                            cx=0 mm, cy=post_h / 2)
    }

    solid bar {
        body = Slot(center=(0, 0), length=bar_len, width=bar_w)
        post_mortise = tab_and_slot(part="slot", length=post_w, thickness=t, tabs=1, tab=20,
                                    screw=0, cx=0 mm, cy=0 mm)
        drawing grip {
            g = Line((20, -10), (20, 10))
        }
        right = LinearPattern(grip, 9, (10, 0))
        axis = Line((0, -20), (0, 20), construction=true)
        left = Mirrored(right, about=axis)
    }

    RightOf(post, base, gap=10)
    AlignBottom(post, base)
    RightOf(bar, post, gap=10)
    AlignTop(bar, post)

    # assembled: (x, y, z) -> (x, -z, y) stands the post up, its foot tenon through the base
    Place(base, position=(0, 0, 0))
    Place(post, rotation=(90 deg, 0, 0), position=(0, t / 2, post_h / 2))
    Place(bar, position=(0, 0, t + post_clear))

    # the request's numbers
    assert base.disc.diameter == 240 mm, "base 240 mm across"
    assert post.body.bb.width == 40 mm, "post 40 mm wide"
    assert post.body.bb.height - 2 * 6 mm == 250 mm, "post stands 250 mm clear"
    assert base.post_mortise.slot[0].bb.width == 24 mm, "24 mm tenon into the base"
    assert bar.post_mortise.slot[0].bb.width == 20 mm, "20 mm tenon into the bar"
    assert bar.body.bb.width == 220 mm and bar.body.bb.height == 30 mm, "bar 220 x 30"
    assert len(bar.right) == 9 and len(bar.left) == 9, "grip lines 20..100 mm each side"
    assert bar.right[8].g.start.x == 100 mm, "last grip line 100 mm out"
    assert base.cup.c.diameter == 78 mm, "78 mm cup hole"
    assert base.cup.c.center.y - base.disc.center.y == 70 mm, "cup 70 mm behind the post"
    assert base.disc.center.y - base.name.word.center.y == 70 mm, "name 70 mm in front"
}
