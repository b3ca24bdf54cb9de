# Request: a desk tensegrity "floating table" for the science club, 6 mm ply, four parts
# and fishing line. Two identical 120 x 120 mm plates (6 mm corners) with a 2.5 mm string
# hole 10 mm in from each corner; two identical inverted-L arms: a 20 mm post standing
# 110 mm above its plate and a 20 mm high bar at its top reaching 60 mm from the post's
# centre, with a 2.5 mm hook hole 45 mm from the post's centre and 14 mm below the top.
# Each arm is glued into its plate by one 12 mm tab, the post's centre 45 mm from the
# plate's middle. The top half is the bottom half upside down, turned round, its plate's
# underside 168 mm up, so its hook hangs 30 mm below the bottom hook. "TENSEGRITY"
# engraved on the bottom plate in front of the post.

import "std/joints.aidl"

thickness 6 mm

def plate(word="") -> solid {
    body = RoundedRectangle(center=(0, 0), width=120, height=120, corner_radius=6)
    hole strings {
        a = Circle(center=(-50, -50), diameter=2.5)
        b = Circle(center=(50, -50), diameter=2.5)
        c = Circle(center=(50, 50), diameter=2.5)
        d = Circle(center=(-50, 50), diameter=2.5)
    }
    post_mortise = tab_and_slot(part="slot", length=20 mm, thickness=6 mm, tabs=1, tab=12 mm,
                                screw=0, rotation=90 deg, cx=0 mm, cy=45 mm)
    drawing label {
        t = Text(word, (0, -30), size=9)
    }
}

def arm() -> solid {
    post = Rectangle(bottom_left=(-10, -6), width=20, height=116)   # 6 mm tab + 110 up
    bar = Rectangle(bottom_left=(-10, 90), width=70, height=20)      # to 60 from the centre
    foot = tab_and_slot(part="tab", length=20 mm, thickness=6 mm, tabs=1, tab=12 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=-6 mm)
    hole hook { c = Circle(center=(45, 96), diameter=2.5) }
}

assembly tensegrity {
    base = plate(word="TENSEGRITY")
    top = plate()
    lower_arm = arm()
    upper_arm = arm()

    # flat on the sheet
    RightOf(top, base, gap=8)
    AlignBottom(top, base)
    Below(lower_arm, base, gap=8)
    AlignLeft(lower_arm, base)
    RightOf(upper_arm, lower_arm, gap=8)
    AlignBottom(upper_arm, lower_arm)

    # in 3D: the base on the desk, its arm's post at y = +45 reaching toward -y; the top
    # half upside down, post at y = -45, plate underside at z = 168
    Place(base, position=(0, 0, 0))
    Place(lower_arm, position=(3, 45, 6), rotation=(90 deg, 0, -90 deg))
    Place(top, position=(0, 0, 174), rotation=(180 deg, 0, 0))
    Place(upper_arm, position=(3, -45, 168), rotation=(-90 deg, 0, 90 deg))

    assert base.body.bb.width == 120 mm and base.body.bb.height == 120 mm, "plates 120"
    assert lower_arm.post.bb.top - lower_arm.foot.bb.top == 110 mm, "post 110 above the plate"
    assert lower_arm.bar.bb.right - lower_arm.post.bb.center_x == 60 mm, "bar reaches 60"
    assert lower_arm.hook.c.center.x - lower_arm.post.bb.center_x == 45 mm, "hook at 45"
    assert lower_arm.bar.bb.top - lower_arm.hook.c.center.y == 14 mm, "hook 14 below the top"
    assert base.strings.c.center.x - base.body.bb.right == -10 mm, "string holes 10 in"
    # the hooks: bottom at 6 + 110 - 14, top at 168 - 110 + 14: 30 mm of string
    assert (6 mm + 110 mm - 14 mm) - (168 mm - 110 mm + 14 mm) == 30 mm, "hooks 30 apart"
}
