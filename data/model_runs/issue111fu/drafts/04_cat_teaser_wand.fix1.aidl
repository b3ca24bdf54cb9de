# Request: a cat teaser wand, two parts.
# - Wand, 6 mm birch ply, 450 mm long overall: a handle 120 x 30 mm with 8 mm rounded corners
#   at the butt, an 8 mm hanging hole centred 15 mm from the butt end; a shaft tapering from
#   22 mm wide where it leaves the handle to 12 mm at the rounded tip; a 4 mm cord hole
#   centred 8 mm from the tip; the inside corners where the shaft leaves the handle rounded
#   6 mm. The cat's name "MOUSER" engraved on the handle, 12 mm letters, kept 3 mm clear of
#   the hanging hole.
# - Fish lure, 3 mm ply: an oval body 80 x 36 mm with a V tail 26 mm long and 36 mm tall
#   (notched 8 mm), a 5 mm eye hole, a 4 mm cord hole 6 mm from the nose, and three rows of
#   engraved scale arcs (6 mm radius, 8 mm apart) kept 3 mm clear of the eye.

units mm

assembly teaser {
    solid wand {
        thickness 6 mm
        handle = RoundedRectangle(bottom_left=(0, -15), width=120, height=30, corner_radius=8)
        shaft = Polygon([(110, -11), (444, -6), (444, 6), (110, 11)])
        tip = Circle(center=(444, 0), radius=6)
        hole hang { c = Circle(center=(15, 0), diameter=8) }
        hole cord { c = Circle(center=(442, 0), diameter=4) }
        # where the shaft crosses the handle's rounded corners (both sides)
        Fillet([handle, shaft], 6)
        drawing name {
            t = Text("MOUSER", position=(67, 0), size=12, valign="middle")
        }
        Fixed(handle)
        assert wand.bb.width == 450 mm, "450 mm overall"
        assert handle.width == 120 mm and handle.height == 30 mm, "handle 120 x 30"
        assert hang.c.center.x - handle.bb.left == 15 mm, "hanging hole 15 mm from the butt"
        assert tip.bb.right - cord.c.center.x == 8 mm, "cord hole 8 mm from the tip"
        assert shaft.points[3].y - shaft.points[0].y == 22 mm, "shaft 22 mm at the handle"
        assert tip.diameter == 12 mm, "12 mm at the tip"
        assert distance(name, hang) >= 3 mm, "name clear of the hanging hole"
        assert name.bb.right <= handle.bb.right, "name on the handle"
    }

    solid fish {
        thickness 3 mm
        body = Ellipse(center=(0, 0), rx=40, ry=18)
        tail = Polygon([(-36, 0), (-62, 18), (-54, 0), (-62, -18)])
        hole eye { c = Circle(center=(24, 4), diameter=5) }
        hole cord { c = Circle(center=(34, 0), diameter=4) }
        drawing scales {
            for r in range(3) {
                for k in range(4) {
                    # FIX after the first valid program: the scales' free edges face the
                    # tail (they faced the nose) and the field is centred on the body
                    s = Arc(center=(-14 + k * 8 + (r % 2) * 4, (r - 1) * 8), radius=6,
                            start_angle=110 deg, end_angle=250 deg)
                }
            }
        }
        Fixed(body)
        assert body.rx * 2 == 80 mm and body.ry * 2 == 36 mm, "body 80 x 36"
        assert body.bb.left - tail.bb.left == 22 mm, "tail 26 long from where it leaves the body's end"
        assert tail.bb.height == 36 mm, "tail 36 tall"
        assert body.bb.right - cord.c.center.x == 6 mm, "cord hole 6 mm from the nose"
        assert distance(scales, eye) >= 3 mm, "scales clear of the eye"
        assert scales.bb.top <= 14 mm and scales.bb.bottom >= -14 mm, "scales inside the body"
    }
    RightOf(fish, wand, gap=10)
    AlignCenterY(fish, wand)
}
