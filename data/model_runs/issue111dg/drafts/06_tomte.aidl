# Request (holidays): a Christmas tomte (Scandinavian gnome) to stand on the windowsill,
# 3 mm poplar, glued in layers. The body is a cone-hat silhouette 160 mm tall (from the
# base's top to the hat's tip) and 104 mm wide at the bottom of its round shoulders, on two
# boots 30 x 12 with 5 mm round toes 8 mm apart; a 5-pointed star (16 mm across its tips)
# engraved filled on the hat, 40 mm below the tip. A beard layer (scalloped bottom of five
# 18 mm curls) and a 22 mm nose disc are glued on the front, the nose's centre 72 mm above
# the base. The body stands in an oval base 130 x 60 by a 30 mm tab (3 mm deep) into a
# mortise 10 mm behind the oval's centre; "GOD JUL" engraved filled (bold, 8 mm) on the
# base in front of the figure.
# FIX after the first valid program: one 30 mm tab bridged the 8 mm gap between the boots,
# which closed a window 18 x 8 under the body (note W0515) and left 0.01 mm slits at the
# boots' round toes (W0519 x2). Now each boot stands on its own 12 mm tab, centred under
# the boot, into its own mortise.

units mm
thickness 3 mm

t = 3 mm
H = 160 mm
nose_y = 72 mm

assembly tomte {
    solid body {
        shape = Hull(Circle(center=(-30, 30), radius=22), Circle(center=(30, 30), radius=22),
                     Point(0, H))
        boot_l = RoundedRectangle(bottom_left=(-34, 0), width=30, height=12, corner_radius=5)
        boot_r = RoundedRectangle(bottom_left=(4, 0), width=30, height=12, corner_radius=5)
        tab_l = Rectangle(center=(-19, -t / 2), width=12, height=t)
        tab_r = Rectangle(center=(19, -t / 2), width=12, height=t)
        drawing star {
            s = Star(center=(0, H - 40), points=5, outer_radius=8, inner_radius=3.5,
                     fill=true)
        }
    }

    solid beard {
        top = Hull(Circle(center=(-28, 40), radius=18), Circle(center=(28, 40), radius=18),
                   Circle(center=(0, nose_y), radius=10))
        for i in range(5) {
            curl = Circle(center=(-28 + i * 14, 24), diameter=18)
        }
    }

    solid nose {
        c = Circle(center=(0, nose_y), diameter=22)
    }

    solid base {
        oval = Ellipse(center=(0, 0), rx=65, ry=30)
        hole mortise {
            m_l = Rectangle(center=(-19, 10), width=12, height=t)
            m_r = Rectangle(center=(19, 10), width=12, height=t)
        }
        drawing words {
            w = Text("GOD JUL", position=(0, -14), size=8, font="sans:Bold", fill=true,
                     valign="middle")
        }
    }

    # 3D: base flat, body standing in its mortise, beard and nose glued on the front
    Place(base, position=(0, 0, 0), face="up")
    Place(body, position=(0, 10 + t / 2, t), face="front", up="up")
    Place(beard, position=(0, 10 - t / 2, t), face="front", up="up")
    Place(nose, position=(0, 10 - t / 2 - t, t), face="front", up="up")

    # flat on the sheet
    RightOf(beard, body, gap=8)
    RightOf(nose, beard, gap=8)
    Below(base, body, gap=8)
    AlignLeft(base, body)

    assert body.shape.bb.top - body.boot_l.bb.bottom == 160 mm, "160 tall above the base"
    assert body.shape.bb.width == 104 mm, "104 wide at the shoulders"
    assert body.boot_r.bb.left - body.boot_l.bb.right == 8 mm, "boots 8 apart"
    assert nose.c.diameter == 22 mm, "22 mm nose"
    assert len(beard.curl) == 5, "five curls"
    assert base.oval.bb.width == 130 mm and base.oval.bb.height == 60 mm, "base 130 x 60"
    assert base.mortise.m_l.center.y - base.oval.center.y == 10 mm, "mortise 10 behind the centre"
    assert body.shape.bb.top - body.star.s.center.y == 40 mm, "star 40 below the tip"
}
