# Request (gifts): a wooden baby play gym for a new nephew, 9 mm birch ply. Two A-frames
# 560 mm tall, 500 mm across the feet, 50 mm flat on top, legs and bottom rail about
# 45 mm wide (the opening is the outline 45 mm in, cut off 400 mm up, corners rounded
# 15 mm). A top bar 700 x 60 mm on edge passes through a 9.3 x 60.3 mm mortise in each
# frame, centred 470 mm up; the frames stand 600 mm apart (centre to centre). Each end of
# the bar is locked by a flat wedge (9 mm, 60 mm long, 15 mm tapering to 9 mm, straight on
# the frame side) pushed through a 14 x 10 mm slot whose inner end is 1 mm inside the
# frame's face. Three 8 mm ribbon holes along the bar, 150 mm apart, 12 mm above its
# bottom edge, and "NOAH" (bold sans, 30 mm, filled) engraved on the bar's middle.
# Three hanging toys, each with a 5 mm ribbon hole: a five-point star 90 mm across the
# tips (inner radius 20, tips rounded 4 mm), a crescent moon from an 80 mm disc, and a
# cloud of three bumps on a rounded base 96 mm wide.

units mm
thickness 9 mm

T = 9 mm
FRAME_X = 300 mm
BAR_Z = 440 mm      # the bar's bottom edge above the floor
BAR_L = 700 mm

def a_frame() -> solid {
    outer = Polygon([(-250, 0), (250, 0), (25, 560), (-25, 560)])
    hole opening {
        w = Intersect(Inset(Polygon([(-250, 0), (250, 0), (25, 560), (-25, 560)]), 45,
                            join="miter"),
                      Rectangle(bottom_left=(-300, 0), width=600, height=400))
        Fillet(15)
    }
    hole mortise {
        m = Rectangle(center=(0, BAR_Z + 30), width=T + 0.3, height=60.3)
    }
}

def wedge() -> solid {
    w = Polygon([(0, -30), (15, -30), (9, 30), (0, 30)])
}

assembly play_gym {
    left = a_frame()
    right = a_frame()
    solid bar {
        body = Rectangle(bottom_left=(-BAR_L / 2, 0), width=BAR_L, height=60)
        hole slots {
            r = Rectangle(bottom_left=(FRAME_X + T / 2 - 1, 25), width=14, height=10)
            l = Rectangle(bottom_left=(-(FRAME_X + T / 2 - 1) - 14, 25), width=14, height=10)
        }
        hole ribbons {
            for k in range(3) {
                c = Circle(center=((k - 1) * 150, 12), diameter=8)
            }
        }
        drawing name {
            t = Text("NOAH", position=(0, 38), size=30, font="sans:Bold", valign="middle",
                     fill=true)
        }
        Fixed(body)
    }
    wedge_l = wedge()
    wedge_r = wedge()
    solid star {
        s = Star(center=(0, 0), points=5, outer_radius=45, inner_radius=20, tip_radius=4)
        hole hang { c = Circle(center=(0, 25), diameter=5) }
    }
    solid moon {
        disc = Circle(center=(0, 0), diameter=80)
        hole bite { c = Circle(center=(18, 8), radius=34) }
        hole hang { c = Circle(center=(-20, 28), diameter=5) }
    }
    solid cloud {
        a = Circle(center=(-28, 0), radius=20)
        b = Circle(center=(0, 12), radius=26)
        c = Circle(center=(28, 0), radius=20)
        base = RoundedRectangle(center=(0, -8), width=96, height=24, corner_radius=12)
        hole hang { h = Circle(center=(0, 28), diameter=5) }
    }

    # flat on the sheet
    RightOf(right, left, gap=10)
    AlignBottom(right, left)
    Below(bar, left, gap=10)
    AlignLeft(bar, left)
    RightOf(star, right, gap=10)
    AlignTop(star, right)
    Below(moon, star, gap=10)
    AlignLeft(moon, star)
    Below(cloud, moon, gap=10)
    AlignLeft(cloud, moon)
    Below(wedge_l, cloud, gap=10)
    AlignLeft(wedge_l, cloud)
    RightOf(wedge_r, wedge_l, gap=10)
    AlignTop(wedge_r, wedge_l)

    # standing: frames face left and right, the bar on edge through them
    Place(left, position=(-(FRAME_X - T / 2), 0, 0), face="left", up="up")
    Place(right, position=(FRAME_X - T / 2, 0, 0), face="right", up="up")
    Place(bar, position=(0, T / 2, BAR_Z), face="front", up="up")
    # wedges lie flat in the slots, straight side on the frames' outer faces
    Place(wedge_r, position=(FRAME_X + T / 2, 10, BAR_Z + 25), face="up")
    Place(wedge_l, position=(-(FRAME_X + T / 2), -10, BAR_Z + 25), face="up", up="front")
    # toys hang under the ribbon holes
    Place(moon, position=(-150, T / 2, 300), face="front", up="up")
    Place(star, position=(0, T / 2, 280), face="front", up="up")
    Place(cloud, position=(150, T / 2, 300), face="front", up="up")

    assert left.outer.bb.height == 560 mm and left.outer.bb.width == 500 mm, "frame size"
    assert BAR_L == 700 mm and bar.body.bb.height == 60 mm, "bar size"
    assert left.mortise.m.width == 9.3 mm and left.mortise.m.height == 60.3 mm, "mortise"
    assert left.mortise.m.center.y - left.outer.bb.bottom == 470 mm, "mortise 470 up"
    assert 2 * FRAME_X == 600 mm, "frames 600 apart"
    assert bar.slots.r.bb.left == FRAME_X + T / 2 - 1 mm, "slot 1 mm inside the face"
    assert bar.slots.r.width == 14 mm and bar.slots.r.height == 10 mm, "slot size"
    assert bar.body.bb.right - bar.slots.r.bb.right >= 25 mm, "end grain past the slot"
    assert bar.ribbons.c[1].center.x - bar.ribbons.c[0].center.x == 150 mm, "ribbons 150"
    assert bar.ribbons.c[0].center.y - bar.body.bb.bottom == 12 mm, "ribbons 12 up"
    assert distance(bar.name, bar.ribbons) >= 3 mm, "name clear of the holes"
    assert bar.name.bb.top <= bar.body.bb.top - 3 mm, "name on the bar"
    assert BAR_Z >= 400 mm, "bar high over the baby"
    assert star.s.outer_radius * 2 == 90 mm, "star 90"
    assert moon.disc.diameter == 80 mm, "moon 80"
    assert cloud.base.bb.width == 96 mm, "cloud 96"
    assert distance(star.hang, moon.hang) >= 0 mm, "toys have holes"
}
