# Request (crafts): a flat tatting shuttle in acrylic, glued from three layers. Two lens-shaped
# plates 72 mm tip to tip and 24 mm wide at the middle (each side an arc of 60 mm radius),
# 1.5 mm acrylic, the tips rounded with a 1.5 mm radius; between them a post, an ellipse
# 16 x 8 mm in 2 mm acrylic, so the thread winds round the post and the tips stay 2 mm apart.
# A 1.5 mm hole through the middle of all three layers to tie the thread on. Both plates have an
# engraved line 2 mm inside their edge; the top plate also has the initials "E.B." engraved
# 4 mm tall (single stroke) 6 mm to the left of the middle hole... centred at x = -20 mm on the
# long axis. Assembled in 3D.

thickness 1.5 mm

param tip_to_tip = 72 mm, min = 55 mm, max = 90 mm
param waist = 24 mm, min = 16 mm, max = 32 mm
# the two arcs: radius r about (0, +-d), with r - d = waist / 2 and r^2 - d^2 = (tip_to_tip / 2)^2
arc_r = ((tip_to_tip / 2) ** 2 / (waist / 2) + waist / 2) / 2
arc_d = arc_r - waist / 2

def plate(initials="") -> solid {
    lens = Intersect(Circle(center=(0, arc_d), radius=arc_r), Circle(center=(0, -arc_d), radius=arc_r))
    hole tie { c = Circle(center=(0, 0), diameter=1.5) }
    drawing trim {
        edge = Inset(Intersect(Circle(center=(0, arc_d), radius=arc_r),
                               Circle(center=(0, -arc_d), radius=arc_r)), 2 mm)
        if initials != "" {
            t = Text(initials, position=(-20 mm, 0), size=4, valign="middle")
        }
    }
    Fillet(1.5 mm)
}

assembly shuttle {
    top = plate(initials="E.B.")
    bottom = plate()
    solid post {
        thickness 2 mm
        e = Ellipse(center=(0, 0), rx=8, ry=4)
        hole tie { c = Circle(center=(0, 0), diameter=1.5) }
    }

    # on the sheet
    Below(bottom, top, gap=4)
    AlignCenterX(bottom, top)
    RightOf(post, top, gap=4)
    AlignCenterY(post, top)

    # assembled: bottom plate, post, top plate
    Place(bottom, position=(0, 0, 0))
    Place(post, position=(0, 0, 1.5 mm))
    Place(top, position=(0, 0, 3.5 mm))

    # the request's numbers
    assert abs(arc_r - 60 mm) < 0.01 mm, "sides are 60 mm arcs"
    assert top.lens.bb.width <= 72 mm and top.lens.bb.width > 69 mm, "72 mm tip to tip before rounding"
    assert abs(top.lens.bb.height - 24 mm) < 0.01 mm, "24 mm wide"
    assert post.e.bb.width == 16 mm and post.e.bb.height == 8 mm, "post 16 x 8"
    assert top.tie.c.diameter == 1.5 mm and post.tie.c.diameter == 1.5 mm, "1.5 mm tie hole"
    assert abs(top.tie.c.center.x - top.lens.bb.center_x) < 0.01 mm, "tie hole in the middle"
    assert abs(post.tie.c.center.x - post.e.center.x) < 0.01 mm, "post's hole in its middle"
    assert abs(top.trim.t.position.x - top.tie.c.center.x + 20 mm) < 0.01 mm, "initials at x = -20"
    assert top.trim.t.size == 4 mm, "initials 4 mm"
    assert 2 * sqrt(arc_r ** 2 - 8 mm ** 2) - 2 * arc_d > post.e.bb.height + 4 mm, "the post sits well inside the plates"
}
